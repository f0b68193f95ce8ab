#!/usr/bin/env bash
# docs/machines/prediction_records.py through docs/machines/prediction_table.py --regenerate
# (the page's tables from the records of the prediction's runs):
#  - each row's median, least and worst miss over the runs, over all machines and per machine,
#    and the bound (10 %) held against the worst run: on six records worked out by hand (two
#    machines), the Cornell box is outside the bound in one run of the first machine (-12 %)
#    and in the only run of the second (+15 %), so it does not hold, though its median (+0.5 %
#    over both, -1.0 % on the first) is well inside; scene2 holds in every run;
#  - the probe's rates' spread over the probes (largest - least over the median);
#  - the host's drift within a run (a second probe's test_speed over the first), in the opening
#    and the run's row;
#  - a record of an earlier probe (run under glibc's malloc, no probe_allocator) and one whose
#    host seconds were measured with each process's repeats in a row, named and left out of
#    the tables;
#  - a records file with a line that is not a record: a message naming the file and the line,
#    a non-zero exit, no table.
# No timing: the records are made up, the script only reads them (under a second).
# Usage: bash tests/prediction_records_test.sh <path-to-simulate-binary> <repo-root>
set -euo pipefail
root="${2:-$(cd "$(dirname "$0")/.." && pwd)}"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

# machine, test_speed, Cornell box's miss, scene2's miss (simulated = 1 + miss, host = 1)
/usr/bin/python3 - "$tmp/records.jsonl" <<'PY'
import json, sys
runs = [("aaaa", 4.0e9, -0.05, 0.03), ("aaaa", 4.2e9, 0.02, 0.05), ("aaaa", 4.1e9, -0.12, -0.02),
        ("aaaa", 4.4e9, 0.04, 0.08), ("aaaa", 4.3e9, -0.01, 0.01), ("bbbb", 5.0e9, 0.15, -0.04)]
with open(sys.argv[1], "w") as f:
    for i, (machine, test, cornell, scene2) in enumerate(runs):
        rows = [{"scene": s, "kind": "ray-traced", "options": "", "simulated": 1 + m, "host": 1.0,
                 "tests_per_ray": t, "crossing_share": 0.3, "host_minus_simulated_ns_a_test": 0.1}
                for s, m, t in (("cornell-box", cornell, 15), ("scene2", scene2, 830))]
        f.write(json.dumps({"date": "2026-01-01T00:0%dZ" % i, "cpu": "Test CPU", "machine": machine,
                            "cores": 2, "commit": "abc", "repeats": 2, "probed": True,
                            "probe_allocator": "tcmalloc", "measurement": "interleaved",
                            "load_before": [1.5, 1, 1], "load_after": [2.5, 1, 1], "wall_seconds": 100,
                            "rates": {"test_speed": test}, "rows": rows,
                            **({"rates_after": {"test_speed": 4.4e9}} if i == 0 else {})}) + "\n")
    # An earlier probe's record (no probe_allocator: glibc's malloc): counted, not tabulated;
    # in the tables it would make the Cornell box's worst +90 % and the load 9.
    rows = [{"scene": "cornell-box", "kind": "ray-traced", "options": "", "simulated": 1.9,
             "host": 1.0, "tests_per_ray": 15, "crossing_share": 0.3,
             "host_minus_simulated_ns_a_test": 0.1}]
    f.write(json.dumps({"date": "2025-12-31T00:00Z", "cpu": "Test CPU", "machine": "aaaa",
                        "cores": 2, "commit": "old", "repeats": 2, "probed": True,
                        "load_before": [9, 1, 1], "load_after": [9, 1, 1], "wall_seconds": 100,
                        "rates": {"test_speed": 1e9}, "rows": rows}) + "\n")
    # A record of the current probe whose host seconds were measured with each process's
    # repeats in a row (no "measurement"): counted, not tabulated, likewise.
    f.write(json.dumps({"date": "2025-12-31T00:01Z", "cpu": "Test CPU", "machine": "aaaa",
                        "cores": 2, "commit": "old", "repeats": 2, "probed": True,
                        "probe_allocator": "tcmalloc",
                        "load_before": [9, 1, 1], "load_after": [9, 1, 1], "wall_seconds": 100,
                        "rates": {"test_speed": 1e9}, "rows": rows}) + "\n")
PY
/usr/bin/python3 "$root/docs/machines/prediction_table.py" --regenerate --no-page \
  --records "$tmp/records.jsonl" > "$tmp/out" || fail "regenerate: exit $?"
