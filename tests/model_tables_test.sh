#!/usr/bin/env bash
# The cost-model tables of docs/model.md are what docs/model_tables.py writes from
# platforms/cost_model.json (one description per parameter: the JSON's doc and source).
# Usage: bash tests/model_tables_test.sh <path-to-simulate-binary> <repo-root>
# (the simulate binary is not needed here; the argument keeps the script-test convention).
set -euo pipefail

root="${2:-$(cd "$(dirname "$0")/.." && pwd)}"
python=/usr/bin/python3
[[ -x "$python" ]] || python=python3

if ! "$python" "$root/docs/model_tables.py" --check; then
  echo "FAIL: docs/model.md's cost-model tables have drifted from platforms/cost_model.json" >&2
  exit 1
fi

# The check itself must notice a change: a copy of the repository's inputs with one doc
# string edited has to fail it.
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$tmp/docs" "$tmp/platforms"
cp "$root/docs/model_tables.py" "$root/docs/model.md" "$tmp/docs/"
cp -r "$root/src" "$tmp/src"
sed 's/"doc": "compare one patch/"doc": "EDITED compare one patch/' \
  "$root/platforms/cost_model.json" > "$tmp/platforms/cost_model.json"
if cmp -s "$tmp/platforms/cost_model.json" "$root/platforms/cost_model.json"; then
  echo "FAIL: the test's edit of cost_model.json did not apply" >&2
  exit 1
fi
if "$python" "$tmp/docs/model_tables.py" --check 2>/dev/null; then
  echo "FAIL: --check accepted a cost model whose doc string differs from docs/model.md" >&2
  exit 1
fi
# Rewriting the tables puts the edited description in.
"$python" "$tmp/docs/model_tables.py" >/dev/null
grep -q "EDITED compare one patch" "$tmp/docs/model.md" || {
  echo "FAIL: docs/model_tables.py did not write the edited description" >&2; exit 1; }
"$python" "$tmp/docs/model_tables.py" --check >/dev/null
echo "PASS: docs/model.md's cost-model tables match platforms/cost_model.json"
