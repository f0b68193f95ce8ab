#!/usr/bin/env bash
# docs/scenes.md's table of the partition by elements (largest / mean elements per radiosity
# processor, scenes 1-3, R = 4 .. 64) is what the scene generator computes from the scenes.
# Usage: bash tests/scenes_partition_table_test.sh <path-to-simulate-binary> <repo-root>
# (the simulate binary is not needed here; the argument keeps the script-test convention).
set -euo pipefail

root="${2:-$(cd "$(dirname "$0")/.." && pwd)}"
python="${PYTHON:-python3}"

table="$("$python" "$root/scenes/generate.py" --partition-table)"
rows=$(printf '%s\n' "$table" | grep -c '^| scene[123] ')
if [[ $rows -ne 3 ]]; then
  echo "FAIL: scenes/generate.py --partition-table printed $rows scene rows, expected 3" >&2
  printf '%s\n' "$table" >&2
  exit 1
fi
if ! TABLE="$table" "$python" -c '
import os, sys
doc = open(sys.argv[1], encoding="utf-8").read()
sys.exit(0 if os.environ["TABLE"].strip() + "\n" in doc else 1)' "$root/docs/scenes.md"; then
  echo "FAIL: docs/scenes.md does not hold the partition table the generator computes:" >&2
  printf '%s\n' "$table" >&2
  echo "(update docs/scenes.md with: python3 scenes/generate.py --partition-table)" >&2
  exit 1
fi
echo "PASS: docs/scenes.md's partition table matches the scenes"
