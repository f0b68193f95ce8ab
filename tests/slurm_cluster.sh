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
#                             # (SLURM_CLUSTER_CPUS=N: a node of N CPUs, not the machine's cores)
#   slurm_cluster_stop DIR    # stops the daemons it started (by their pid files)
# A pid file's process is signalled only when it is this cluster's own daemon (its program and its
# own configuration path in its arguments, this user's); the folder may not hold spaces
# (slurm.conf cannot), and is refused with that reason.
# Needs root (slurmd runs the jobs as their submitter) and Debian's slurmctld, slurmd,
# slurm-client and munge (.ci/install-deps).

free_port() {
  /usr/bin/python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])'
}

slurm_cluster_start() {
  local dir
  dir=$(realpath -m -- "$1")
  SLURM_CLUSTER_WHY=""
  # slurm.conf values end at white space and take no quotes (slurm.conf(5)); the daemons change
  # folder, so the path is made absolute.
  if [[ "$dir" =~ [^A-Za-z0-9._/+-] ]]; then
    SLURM_CLUSTER_WHY="the folder \"$dir\" holds a space or another character slurm.conf cannot hold (use letters, digits and . _ / + -)"
    return 1
  fi
  local tool
  for tool in munged mungekey slurmctld slurmd sbatch squeue scontrol; do
    if ! command -v "$tool" >/dev/null 2>&1 && [ ! -x "/usr/sbin/$tool" ]; then
      SLURM_CLUSTER_WHY="$tool is not installed (run .ci/install-deps)"
      return 1
    fi
  done
  local cpus overrides=""
  # The node offers the machine's cores, or SLURM_CLUSTER_CPUS when set (the tests: more job
  # slots than cores, so that a small sweep's jobs start at once instead of in waves of nproc,
  # each wave a round of Slurm's scheduling and of the sweep's status checks). slurmd takes a
  # node with more CPUs than it finds only under config_overrides ("generally only useful for
  # testing purposes", slurm.conf(5)).
  cpus=$(nproc)
  if [ -n "${SLURM_CLUSTER_CPUS:-}" ]; then
    if ! [[ "$SLURM_CLUSTER_CPUS" =~ ^[1-9][0-9]{0,3}$ ]]; then
      SLURM_CLUSTER_WHY="SLURM_CLUSTER_CPUS=\"$SLURM_CLUSTER_CPUS\" is not a whole number from 1 to 9999"
      return 1
    fi
    [ "$SLURM_CLUSTER_CPUS" -gt "$cpus" ] && overrides="SlurmdParameters=config_overrides"
    cpus=$SLURM_CLUSTER_CPUS
  fi
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
# The main scheduling loop every second, not every 60 s: a job waiting for a free CPU starts
# about 0.2 s after another ends, not 2 s (measured on this one-node cluster, Slurm 22.05); a
# few jobs on one node make the pass cheap.
SchedulerParameters=sched_interval=1
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
$overrides
NodeName=$node NodeAddr=127.0.0.1 CPUs=$cpus RealMemory=$memory State=UNKNOWN
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

# Whether the pid file names one of this cluster's own daemons; then SLURM_CLUSTER_PID holds it.
# It must be a decimal number above 1 (0 would signal the caller's process group, -N a whole
# group, 1 init), a live process of this user, whose program is PROGRAM and whose arguments hold
# ARGUMENT, this cluster's own configuration path. Otherwise the reason is in SLURM_CLUSTER_WHY.
slurm_cluster_own_pid() {
  local pidfile="$1" program="$2" argument="$3" pid owner arg
  SLURM_CLUSTER_PID=""
  pid=$(head -c 32 -- "$pidfile" 2>/dev/null | head -n 1)
  pid="${pid#"${pid%%[![:space:]]*}"}"
  pid="${pid%"${pid##*[![:space:]]}"}"
  if ! [[ "$pid" =~ ^[0-9]{1,9}$ ]] || [ "$((10#$pid))" -le 1 ]; then
    SLURM_CLUSTER_WHY="$pidfile: \"$pid\" is not a daemon's pid (a decimal number above 1)"
    return 1
  fi
  pid=$((10#$pid))
  if ! owner=$(stat -c %u "/proc/$pid" 2>/dev/null); then
    SLURM_CLUSTER_WHY="$pidfile: no process $pid runs"
    return 1
  fi
  if [ "$owner" != "$(id -u)" ]; then
    SLURM_CLUSTER_WHY="$pidfile: process $pid belongs to uid $owner, not to this user"
    return 1
  fi
  local -a args=()
  mapfile -d '' -t args < "/proc/$pid/cmdline" 2>/dev/null
  if [ "${#args[@]}" -eq 0 ] || [ "${args[0]}" != "/usr/sbin/$program" ]; then
    SLURM_CLUSTER_WHY="$pidfile: process $pid is not /usr/sbin/$program"
    return 1
  fi
  for arg in "${args[@]:1}"; do
    if [ "$arg" = "$argument" ]; then
      SLURM_CLUSTER_PID=$pid
      return 0
    fi
  done
  SLURM_CLUSTER_WHY="$pidfile: process $pid is a $program not started with $argument"
  return 1
}

slurm_cluster_stop() {
  local dir pid i
  dir=$(realpath -m -- "$1")
  # Only this cluster's own jobs: scancel reaches the cluster SLURM_CONF names.
  if [ "${SLURM_CONF:-}" = "$dir/slurm.conf" ] && [ -f "$dir/slurm.conf" ]; then
    scancel --full --quiet --user=root 2>/dev/null
  fi
  local -a pidfiles=("$dir/slurmd.pid" "$dir/slurmctld.pid" "$dir/munge/munged.pid")
  local -a programs=(slurmd slurmctld munged)
  local -a arguments=("$dir/slurm.conf" "$dir/slurm.conf" "--socket=$dir/munge/socket")
  local -a signalled=()
  for i in 0 1 2; do
    [ -f "${pidfiles[$i]}" ] || continue
    if ! slurm_cluster_own_pid "${pidfiles[$i]}" "${programs[$i]}" "${arguments[$i]}"; then
      echo "slurm_cluster.sh: not signalled: $SLURM_CLUSTER_WHY" >&2
      continue
    fi
    kill "$SLURM_CLUSTER_PID" 2>/dev/null && signalled+=("$SLURM_CLUSTER_PID:${programs[$i]}")
  done
  # All three asked to stop at once, then waited for together (each takes a second or two to
  # end): 5 s at most, then killed.
  local entry program running
  for _ in $(seq 1 50); do
    running=0
    for entry in "${signalled[@]}"; do
      kill -0 "${entry%%:*}" 2>/dev/null && running=1
    done
    [ "$running" = 0 ] && break
    sleep 0.1
  done
  for entry in "${signalled[@]}"; do   # still the daemon signalled (its program), not a reuse
    pid=${entry%%:*} program=${entry#*:}
    [ "$(head -z -n 1 "/proc/$pid/cmdline" 2>/dev/null | tr -d '\0')" = "/usr/sbin/$program" ] &&
      kill -9 "$pid" 2>/dev/null
  done
  return 0
}

if [ "${BASH_SOURCE[0]}" = "$0" ]; then   # run, not sourced
  dir=$(realpath -m -- "${2:-/tmp/ncube-slurm}")
  case "${1:-}" in
    start)
      if [ -f "$dir/slurmctld.pid" ] &&
          slurm_cluster_own_pid "$dir/slurmctld.pid" slurmctld "$dir/slurm.conf"; then
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
