#!/usr/bin/env bash
# The machine library (platforms/machines/, docs/machines/):
#  - the committed platform files are exactly what platforms/machines/generate.py writes, and
#    docs/machines/README.md's table is what docs/machines/index_table.py writes from them;
#  - every file loads and runs (scene1, R=8, V=7, one iteration: its first shots' messages
#    cross the platform; 3 cost a third more), has its nodes node-0 ..
#    node-(n-1) (64 for a machine's own file, n for its family's <name>-n<n>.xml), and the node
#    speed, memory and overheads the simulator read back (provenance.platform.values) are the
#    figures the machine's page states; the page's link bandwidth and hop latency are the file's;
#  - every page has the ping-pong table's markers, and published_network.json names existing
#    files with a tolerance for every published value.
# Usage: bash tests/machines_platforms_test.sh <path-to-simulate-binary> <repo-root>
set -euo pipefail

simulate="$(realpath "${1:?usage: machines_platforms_test.sh <simulate> <repo-root>}")"
root="${2:-$(cd "$(dirname "$0")/.." && pwd)}"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
status=0

# 1. Reproducible from the generator, nothing extra committed.
/usr/bin/python3 "$root/platforms/machines/generate.py" --out "$tmp/gen"
for f in "$tmp"/gen/*.xml; do
  name="$(basename "$f")"
  if ! cmp -s "$f" "$root/platforms/machines/$name"; then
    echo "FAIL: platforms/machines/$name differs from what platforms/machines/generate.py writes (run it)" >&2
    status=1
  fi
done
for f in "$root"/platforms/machines/*.xml; do
  [[ -f "$tmp/gen/$(basename "$f")" ]] || { echo "FAIL: platforms/machines/$(basename "$f") is not written by generate.py" >&2; status=1; }
done
if ! /usr/bin/python3 "$root/docs/machines/index_table.py" --check; then status=1; fi

# 2. Each file runs; its figures are the page's.
runs=0
ran=()   # platform file, result file: checked by one Python below (one start, not one a file)
# The runs in one batch, each forked from build/simulate_server (tests/forked_batch.py: about
# 85 ms of CPU less a run than a new ./simulate).
files=("$root"/platforms/machines/*.xml)
for f in "${files[@]}"; do
  name="$(basename "$f" .xml)"
  printf '{"args": ["scene1.json", "--R", "8", "--V", "7", "--iterations", "1", "--platform", "%s", "--json", "%s"], "stdout": "%s", "stderr": "%s"}\n' \
    "$f" "$tmp/$name.json" "$tmp/$name.out" "$tmp/$name.log"
done > "$tmp/cases.jsonl"
mapfile -t codes < <(cd "$root" && /usr/bin/python3 "$root/tests/forked_batch.py" "$simulate" "$tmp/cases.jsonl")
for k in "${!files[@]}"; do
  f=${files[k]}
  name="$(basename "$f" .xml)"
  out="$tmp/$name.json"
  if [ "${codes[k]:-none}" != 0 ]; then
    echo "FAIL: $name: ./simulate did not run (exit ${codes[k]:-none}):" >&2; cat "$tmp/$name.out" "$tmp/$name.log" >&2; status=1; continue
  fi
  runs=$((runs + 1))
  ran+=("$f" "$out")
done
if ((runs)) && ! /usr/bin/python3 - "$root" "${ran[@]}" <<'EOF'
import json, os, re, sys
root, pairs = sys.argv[1], sys.argv[2:]
sys.path.insert(0, os.path.join(root, "docs", "machines"))
import index_table  # the table's own reader of the XML, for the link figures

def check(platform, result):
    base = os.path.basename(platform)[:-4]
    family = re.search(r"-n(\d+)$", base)
    machine = base[:family.start()] if family else base
    nodes = int(family.group(1)) if family else 64
    failures = []
    r = json.load(open(result))
    p = r["provenance"]["platform"]
    values = p["values"]
    if r["status"] != "ok" or p["format"] != "simgrid-xml":
        failures.append("status %s, format %s" % (r["status"], p["format"]))
    if values["nodes"] != nodes:
        failures.append("%s nodes, expected %d" % (values["nodes"], nodes))

    page_path = os.path.join(root, "docs", "machines", machine + ".md")
    page = open(page_path, encoding="utf-8").read()
    stated = {}
    for line in page.splitlines():
        cells = [c.strip() for c in line.split("|")[1:-1]]
        if len(cells) < 2 or not cells[0].startswith("`"):
            continue
        number = re.match(r"[0-9][0-9.eE+-]*", cells[1].replace(",", ""))
        for name in re.findall(r"`(\w+)`", cells[0]):
            if number:
                stated[name] = float(number.group(0))
    xml = index_table.describe(platform)
    read_back = {"nodes": values["nodes"] if not family else 64, "node_speed": values["node_speed"],
                 "node_memory": values["node_memory"], "send_overhead": values["send_overhead"],
                 "receive_overhead": values["receive_overhead"], "link_bandwidth": xml["bandwidth"],
                 "hop_latency": xml["latency"]}
    for rate in ("test_speed", "arithmetic_speed", "memory_speed"):  # given by a machine that has them
        if rate in values:
            read_back[rate] = values[rate]
    for name, value in read_back.items():
        if name not in stated:
            failures.append("%s states no `%s`" % (os.path.relpath(page_path, root), name))
        elif abs(stated[name] - value) > 1e-9 * abs(value):
            failures.append("`%s`: the page states %.10g, the platform has %.10g" % (name, stated[name], value))
    if "<!-- network-table:begin -->" not in page or "<!-- network-table:end -->" not in page:
        failures.append("%s lacks the network-table markers" % os.path.relpath(page_path, root))
    for failure in failures:
        print("FAIL: %s: %s" % (base, failure), file=sys.stderr)
    return failures

failed = False
for k in range(0, len(pairs), 2):
    failed = bool(check(pairs[k], pairs[k + 1])) or failed
sys.exit(1 if failed else 0)
EOF
then status=1; fi
[[ $runs -ge 5 ]] || { echo "FAIL: only $runs platform files ran" >&2; status=1; }

# 3. The published figures name existing files and carry a tolerance.
if ! /usr/bin/python3 - "$root" <<'EOF'
import json, os, sys
root = sys.argv[1]
data = json.load(open(os.path.join(root, "platforms", "machines", "published_network.json")))
bad = []
for name, m in data["machines"].items():
    for key in ("platform", "page"):
        if not os.path.isfile(os.path.join(root, m[key])):
            bad.append("%s: %s %s does not exist" % (name, key, m[key]))
    for figure in ("one_way_latency", "asymptotic_bandwidth"):
        f = m[figure]
        if f["value"] is None:
            if not f.get("note"):
                bad.append("%s: %s is null without a note on what was tried" % (name, figure))
        elif not (f["value"] > 0 and f["tolerance"] and 0 < f["tolerance"] < 1 and f["source"]):
            bad.append("%s: %s needs a positive value, a tolerance in (0, 1) and a source" % (name, figure))
for b in bad:
    print("FAIL: published_network.json: " + b, file=sys.stderr)
sys.exit(1 if bad else 0)
EOF
then status=1; fi

[[ $status -eq 0 ]] && echo "PASS: $runs machine platform files reproduced, run, and hold their pages' figures"
exit $status
