#!/usr/bin/env bash
# tests/slurm_cluster.sh signals only the daemons it started: a pid file holding 0, 1, -5, a
# word, the pid of an unrelated process, a look-alike daemon of another cluster or of another
# user is refused with a line saying why, and none of them is signalled; this cluster's own
# (look-alike) daemon, in a folder with spaces, is stopped; a cluster in a folder with spaces
# is refused at start with the reason. No Slurm needed: the daemons are stand-ins whose
# command line is the daemon's (bash's exec -a).
set -u
source "$2/tests/slurm_cluster.sh"
work=$(mktemp -d)
started=()
trap 'for p in "${started[@]}"; do kill -9 "$p" 2>/dev/null; done; rm -rf "$work"' EXIT
failures=0
check() {  # check CONDITION-STATUS WHAT
  if [ "$1" = 0 ]; then echo "ok   $2"; else echo "FAIL $2"; failures=$((failures + 1)); fi
}
# A process whose command line reads PROGRAM -c SLEEP ARGS... (one process, which sleeps); its pid
# in $stand_in. Started from a subshell that ends, so that, like a daemon, it is not this shell's
# child (a stopped child would stay a zombie until this shell reaps it).
SLEEP='import time; time.sleep(300)'
stand_in() {
  local program="$1"; shift
  stand_in=$( (exec -a "$program" /usr/bin/python3 -c "$SLEEP" "$@") >/dev/null 2>&1 & echo $!)
  started+=("$stand_in")
  for _ in $(seq 1 50); do
    tr '\0' ' ' < "/proc/$stand_in/cmdline" 2>/dev/null | grep -q "^$program " && return
    sleep 0.02
  done
}
# Runs slurm_cluster_stop DIR in a process group of its own (a kill 0 there would end it alone),
# with SLURM_CONF pointing elsewhere (scancel is not run); its status and stderr.
stop_in() {
  setsid bash -c 'source "$1/tests/slurm_cluster.sh"; SLURM_CONF=/nonexistent slurm_cluster_stop "$2"' \
    _ "$2" "$1" 2> "$work/stop.err"
  echo $?
}

dir="$work/cluster"
mkdir -p "$dir/munge"
for content in 0 1 -5 00 "1 2" word 99999999999; do
  printf '%s\n' "$content" > "$dir/slurmd.pid"
  status=$(stop_in "$dir" "$2")
  grep -q "not signalled: .*not a daemon's pid" "$work/stop.err"
  check $? "a pid file holding \"$content\" is refused, saying why (status $status: $(head -c 200 "$work/stop.err"))"
  [ "$status" = 0 ]; check $? "  and the stop itself was not signalled (status $status)"
done

sleep 300 >/dev/null 2>&1 & unrelated=$!; disown; started+=("$unrelated")
echo "$unrelated" > "$dir/slurmd.pid"
status=$(stop_in "$dir" "$2")
kill -0 "$unrelated" 2>/dev/null
check $? "an unrelated sleep named by slurmd.pid is not signalled ($(head -c 200 "$work/stop.err"))"
grep -q "is not /usr/sbin/slurmd" "$work/stop.err"; check $? "  the reason names the program"

stand_in /usr/sbin/slurmd -f /elsewhere/slurm.conf -N node
other=$stand_in
echo "$other" > "$dir/slurmd.pid"
status=$(stop_in "$dir" "$2")
kill -0 "$other" 2>/dev/null
check $? "a slurmd of another cluster (its own slurm.conf) is not signalled ($(head -c 200 "$work/stop.err"))"

if [ "$(id -u)" = 0 ] && command -v setpriv >/dev/null; then
  ( exec setpriv --reuid=65534 --regid=65534 --clear-groups \
      bash -c 'exec -a /usr/sbin/slurmd /usr/bin/python3 -c "$1" -f "$2"' _ "$SLEEP" "$dir/slurm.conf" ) \
    >/dev/null 2>&1 &
  foreign=$!; disown; started+=("$foreign")
  for _ in $(seq 1 50); do
    tr '\0' ' ' < "/proc/$foreign/cmdline" 2>/dev/null | grep -q "^/usr/sbin/slurmd " && break
    sleep 0.02
  done
  echo "$foreign" > "$dir/slurmd.pid"
  status=$(stop_in "$dir" "$2")
  kill -0 "$foreign" 2>/dev/null
  check $? "another user's slurmd of this very cluster is not signalled ($(head -c 200 "$work/stop.err"))"
  grep -q "belongs to uid 65534" "$work/stop.err"; check $? "  the reason names its owner"
else
  echo "skip another user's process (needs root and setpriv)"
fi

# This cluster's own daemons, in a folder with spaces: stopped.
spaced="$work/a folder with spaces"
mkdir -p "$spaced/munge"
stand_in /usr/sbin/slurmd -f "$spaced/slurm.conf" -N node
own_slurmd=$stand_in
stand_in /usr/sbin/munged --force "--socket=$spaced/munge/socket"
own_munged=$stand_in
echo "$own_slurmd" > "$spaced/slurmd.pid"
echo "$own_munged" > "$spaced/munge/munged.pid"
status=$(stop_in "$spaced" "$2")
sleep 0.2
! kill -0 "$own_slurmd" 2>/dev/null; check $? "its own slurmd (in a folder with spaces) is stopped"
! kill -0 "$own_munged" 2>/dev/null; check $? "its own munged is stopped"
[ ! -s "$work/stop.err" ]; check $? "  without a complaint ($(head -c 200 "$work/stop.err"))"

# Starting in a folder with spaces: refused, with the reason, before anything is started.
slurm_cluster_start "$spaced/new"
[ $? = 1 ] && [[ "$SLURM_CLUSTER_WHY" == *"space"* ]]
check $? "a cluster in a folder with spaces is refused: $SLURM_CLUSTER_WHY"
[ ! -e "$spaced/new" ]; check $? "  and nothing is created there"

# A node's CPU count that is not a whole number from 1 to 9999: refused before anything starts.
for bad in 0 -1 nan 1e400 0x10 " 2" 10000; do
  SLURM_CLUSTER_CPUS=$bad slurm_cluster_start "$work/cpus"
  [ $? = 1 ] && [[ "$SLURM_CLUSTER_WHY" == *"SLURM_CLUSTER_CPUS"* ]] && [ ! -e "$work/cpus" ]
  check $? "SLURM_CLUSTER_CPUS=$bad is refused, nothing created: $SLURM_CLUSTER_WHY"
done

exit $((failures > 0))
