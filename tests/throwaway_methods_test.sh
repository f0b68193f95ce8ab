#!/usr/bin/env bash
# A method is one registration (docs/architecture.md, "How to add a method"): build/simulate_throwaway
# is ./simulate with two more form-factor methods registered from tests/throwaway_methods.cpp
# and nothing else changed, and every consumer must know them without an edit of its own:
#  1. --describe-options: the option's values, the result file's recorded_when, each method's
#     rules (V > 0, rays) under "methods";
#  2. a run: the result file records form_factors, writes the counters the method may write,
#     the summary says what the registration says; with V > 0 the gather is the method's own
#     (test-halved halves the light, so its V = 1 run differs from the ray-traced one);
#  3. the configuration check: test-unoccluded refuses V > 0 and the rays' options (exit 2);
#  4. the sweep's rules (analysis/ncube/sweep.py), reading the description the binary prints.
# Called by ctest as: throwaway_methods_test.sh SIMULATE REPO_ROOT. A few seconds.
set -u
simulate="$1"
root="$2"
throwaway="$(dirname "$simulate")/simulate_throwaway"
python=/usr/bin/python3
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
export NCUBE_ROOT="$root"
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

[ -x "$throwaway" ] || { echo "FAIL: no $throwaway (built beside simulate)"; exit 1; }

# 1. The description.
"$throwaway" --describe-options > "$work/described.json" || fail "--describe-options"
"$python" - "$work/described.json" <<'EOF' || fail "the description does not know the methods"
import json, sys
described = {d["flag"]: d for d in json.load(open(sys.argv[1]))}
ff = described["--form-factors"]
problems = []
for name in ("test-halved", "test-unoccluded"):
    if name not in ff["values"]:
        problems.append(f"{name} not among --form-factors' values")
    if name not in ff["recorded_when"]["form_factors"]:
        problems.append(f"{name} runs would not record form_factors")
    if name not in ff["methods"]:
        problems.append(f"{name} not under --form-factors' methods")
m = ff.get("methods", {})
if m.get("test-halved", {}).get("visibility_processors") is not True:
    problems.append("test-halved not defined with V > 0")
if m.get("test-unoccluded", {}).get("visibility_processors") is not False \
        or "asks no visibility processor" not in m.get("test-unoccluded", {}).get("reason", ""):
    problems.append("test-unoccluded's V = 0 rule or its reason missing")
if m.get("test-unoccluded", {}).get("traces_rays") is not False:
    problems.append("test-unoccluded said to trace rays")
print("\n".join(problems)) if problems else None
sys.exit(1 if problems else 0)
EOF

# 2. Runs: scene0, one shot.
run() {  # NAME ARGS...: writes $work/NAME.json and $work/NAME.txt
  local name="$1"; shift
  "$throwaway" scene0 --iterations 1 --json "$work/$name.json" "$@" > "$work/$name.txt" 2>&1 ||
    fail "run $name ($*): exit $?: $(head -c 300 "$work/$name.txt")"
}
run rays1 --R 1 --V 1
run halved1 --R 1 --V 1 --form-factors test-halved
run halved0 --R 1 --V 0 --form-factors test-halved
run rays0 --R 1 --V 0
run unoccluded --R 1 --V 0 --form-factors test-unoccluded
"$python" - "$work" <<'EOF' || fail "the runs do not show the methods"
import json, sys
work = sys.argv[1]
r = {n: json.load(open(f"{work}/{n}.json")) for n in ("rays1", "halved1", "halved0", "rays0", "unoccluded")}
t = {n: open(f"{work}/{n}.txt").read() for n in r}
problems = []
for n in ("halved1", "halved0", "unoccluded"):
    want = "test-unoccluded" if n == "unoccluded" else "test-halved"
    if r[n]["config"].get("form_factors") != want:
        problems.append(f"{n}: config.form_factors {r[n]['config'].get('form_factors')!r}, expected {want}")
    if "form factors          " + want not in t[n]:
        problems.append(f"{n}: the summary does not name the method")
    if any(k.startswith("hemicube_") for k in r[n]["counts"]):
        problems.append(f"{n}: writes the hemicube's counters")