has() { grep -qxF -- "$1" "$tmp/out" || fail "no line: $1"$'\n'"$(cat "$tmp/out")"; }
# Over both machines: 6 runs, median of (-5, 2, -12, 4, -1, 15) = +0.5, least -1.0, worst +15.0.
has "| cornell-box | 2 | 6 | +0.5 % | −12.0 % to +15.0 % | −1.0 % | +15.0 % | 4 of 6 | **no** |"
has "| scene2 | 2 | 6 | +2.0 % | −4.0 % to +8.0 % | +1.0 % | +8.0 % | 6 of 6 | yes |"
# The first machine alone: worst -12.0 % (by size, not the best run, not the median).
has "| cornell-box | 5 | −1.0 % | −12.0 % to +4.0 % | −1.0 % | −12.0 % | 4 of 5 | **no** |"
has "| scene2 | 5 | +3.0 % | −2.0 % to +8.0 % | +1.0 % | +8.0 % | 5 of 5 | yes |"
# The second machine's one run.
has "| cornell-box | 1 | +15.0 % | +15.0 % to +15.0 % | +15.0 % | +15.0 % | 0 of 1 | **no** |"
# The rates over the first machine's 5 probes: median 4.2e9, spread (4.4 - 4.0) / 4.2.
has "| \`test_speed\` | Test CPU, id aaaa | 5 | 4.2e+09 | 4e+09 | 4.4e+09 | 9.5 % |"
grep -qF "it holds in every run for scene2; it does **not** hold for cornell-box." "$tmp/out" \
  || fail "the opening does not say where the bound holds"$'\n'"$(cat "$tmp/out")"
grep -qF "load average 1.5 to 2.5" "$tmp/out" || fail "the load is not shown"
grep -qF "2 earlier records (1 of probes run under glibc's malloc" "$tmp/out" ||
  fail "the earlier probe's record is not named"
grep -qF "; 1 whose host seconds were measured with each process's repeats in a row" "$tmp/out" ||
  fail "the record measured in a row is not named"
# The host's drift: the first run's second probe 4.4e9 over its first 4.0e9.
grep -qF "in 1 of the 6 runs): \`test_speed\` moved by +10.0 % to +10.0 %" "$tmp/out" ||
  fail "the host's drift within a run is not given"$'\n'"$(grep -F drift "$tmp/out")"
grep -qF "| 2026-01-01T00:00Z | aaaa | abc | 2 | 1.5 → 2.5 | 100 | +10.0 % |" "$tmp/out" ||
  fail "the run's drift is not in its row"

# A line that is not a record: named, non-zero, no table.
printf '%s\n' '{"date": "x"}' >> "$tmp/records.jsonl"
if /usr/bin/python3 "$root/docs/machines/prediction_table.py" --regenerate --no-page \
     --records "$tmp/records.jsonl" > "$tmp/out2" 2> "$tmp/err"; then
  fail "a records file with a line that is not a record was read"
fi
grep -qF "records.jsonl: line 9: not a record" "$tmp/err" || fail "not named: $(cat "$tmp/err")"
[[ ! -s "$tmp/out2" ]] || fail "a table was printed from a bad records file"
# The probe's exit 4 (the host too disturbed to measure): probed again, up to 3 times in all;
# still disturbed, probe() says so (the run is then not made, or has no second probe); any
# other exit ends the script with one line naming the probe. A fake probe exits with $EXITS's
# codes in turn.
cat > "$tmp/probe" <<'SH'
#!/bin/sh
n=$(cat "$COUNT" 2>/dev/null || echo 0); echo $((n + 1)) > "$COUNT"
code=$(echo "$EXITS" | cut -d, -f$((n + 1)))
echo "machine_probe: the host was too disturbed" >&2
[ "$code" = 0 ] && : > "$2"
exit "$code"
SH
chmod +x "$tmp/probe"
COUNT="$tmp/count" /usr/bin/python3 - "$root/docs/machines/prediction_table.py" "$tmp" <<'PY' ||
import importlib.util, os, sys
path, tmp = sys.argv[1], sys.argv[2]
spec = importlib.util.spec_from_file_location("prediction_table", path)
table = importlib.util.module_from_spec(spec)
spec.loader.exec_module(table)
table.PROBE = os.path.join(tmp, "probe")
def tries(exits):
    os.environ["EXITS"] = exits
    with open(os.environ["COUNT"], "w") as f:
        f.write("0")
    try:
        result = table.probe(os.path.join(tmp, "p.xml"))
    except SystemExit as e:
        result = str(e)
    return result, int(open(os.environ["COUNT"]).read())
assert tries("4,0") == (True, 2), tries("4,0")
assert tries("4,4,4,0") == (False, 3), tries("4,4,4,0")
said, count = tries("3")
assert count == 1 and said == ("prediction_table.py: build/machine_probe failed (exit 3): "
                               "machine_probe: the host was too disturbed"), said
PY
  fail "the probe's exit 4 is not probed again, or another exit is not one line"
echo "prediction_records_test: ok"
