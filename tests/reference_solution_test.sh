#!/usr/bin/env bash
# build/reference_solution (docs/accuracy.md) on small scenes with closed forms (a closed
# furnace, two opposed squares), the result not depending on the number of threads, bad input
# exit 2 with one line; and the committed references' identity, cheaply: each file is what its
# recorded command made, of today's scene file, and this build's fingerprint (a small run) is
# the one recorded with them (analysis/ncube/reference_manifest.py), so that the program still
# computes what made them. Regenerating them is the references' own command
# (`experiments/claims/references --check`: minutes to an hour, docs/accuracy.md). About 30 s.
set -u
simulate=$1 root=$2
solver=$(dirname "$simulate")/reference_solution
scratch=$(mktemp -d) && trap 'rm -rf "$scratch"' EXIT
failed=0
fail() { echo "FAIL: $*"; failed=1; }
same() {  # two reference files equal but for their host-time and version fields
  /usr/bin/python3 - "$1" "$2" <<'PY'
import json, sys
a, b = (json.load(open(p)) for p in sys.argv[1:3])
for d in (a, b):
    d.pop("host_seconds"); d.pop("code_version")
sys.exit(0 if a == b else 1)
PY
}

# Bad input: one line, exit 2, no file.
for args in "--samples 9" "--samples 2" "--samples 4096" "--threads -1" "--samples x" "--refine 0" "--refine 5" \
    "--structure elements --samples 4" "--structure hemicube-elements --samples 4"; do
  "$solver" cornell-box $args --out "$scratch/bad.json" > "$scratch/out" 2> "$scratch/err"
  rc=$?
  [[ $rc == 2 && $(wc -l < "$scratch/err") == 1 && ! -e $scratch/bad.json ]] ||
    fail "$args: exit $rc, $(cat "$scratch/err")"
done
"$solver" "$scratch/none.json" --out "$scratch/bad.json" 2> "$scratch/err"
rc=$?
[[ $rc == 2 && $(cat "$scratch/err") == *none.json* ]] || fail "missing scene: exit $rc"

# Threads change nothing: this run on one thread is held (below) against the references'
# command's own run of the same case (K = 4, --refine 1) on every core (--threads 0: 2 on the
# suite's machine; with fewer cores, a --threads 2 run of it here instead).
"$solver" cornell-box --samples 4 --refine 1 --threads 1 --quiet --out "$scratch/one.json" \
  --mesh "$scratch/one.ply" || fail "--threads 1 failed"

# --mesh is the same solution in ./simulate's mesh layout: no error against the file.
measured=$(/usr/bin/python3 "$root/analysis/ncube/accuracy.py" "$scratch/one.ply" "$scratch/one.json")
[[ $measured == "element RMS 0  patch RMS 0  largest patch error 0 "* ]] || fail "--mesh: $measured"

# A closed furnace: the unit cube's six faces inward, 4 x 4 elements each, every one emitting
# 1 with reflectance 0.5. Every row of F sums to 1, so B = E / (1 - rho) = 2 everywhere,
# through the whole tool (scene loading, rays, solver, file): within 1 % at K = 64
# (tests/models/furnace.json, which structure_solution_file_test.sh solves too).
"$solver" "$root/tests/models/furnace.json" --samples 64 --quiet --out "$scratch/furnace-ref.json" &&
  /usr/bin/python3 -c '
import json, sys
r = json.load(open(sys.argv[1]))
worst = max(abs(c - 2) for e in r["elements"] for c in e[2:])
sys.exit(0 if len(r["elements"]) == 96 and worst < 0.01 else "furnace: |B - 2| up to %g" % worst)
' "$scratch/furnace-ref.json" || fail "the furnace is not 2 everywhere"

# Two opposed unit squares one apart, 2 x 2 elements each: an emitter (E = 1, rho = 0) and a
# receiver (rho = 0.5): the receiver's mean is 0.5 F = 0.5 x 0.19982 (Howell C-11), through the
# parts' near closed form; within 0.5 % at K = 64.
cat > "$scratch/squares.json" <<'JSON'
{"name": "squares", "patches": [
 {"vertices": [[0,0,0],[1,0,0],[1,1,0],[0,1,0]], "reflectance": [0,0,0], "emission": [1,1,1], "elements": [2,2]},
 {"vertices": [[0,0,1],[0,1,1],[1,1,1],[1,0,1]], "reflectance": [0.5,0.5,0.5], "elements": [2,2]}]}
JSON
"$solver" "$scratch/squares.json" --samples 64 --quiet --out "$scratch/squares-ref.json" &&
  /usr/bin/python3 -c '
import json, math, sys
r = json.load(open(sys.argv[1]))
exact = 0.5 * 2 / math.pi * (math.log(math.sqrt(4 / 3)) + 2 * math.sqrt(2) * math.atan(1 / math.sqrt(2)) - 2 * math.atan(1))
mean = sum(e[1] * e[2] for e in r["elements"] if e[0] == 1) / sum(e[1] for e in r["elements"] if e[0] == 1)
sys.exit(0 if abs(mean / exact - 1) < 0.005 else "squares: the receiver %.6f, exact %.6f" % (mean, exact))
' "$scratch/squares-ref.json" || fail "the opposed squares are not Howell's value"

# The committed references: recorded, unchanged, of today's scene files, and this build's
# fingerprint the recorded one. The fingerprint is run once for the four uses below (this
# check, the references' command's record, the two checks of its output): kept in the scratch
# folder under the program file's SHA-256 (reference_manifest.py, NCUBE_FINGERPRINT_CACHE).
export NCUBE_FINGERPRINT_CACHE=$scratch/fingerprints
/usr/bin/python3 "$root/analysis/ncube/reference_manifest.py" check "$root/analysis/reference" \
  --build "$(dirname "$solver")" --scenes-dir "$root/scenes" || fail "the committed references (above)"
# The references' own command, small (K = 4, --refine 1): it writes the reference and its
# records, and the check passes on what it wrote; an edited file then fails it.
"$root/experiments/claims/references" --build "$(dirname "$solver")" --out "$scratch/refs" \
  --samples 4 --refine 1 cornell-box > /dev/null &&
  /usr/bin/python3 "$root/analysis/ncube/reference_manifest.py" check "$scratch/refs" \
    --build "$(dirname "$solver")" --scenes-dir "$root/scenes" > /dev/null ||
  fail "experiments/claims/references: its own output does not check"
many=$scratch/refs/cornell-box.json
if (( $(getconf _NPROCESSORS_ONLN) < 2 )); then
  many=$scratch/two.json
  "$solver" cornell-box --samples 4 --refine 1 --threads 2 --quiet --out "$many" || fail "--threads 2 failed"
fi
same "$scratch/one.json" "$many" || fail "--threads 1 and 2 differ"
sed -i 's/"element_pairs": /"element_pairs": 1/' "$scratch/refs/cornell-box.json"
/usr/bin/python3 "$root/analysis/ncube/reference_manifest.py" check "$scratch/refs" \
  --build "$(dirname "$solver")" --scenes-dir "$root/scenes" > "$scratch/out" &&
  fail "an edited reference passes the check"
grep -q "cornell-box.json: its content is not what its command made" "$scratch/out" ||
  fail "an edited reference: $(cat "$scratch/out")"
[[ $failed == 0 ]] && echo "reference_solution_test: passed"
exit $failed
