#!/usr/bin/env bash
# experiments/sweep --slurm asks the cluster first (issue 39 item 3, ncube.runner.slurm_answers):
# with a controller that does not answer, one line and exit 2 within a few seconds, nothing
# written or submitted. A failure of every cell says no cell finished (not "the other cells
# finished and are kept"). `--check | head` ends quietly on the closed pipe (item 9). About 2 s.
root="$2"
work=$(mktemp -d /tmp/sweep_slurm_check_test.XXXXXX)
trap 'rm -rf "$work"' EXIT
failed=0
fail() { echo "FAIL: $*"; failed=1; }
printf 'options: {iterations: 2}\ncells:\n  - {scene: scene0, R: 1, V: 0}\n' > "$work/one.yaml"

# A controller on a port nothing listens on: sinfo fails at once (MessageTimeout=1; left at its
# default, sinfo retries for 9 s and the sweep's own 5 s limit answers, a branch checked below
# with a shorter limit).
port=$(/usr/bin/python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
cat > "$work/slurm.conf" <<CONF
ClusterName=nobody
SlurmctldHost=localhost(127.0.0.1)
SlurmctldPort=$port
AuthType=auth/munge
AuthInfo=socket=$work/no-munge-socket
NodeName=localhost CPUs=1
PartitionName=p Nodes=localhost Default=YES
MessageTimeout=1
CONF
start=$(date +%s)
SLURM_CONF="$work/slurm.conf" "$root/experiments/sweep" "$work/one.yaml" --results "$work/results" \
  --slurm > "$work/out" 2> "$work/err"
code=$?
took=$(( $(date +%s) - start ))
[ "$code" = 2 ] || fail "--slurm without a cluster: exit $code, not 2: $(cat "$work/err")"
[ "$(wc -l < "$work/err")" = 1 ] || fail "--slurm without a cluster: not one line: $(cat "$work/err")"
grep -q "the Slurm cluster does not answer" "$work/err" || fail "the line: $(cat "$work/err")"
if grep -q "kept" "$work/err" "$work/out"; then fail "it speaks of kept cells: $(cat "$work/err")"; fi
[ -s "$work/out" ] && fail "it printed: $(cat "$work/out")"
[ "$took" -le 12 ] || fail "--slurm without a cluster took $took s"
[ -e "$work/results" ] && fail "it made the results folder"

# A cluster that answers nothing within the limit: sinfo stopped there, its reason one line.
mkdir "$work/bin"
printf '#!/bin/sh\nexec sleep 30\n' > "$work/bin/sinfo"
chmod +x "$work/bin/sinfo"
(cd "$root/analysis" && PATH="$work/bin:$PATH" /usr/bin/python3 - <<'PY') || fail "sinfo's time limit"
import time
from ncube import runner
runner.SLURM_ANSWER_SECONDS = 0.5
start = time.monotonic()
why = runner.slurm_answers()
assert why == "sinfo did not answer in 0.5 s" and time.monotonic() - start < 5, why
PY

# Every cell failed: no sentence about cells kept.
(cd "$root/analysis" && /usr/bin/python3 - "$work" <<'PY') || fail "outcome.failed's sentence"
import sys, types
from ncube import outcome
said = []
outcome.say = said.append
messages = types.SimpleNamespace(locked=False, full=False)
outcome.free_bytes = lambda _folder: 1 << 40
code = outcome.failed(1, messages, sys.argv[1], ["cells/a.json", "cells/b.json"], total=2)
assert code == outcome.CELLS_FAILED and "no cell finished" in said[-1] and "kept" not in said[-1], said
outcome.failed(1, messages, sys.argv[1], ["cells/a.json"], total=2)
assert "the other cells finished and are kept" in said[-1], said
PY

# A closed pipe: quiet, 128 + SIGPIPE (as any command in a pipe whose reader is gone).
"$root/experiments/sweep" "$root"/experiments/table*.json --check 2> "$work/err" | true
code=${PIPESTATUS[0]}
[ "$code" = 141 ] || fail "--check | true: exit $code, not 141"
[ -s "$work/err" ] && fail "--check | true: $(head -n 3 "$work/err")"
[ "$failed" = 0 ] && echo "sweep_slurm_check_test: passed (--slurm refused in $took s)"
exit "$failed"
