#!/usr/bin/env bash
# analysis/cycles/cycles_answers.py (docs/accuracy.md, "Against Cycles") on closed forms, where
# Debian's blender is installed (skipped, exit 77, elsewhere): units, one-sided emitters and
# receivers, opaque backs, enough bounces; the committed Cornell box answers reproduce. About 2
# minutes on a shared 2-core machine.
set -u
root=$2
command -v blender > /dev/null || { echo "cycles_answers_test: skipped: no blender on PATH"; exit 77; }
answers=$root/analysis/cycles/cycles_answers.py
scratch=$(mktemp -d) && trap 'rm -rf "$scratch"' EXIT
failed=0
fail() { echo "FAIL: $*"; failed=1; }

/usr/bin/python3 - "$scratch" <<'PY'
import json, sys
d = sys.argv[1]
up = [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]]          # z = 0 facing +z
def at(z, facing_up):
    q = [[x, y, z] for x, y, _ in up]
    return q if facing_up else q[::-1]
# Two parallel unit squares one apart: the emitter E1 (z = 0, up, E = 1) and the receiver A
# (z = 1, down, rho = 0.5): B_A = 0.5 F = 0.5 x 0.19982 (Howell C-11). A second emitter E2
# (z = 2, down) shines on A's back only, which must take nothing (one-sided receiver, opaque
# back); R (z = -1, up) faces E1's back, which must send nothing (one-sided emitter): B_R = 0.
json.dump({"name": "squares", "patches": [
    {"vertices": at(0, True), "reflectance": [0, 0, 0], "emission": [1, 1, 1], "elements": [1, 1]},
    {"vertices": at(1, False), "reflectance": [0.5, 0.5, 0.5], "elements": [1, 1]},
    {"vertices": at(2, False), "reflectance": [0, 0, 0], "emission": [1, 1, 1], "elements": [1, 1]},
    {"vertices": at(-1, True), "reflectance": [0.5, 0.5, 0.5], "elements": [1, 1]}]},
    open(f"{d}/squares.json", "w"))
# A furnace: the unit cube's faces inward, E = 1, rho = 0.8: B = E / (1 - rho) = 5 (paths of
# many bounces: a cap on them, or clamping, reads low).
faces = [[[0,0,0],[1,0,0],[1,1,0],[0,1,0]], [[0,0,1],[0,1,1],[1,1,1],[1,0,1]],
         [[0,0,0],[0,1,0],[0,1,1],[0,0,1]], [[1,0,0],[1,0,1],[1,1,1],[1,1,0]],
         [[0,0,0],[0,0,1],[1,0,1],[1,0,0]], [[0,1,0],[1,1,0],[1,1,1],[0,1,1]]]
json.dump({"name": "furnace", "patches": [{"vertices": f, "reflectance": [0.8] * 3,
           "emission": [1, 1, 1], "elements": [1, 1]} for f in faces]}, open(f"{d}/furnace.json", "w"))
PY

run() { /usr/bin/python3 "$answers" "$@" > "$scratch/out" 2> "$scratch/err"; }
run "$scratch/squares.json" --out "$scratch/squares-answer.json" --texels 16 --samples 64 --seeds 4 --threads 2 ||
  fail "squares: $(cat "$scratch/err")"
/usr/bin/python3 - "$scratch/squares-answer.json" <<'PY' || fail "the squares"
import json, math, sys
p = json.load(open(sys.argv[1]))["patches"]
x = 1.0
exact = 0.5 * 2 / (math.pi * x * x) * (math.log(math.sqrt((1 + x*x)**2 / (1 + 2*x*x)))
                                       + 2 * x * math.sqrt(1 + x*x) * math.atan(x / math.sqrt(1 + x*x))
                                       - 2 * x * math.atan(x))
y, se = p[1][8], p[1][9]
print(f"squares: B_A {y:.6f} +- {se:.6f} (exact {exact:.6f}), B_R {p[3][8]}, emitters {p[0][8]} {p[2][8]}")
ok = abs(y - exact) <= 4 * se + 1e-3 * exact and p[3][8] == 0.0 and p[0][8] == 1.0 and p[2][8] == 1.0
sys.exit(0 if ok else 1)
PY
run "$scratch/furnace.json" --out "$scratch/furnace-answer.json" --texels 16 --samples 64 --seeds 4 --threads 2 ||
  fail "furnace: $(cat "$scratch/err")"
/usr/bin/python3 - "$scratch/furnace-answer.json" <<'PY' || fail "the furnace"
import json, math, sys
p = json.load(open(sys.argv[1]))["patches"]
mean = sum(r[8] for r in p) / 6
se = math.sqrt(sum(r[9] ** 2 for r in p)) / 6
print(f"furnace: B {mean:.5f} +- {se:.5f} (exact 5), patches {min(r[8] for r in p):.4f} to {max(r[8] for r in p):.4f}")
sys.exit(0 if abs(mean - 5) <= 4 * se and all(abs(r[8] - 5) <= 4 * r[9] + 1e-3 for r in p) else 1)
PY
# The same command gives the same answers but for the seconds (Cycles is deterministic for a seed).
run "$scratch/squares.json" --out "$scratch/again.json" --texels 16 --samples 64 --seeds 4 --threads 1 &&
  /usr/bin/python3 - "$scratch/squares-answer.json" "$scratch/again.json" <<'PY' || fail "a second run differs"
import json, sys
a, b = (json.load(open(p)) for p in sys.argv[1:3])
for d in (a, b):
    for k in ("host_seconds", "bake_seconds", "threads"):
        d.pop(k)
sys.exit(0 if a == b else 1)
PY
# The committed Cornell box answers reproduce from their command (experiments/claims/cycles-answers)
# but for the seconds and the thread count: about a minute.
"$root/experiments/claims/cycles-answers" --out "$scratch/committed" cornell-box > /dev/null 2>&1 &&
  /usr/bin/python3 - "$root/analysis/cycles/cornell-box.json" "$scratch/committed/cornell-box.json" <<'PY' ||
import json, sys
a, b = (json.load(open(p)) for p in sys.argv[1:3])
for d in (a, b):
    for k in ("host_seconds", "bake_seconds", "threads"):
        d.pop(k)
sys.exit(0 if a == b else 1)
PY
  fail "analysis/cycles/cornell-box.json does not reproduce from experiments/claims/cycles-answers"
# Bad input: one line, exit 2, no file.
for args in "--seeds 1" "--samples 0"; do
  run "$scratch/squares.json" $args --out "$scratch/bad.json"
  rc=$?
  [[ $rc == 2 && $(wc -l < "$scratch/err") == 1 && ! -e $scratch/bad.json ]] || fail "$args: exit $rc"
done
run "$scratch/none.json" --out "$scratch/bad.json"
rc=$?
[[ $rc == 2 && $(cat "$scratch/err") == *none.json* ]] || fail "missing scene: exit $rc"
[[ $failed == 0 ]] && echo "cycles_answers_test: passed"
exit $failed
