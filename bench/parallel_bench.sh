#!/usr/bin/env bash
# Host speed of the simulator for the parallel programs (a reported figure, not a test):
# host seconds of one iteration of scene3 at R=64, V=0 and at R=8, V=7, as the difference
# between runs of 3 and 1 iterations divided by 2 (so set-up time is not counted), and the
# whole one-iteration run. Usage: bench/parallel_bench.sh   (after building)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
host_seconds() {
  "$root/simulate" scene3.json --R "$1" --V "$2" --iterations "$3" --json /tmp/ncube-bench.json --quiet
  /usr/bin/python3 -c "import json; print(json.load(open('/tmp/ncube-bench.json'))['host_seconds'])"
}
for config in "64 0" "8 7"; do
  set -- $config
  one=$(host_seconds "$1" "$2" 1)
  three=$(host_seconds "$1" "$2" 3)
  /usr/bin/python3 -c "print(f'scene3 R=$1 V=$2: {($three - $one) / 2:.3f} host s per iteration; one-iteration run {$one:.3f} s in all')"
done
