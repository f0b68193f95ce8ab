#!/usr/bin/env bash
# The machine-parameter tables of docs/model.md, docs/platforms.md and docs/result-format.md
# are what docs/platform_tables.py writes from the one list, src/machine/machine_parameters.h
# (and the nCube2's values and sources from platforms/ncube2.json).
# Usage: bash tests/platform_tables_test.sh <path-to-simulate-binary> <repo-root>
# (the simulate binary is not needed here; the argument keeps the script-test convention).
set -euo pipefail

root="${2:-$(cd "$(dirname "$0")/.." && pwd)}"
python=/usr/bin/python3
[[ -x "$python" ]] || python=python3
fail() { echo "FAIL: $*" >&2; exit 1; }

"$python" "$root/docs/platform_tables.py" --check ||
  fail "the machine-parameter tables have drifted from src/machine/machine_parameters.h"

# A copy of the inputs the script reads, so that the check can be shown to notice changes.
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
copy() {
  rm -rf "$tmp/r" && mkdir -p "$tmp/r/docs" "$tmp/r/platforms" "$tmp/r/src/machine"
  cp "$root/docs/platform_tables.py" "$root/docs/model_tables.py" "$root/docs/model.md" \
     "$root/docs/platforms.md" "$root/docs/result-format.md" "$tmp/r/docs/"
  cp "$root/platforms/ncube2.json" "$tmp/r/platforms/"
  cp "$root/src/machine/machine_parameters.h" "$tmp/r/src/machine/"
}
list="$tmp/r/src/machine/machine_parameters.h"

# 1. A doc string edited in the list: --check fails, a rewrite puts it in.
copy
sed -i 's/"memory of one node;/"EDITED memory of one node;/' "$list"
grep -q EDITED "$list" || fail "the test's edit of the list did not apply"
"$python" "$tmp/r/docs/platform_tables.py" --check 2>/dev/null &&
  fail "--check accepted a list whose doc string differs from the tables"
"$python" "$tmp/r/docs/platform_tables.py" >/dev/null
for doc in model.md platforms.md result-format.md; do
  grep -q "EDITED memory of one node\|| \`node_memory\` |" "$tmp/r/docs/$doc" ||
    fail "docs/$doc lost node_memory"
done
grep -q "EDITED memory of one node" "$tmp/r/docs/model.md" ||
  fail "docs/platform_tables.py did not write the edited description"
"$python" "$tmp/r/docs/platform_tables.py" --check >/dev/null

# 2. A new parameter (one entry in the list, and its nCube2 value): every table gains its row.
copy
sed -i 's/"CPU time the receiving node spends per message when its program takes it")/&                \\\
  X(dummy_knob, double, "s", 0, 2, false, kProperty, false, "DUMMY knob of the test")/' "$list"
grep -q "X(dummy_knob" "$list" || fail "the test's new parameter did not apply"
"$python" - "$tmp/r/platforms/ncube2.json" <<'PY'
import json, sys
path = sys.argv[1]
doc = json.load(open(path))
doc["parameters"]["dummy_knob"] = {"value": 0.5, "unit": "s", "doc": "d", "source": "DUMMY source"}
json.dump(doc, open(path, "w"))
PY
"$python" "$tmp/r/docs/platform_tables.py" --check 2>/dev/null &&
  fail "--check accepted a list with a parameter that no table has"
"$python" "$tmp/r/docs/platform_tables.py" >/dev/null
grep -q '| `dummy_knob` | s | 0.5 | 0 … 2 | DUMMY knob of the test | DUMMY source |' "$tmp/r/docs/model.md" ||
  fail "docs/model.md has no row for the new parameter"
grep -q '| `dummy_knob` | s | 0 … 2 | `"dummy_knob": {"value": …}` | `<prop id="dummy_knob"' "$tmp/r/docs/platforms.md" ||
  fail "docs/platforms.md has no row for the new parameter"
grep -q '| `dummy_knob` | s | yes | yes | DUMMY knob of the test |' "$tmp/r/docs/result-format.md" ||
  fail "docs/result-format.md has no row for the new parameter"

# 3. A machine file without the new parameter's value: the script names it (exit 2).
copy
sed -i 's/"CPU time the receiving node spends per message when its program takes it")/&                \\\
  X(dummy_knob, double, "s", 0, 2, false, kProperty, false, "DUMMY knob of the test")/' "$list"
status=0
"$python" "$tmp/r/docs/platform_tables.py" --check 2>"$tmp/err" || status=$?
[[ $status == 2 ]] && grep -q "has no parameter dummy_knob" "$tmp/err" ||
  fail "a parameter without an nCube2 value was not named (exit $status: $(cat "$tmp/err"))"

# 4. A network-model setting changed in the list: the table in docs/model.md follows.
copy
sed -i 's/X("network\/solver", "fairbottleneck",/X("network\/solver", "maxmin",/' "$list"
grep -q "\"maxmin\"" "$list" || fail "the test's network edit did not apply"
"$python" "$tmp/r/docs/platform_tables.py" --check 2>/dev/null &&
  fail "--check accepted a network model that differs from docs/model.md's table"

echo "PASS: the machine-parameter tables match src/machine/machine_parameters.h"