if "form_factors" in r["rays1"]["config"]:
    problems.append("a ray-traced run records form_factors (the paper's files would change)")
if "samples per shooter, halved" not in t["halved1"] or "unoccluded" not in t["unoccluded"]:
    problems.append("the summary's configuration line is not the method's setting")
if "rays                  " not in t["halved0"]:
    problems.append("the summary's counted line is not the method's")
# Halved light: the one shot (the same light, shot the same way) gives every patch that is not
# a light half of the radiosity the rays give it, with V = 1 only if the gather is the method's
# own; a patch that received nothing keeps its own.
for v in ("1", "0"):
    rays, half = r["rays" + v]["patch_radiosity"], r["halved" + v]["patch_radiosity"]
    halved_patches = sum(1 for a, b in zip(rays, half)
                         if all(x > 0 and abs(y - x / 2) <= 1e-12 * x for x, y in zip(a, b)))
    if halved_patches == 0 or any(y > x for a, b in zip(rays, half) for x, y in zip(a, b)):
        problems.append(f"V = {v}: test-halved's light is not half the rays' on any patch "
                        f"(its {'gather' if v == '1' else 'shot'} not called)")
if r["unoccluded"]["counts"].get("rays", 0) != 0:
    problems.append("test-unoccluded traced rays")
print("\n".join(problems)) if problems else None
sys.exit(1 if problems else 0)
EOF

# 3. The configuration check.
refused() {  # TEXT ARGS...: exit 2 naming TEXT
  local text="$1"; shift
  "$throwaway" scene0 --iterations 1 "$@" > "$work/refused.txt" 2>&1
  local code=$?
  [ "$code" = 2 ] && grep -q "$text" "$work/refused.txt" ||
    fail "$*: exit $code, expected 2 naming \"$text\": $(head -c 300 "$work/refused.txt")"
}
refused "V = 0 only" --R 1 --V 1 --form-factors test-unoccluded
refused "does not cut the shooter" --R 1 --form-factors test-unoccluded --samples 4
refused "traces no rays" --R 1 --form-factors test-unoccluded --visibility octree

# 4. The sweep's rules, from the description this binary prints (a copy of the analysis
# package reading it; scenes and platforms are the repository's).
mkdir -p "$work/copy/analysis"
cp -r "$root/analysis/ncube" "$work/copy/analysis/ncube"
ln -s "$root/scenes" "$work/copy/scenes"
ln -s "$root/platforms" "$work/copy/platforms"
cp "$work/described.json" "$work/copy/analysis/ncube/simulate_options.json"
"$python" - "$work/copy" <<'EOF' || fail "the sweep's rules do not know the methods"
import sys
from pathlib import Path
sys.path.insert(0, sys.argv[1] + "/analysis")
from ncube import sweep
folder = Path(sys.argv[1])
problems = []
def load(cell):
    path = folder / "s.yaml"
    path.write_text("cells: [" + cell + "]\n")
    try:
        sweep.load(path)
        return None
    except sweep.SweepError as e:
        return str(e)
for cell, expected in (("{scene: scene0, R: 1, V: 1, form_factors: test-halved}", None),
                       ("{scene: scene0, R: 1, V: 0, form_factors: test-unoccluded}", None),
                       ("{scene: scene0, R: 1, V: 1, form_factors: test-unoccluded}", "V = 0 only"),
                       ("{scene: scene0, R: 1, V: 0, form_factors: test-unoccluded, samples: 4}",
                        "traces no rays")):
    error = load(cell)
    if (error is None) != (expected is None) or (expected and expected not in error):
        problems.append(f"{cell}: {error or 'accepted'}; expected {expected or 'accepted'}")
print("\n".join(problems)) if problems else None
sys.exit(1 if problems else 0)
EOF

if [ "$failures" -gt 0 ]; then
  echo "$failures failures"
  exit 1
fi
echo "throwaway methods: every consumer knows a method registered from outside its list"
