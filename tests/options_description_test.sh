#!/usr/bin/env bash
# One source per option: what `simulate --describe-options` prints (the parser's own
# registrations, src/tools/option_table.h) is the committed analysis/ncube/simulate_options.json,
# which the sweep tool's validation (analysis/ncube/options.py) reads and docs/cli.md's table is
# written from. Fails when any of the three drifts from the binary.
# Usage: bash tests/options_description_test.sh <path-to-simulate-binary> <repo-root>
set -euo pipefail

simulate="$1"
root="${2:-$(cd "$(dirname "$0")/.." && pwd)}"
python=/usr/bin/python3
[[ -x "$python" ]] || python=python3
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT

"$simulate" --describe-options > "$tmp/described.json"
if ! cmp -s "$tmp/described.json" "$root/analysis/ncube/simulate_options.json"; then
  diff "$root/analysis/ncube/simulate_options.json" "$tmp/described.json" | head -20 >&2 || true
  echo "FAIL: analysis/ncube/simulate_options.json is not what simulate --describe-options" \
       "prints; run: build/simulate --describe-options > analysis/ncube/simulate_options.json" >&2
  exit 1
fi

if ! "$python" "$root/docs/options_table.py" --check; then
  echo "FAIL: docs/cli.md's option table or docs/result-format.md's counter table has drifted from analysis/ncube/simulate_options.json" >&2
  exit 1
fi

# The sweep tool accepts and refuses at the same ends as the binary: each range end is
# accepted by ./simulate (tests/robustness tries them) and by options.py, one step past each
# end refused by both.
"$python" - "$root" <<'EOF'
import sys
sys.path.insert(0, sys.argv[1] + "/analysis")
from ncube import options as opts
import json
described = {d["flag"]: d for d in json.load(open(opts.DESCRIPTION))}
problems = []
for name, option in opts.OPTIONS.items():
    r = described[option.flag].get("range")
    if not r:
        continue
    for end, included, step in ((r["low"], r["low_included"], -1), (r["high"], r["high_included"], 1)):
        inside = end if included else end - step * (1 if option.kind is int else abs(end) * 1e-9 or 1e-300)
        past = end + step if option.kind is int else end + step * (abs(end) * 1e-6 or 1e-300)
        if option.kind is int and described[option.flag].get("perfect_square"):
            continue  # the square rule is tried on its own below
        if option.check(option.kind(inside)) is not None:
            problems.append(f"{name}: options.py refuses {inside}, inside the range")
        if option.check(option.kind(past)) is None:
            problems.append(f"{name}: options.py accepts {past}, outside the range")
samples = opts.OPTIONS["samples"].check
if samples(64) or samples(1) or not samples(32) or not samples(0) or not samples(81):
    problems.append("samples: options.py does not hold the perfect squares from 1 to 64")
if problems:
    print("FAIL: " + "; ".join(problems), file=sys.stderr)
    sys.exit(1)
EOF

# The check itself must notice a change: a copy whose description has one help text edited
# has to fail it, and rewriting the table puts the edit in.
mkdir -p "$tmp/repo/docs" "$tmp/repo/analysis/ncube"
cp "$root/docs/options_table.py" "$root/docs/model_tables.py" "$root/docs/cli.md" \
   "$root/docs/result-format.md" "$tmp/repo/docs/"
sed 's/"radiosity processors"/"EDITED radiosity processors"/; s/"hemicube: cells whose centre/"EDITED hemicube: cells whose centre/' \
  "$tmp/described.json" > "$tmp/repo/analysis/ncube/simulate_options.json"
if cmp -s "$tmp/repo/analysis/ncube/simulate_options.json" "$tmp/described.json"; then
  echo "FAIL: the test's edit of the description did not apply" >&2
  exit 1
fi
if "$python" "$tmp/repo/docs/options_table.py" --check 2>/dev/null; then
  echo "FAIL: --check accepted a description whose help text differs from docs/cli.md" >&2
  exit 1
fi
"$python" "$tmp/repo/docs/options_table.py" >/dev/null
grep -q "EDITED radiosity processors" "$tmp/repo/docs/cli.md" || {
  echo "FAIL: docs/options_table.py did not write the edited help text" >&2; exit 1; }
# docs/result-format.md's table of each method's counters comes from the registry likewise:
# the edited text of a hemicube counter is in it after the rewrite.
grep -q "| \`hemicube\` | \`hemicube_depth_tests\` | EDITED hemicube: cells whose centre" \
  "$tmp/repo/docs/result-format.md" || {
  echo "FAIL: docs/options_table.py did not write the counter table from the registry" >&2; exit 1; }
echo "PASS: simulate --describe-options, analysis/ncube/simulate_options.json, options.py and" \
     "docs/cli.md agree"
