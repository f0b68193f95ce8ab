#!/usr/bin/env bash
# A one-node Slurm cluster for the tests (tests/sweep_slurm_test.sh) and for trying
# `experiments/sweep --slurm` on this machine (docs/sweeps.md, "Trying --slurm on this
# machine"), started in a folder of its own: munged with its own key and socket, slurmctld and
# slurmd on the loopback with free ports, proctrack/linuxproc and task/none (no cgroups), no
# accounting database. Run it:
#   tests/slurm_cluster.sh start [DIR]   # default /tmp/ncube-slurm; prints the SLURM_CONF to export
#   tests/slurm_cluster.sh stop [DIR]    # cancels its jobs and stops its daemons
# or source this file, then
#   slurm_cluster_start DIR   # exports SLURM_CONF; returns 1 with the reason in SLURM_CLUSTER_WHY
#   slurm_cluster_stop DIR    # stops the daemons it started (by their pid files)
# Needs root (slurmd runs the jobs as their submitter) and Debian's slurmctld, slurmd,
# slurm-client and munge (.ci/install-deps).

free_port() {
  /usr/bin/python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])'
}

slurm_cluster_start() {
  local dir="$1"
  SLURM_CLUSTER_WHY=""
  local tool
  for tool in munged mungekey slurmctld slurmd sbatch squeue scontrol; do
    if ! command -v "$tool" >/dev/null 2>&1 && [ ! -x "/usr/sbin/$tool" ]; then
      SLURM_CLUSTER_WHY="$tool is not installed (run .ci/install-deps)"
      return 1
    fi
  done
  if [ "$(id -u)" != 0 ]; then
    SLURM_CLUSTER_WHY="slurmd must run as root to start jobs, and this is uid $(id -u)"
    return 1
  fi
  mkdir -p "$dir"/{munge,state,spool,log}
  chmod 700 "$dir/munge"
  /usr/sbin/mungekey --create --keyfile="$dir/munge/munge.key" >/dev/null 2>&1 || true
  if ! /usr/sbin/munged --force --socket="$dir/munge/socket" --key-file="$dir/munge/munge.key" \
      --pid-file="$dir/munge/munged.pid" --log-file="$dir/log/munged.log" \
      --seed-file="$dir/munge/seed" >/dev/null 2>&1; then
    SLURM_CLUSTER_WHY="munged did not start: $(tail -n1 "$dir/log/munged.log" 2>/dev/null)"
    return 1
  fi
  local node memory ctld_port slurmd_port
  node=$(hostname -s)
  # The node offers what the machine has; slurmd refuses to register with more.
  memory=$(( $(awk '/MemTotal/ {print $2}' /proc/meminfo) / 1024 - 256 ))
  ctld_port=$(free_port)
  slurmd_port=$(free_port)
  cat > "$dir/slurm.conf" <<EOF
ClusterName=ncubetest
SlurmctldHost=$node(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$dir/munge/socket
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool/%n
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/log/slurmctld.log
SlurmdLogFile=$dir/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
MpiDefault=none
SwitchType=switch/none
LaunchParameters=use_interactive_step
ReturnToService=2
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core_Memory
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
# Memory requests are enforced by sampling the job's processes (no cgroups): a job over its
# --mem is killed, and the sweep's status command reports it (ncube.slurm_status).
JobAcctGatherType=jobacct_gather/linux
JobAcctGatherFrequency=task=1
JobAcctGatherParams=OverMemoryKill
MinJobAge=600
InactiveLimit=0
KillWait=5
NodeName=$node NodeAddr=127.0.0.1 CPUs=$(nproc) RealMemory=$memory State=UNKNOWN
PartitionName=test Nodes=$node Default=YES MaxTime=INFINITE State=UP
EOF
  export SLURM_CONF="$dir/slurm.conf"
  if ! /usr/sbin/slurmctld -f "$SLURM_CONF" -i >/dev/null 2>&1; then
    SLURM_CLUSTER_WHY="slurmctld did not start: $(tail -n1 "$dir/log/slurmctld.log" 2>/dev/null)"
    return 1
  fi
  if ! /usr/sbin/slurmd -f "$SLURM_CONF" -N "$node" >/dev/null 2>&1; then
    SLURM_CLUSTER_WHY="slurmd did not start: $(tail -n1 "$dir/log/slurmd.log" 2>/dev/null)"
    return 1
  fi
  local waited
  for waited in $(seq 1 100); do
    if sinfo -h -N -o '%t' 2>/dev/null | grep -qE '^(idle|mix|alloc)'; then
      return 0
    fi
    sleep 0.2
  done
  SLURM_CLUSTER_WHY="the node did not become idle in 20 s: $(sinfo -h -N -o '%t %E' 2>&1 | head -n1); $(tail -n1 "$dir/log/slurmd.log" 2>/dev/null)"
  return 1
}

slurm_cluster_stop() {
  local dir="$1" pidfile pid
  [ -n "${SLURM_CONF:-}" ] && scancel --full --quiet --user=root 2>/dev/null
  for pidfile in "$dir/slurmd.pid" "$dir/slurmctld.pid" "$dir/munge/munged.pid"; do
    [ -f "$pidfile" ] || continue
    pid=$(cat "$pidfile")
    kill "$pid" 2>/dev/null || continue
    for _ in $(seq 1 50); do
      kill -0 "$pid" 2>/dev/null || break
      sleep 0.1
    done
    kill -9 "$pid" 2>/dev/null
  done
}

if [ "${BASH_SOURCE[0]}" = "$0" ]; then   # run, not sourced
  dir="${2:-/tmp/ncube-slurm}"
  case "${1:-}" in
    start)
      if [ -f "$dir/slurmctld.pid" ] && kill -0 "$(cat "$dir/slurmctld.pid")" 2>/dev/null; then
        echo "slurm_cluster.sh: a cluster runs in $dir already (stop it: $0 stop $dir)" >&2
        exit 2
      fi
      if ! slurm_cluster_start "$dir"; then
        echo "slurm_cluster.sh: the cluster did not start: $SLURM_CLUSTER_WHY" >&2
        slurm_cluster_stop "$dir"
        exit 1
      fi
      echo "a one-node Slurm cluster runs in $dir (partition test, $(nproc) CPUs); for experiments/sweep --slurm:"
      echo "export SLURM_CONF=$SLURM_CONF"
      echo "stop it with: $0 stop $dir" ;;
    stop)
      [ -f "$dir/slurm.conf" ] && export SLURM_CONF="$dir/slurm.conf"
      slurm_cluster_stop "$dir"
      echo "stopped the cluster of $dir" ;;
    *)
      echo "usage: $0 start|stop [DIR]   (default DIR /tmp/ncube-slurm)" >&2
      exit 2 ;;
  esac
fi
