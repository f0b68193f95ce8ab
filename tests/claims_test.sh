#!/usr/bin/env bash
# analysis/claims.py (docs/accuracy.md, "The study") on a two-cell sweep of the Cornell box:
# its table's form-factor error per patch (b) is the one computed here from the cells' meshes
# and the committed exact structure, the exact structure's balance closes (its rest 0), a
# second run reuses the cells and writes the same page, a scene without an exact structure is
# one line and exit 1; two pictures side by side; the second claim's section taken from
# analysis/claims_schemes.py when it is there. (The first claim's sentences against their
# intervals: tests/claims_sentences_test.py.) The pictures at 200 x 150 (rendering 800 x 600 costs
# 1.5 s of CPU a picture and shows nothing more here). About 10 s.
set -u
simulate=$1 root=$2
scratch=$(mktemp -d) && trap 'rm -rf "$scratch"' EXIT
export NCUBE_SIMULATE=$simulate
cat > "$scratch/accuracy-test.yaml" <<'YAML'
name: claims-test
measure: total_seconds
options: {R: 2, V: 1}
grid:
  scene: [cornell-box]
  samples: [1, 4]
YAML
failed=0
fail() { echo "FAIL: $*"; failed=1; }
cat > "$scratch/pictures-test.yaml" <<'YAML'
name: claims-pictures-test
measure: total_seconds
options: {scene: cornell-box, R: 2, V: 0, iterations: 3, image_width: 200, image_height: 150}
cells:
  - {samples: 1}
  - {form_factors: hemicube, hemicube_resolution: 20}
YAML
run() {
  /usr/bin/python3 "$root/analysis/claims.py" --results "$scratch/results" --sweeps "$@" \
    --pictures "$scratch/pictures-test.yaml" --pictures-figure "$scratch/pictures.png" \
    --no-schemes --no-hemicube --out "$scratch/claims.md" --figure "$scratch/claims.png"
}
run "$scratch/accuracy-test.yaml" > "$scratch/out" 2>&1 || fail "claims.py: $(cat "$scratch/out")"
[[ -s $scratch/claims.png ]] || fail "no figure"
[[ -s $scratch/pictures.png && $(ls "$scratch"/results/claims/pictures/*.png | wc -l) == 2 ]] ||
  fail "no pictures"
grep -qF "Left to right: cornell-box: ray-traced M=1, R=2 V=0, 3 iterations; cornell-box: hemicube N=20 centre, R=2 V=0, 3 iterations." \
  "$scratch/claims.md" || fail "the pictures' labels: $(grep -F 'Left to right' "$scratch/claims.md")"
cp "$scratch/claims.md" "$scratch/first.md"
before=$(stat -c %i "$scratch"/results/claims/cells/*.ply | sort | tr '\n' ' ')
run "$scratch/accuracy-test.yaml" > "$scratch/out" 2>&1 || fail "second run: $(cat "$scratch/out")"
after=$(stat -c %i "$scratch"/results/claims/cells/*.ply | sort | tr '\n' ' ')
[[ $before == "$after" ]] || fail "the second run ran the cells again"
cmp -s "$scratch/first.md" "$scratch/claims.md" || fail "a second run writes another page"
sed 's/cornell-box/scene2/; s/samples: \[1, 4\]/samples: [1]/; s/R: 2, V: 1/R: 4, V: 0/' \
  "$scratch/accuracy-test.yaml" > "$scratch/accuracy-scene2.yaml"
run "$scratch/accuracy-scene2.yaml" > "$scratch/out" 2> "$scratch/err"
rc=$?
[[ $rc != 0 && $(wc -l < "$scratch/err") == 1 && $(cat "$scratch/err") == *"no exact structure for scene2"* ]] ||
  fail "scene2 without an exact structure: exit $rc, $(cat "$scratch/err")"
# Every figure the committed page shows is an output claims.py takes an option for (its
# default the committed file): with --out elsewhere no committed figure is written (the cost
# figure and the speedup curves were written onto the committed ones whatever the options).
/usr/bin/python3 "$root/tests/robustness/argparse_options.py" "$root/analysis/claims.py" \
  > "$scratch/options.json" || fail "claims.py's options not read"
# The checks of the first run's page (first.md, its copy), the second claim's section and the
# page's figures, in one python3 (each python3 start and its imports cost 0.1 to 0.3 CPU s).
/usr/bin/python3 - "$root" "$scratch" "$scratch/options.json" <<'PY' || failed=1
# (b) per patch, worked out here: the area-weighted RMS over patches of the symmetric difference
# (Y - Y_s) / ((Y + Y_s) / 2) (docs/accuracy.md, "The error measure"), Y the patch's
# area-weighted mean luminance of the mesh's elements, Y_s the exact structure's.
import json, math, re, sys, types
from pathlib import Path
root, scratch = Path(sys.argv[1]), Path(sys.argv[2])
sys.path.insert(0, str(root / "analysis"))
from ncube import accuracy
structure = json.loads((root / "analysis/reference/structure/cornell-box-patches.json").read_text())
meshes = sorted((scratch / "results/claims/cells").glob("cornell-box-R2-V1-*.ply"))
rows = [l for l in (scratch / "first.md").read_text().splitlines()
        if l.startswith("| ray-traced, R=2 V=1 |")]
problems = []
if len(meshes) != 2 or len(rows) != 2:
    problems.append(f"{len(meshes)} meshes, {len(rows)} rows")
Y = lambda rgb: 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2]
def patch_means(values):
    total, area = {}, {}
    for (patch, a, *_), y in zip(structure["elements"], values):
        total[patch] = total.get(patch, 0.0) + a * y
        area[patch] = area.get(patch, 0.0) + a
    return {p: total[p] / area[p] for p in total}, area
truth, area = patch_means([Y(e[2:]) for e in structure["elements"]])
expected = []
for mesh in meshes:
    got, _ = patch_means([Y(rgb) for _, rgb in accuracy.solution_from_ply(mesh)])
    num = sum(area[p] * ((got[p] - truth[p]) / ((got[p] + truth[p]) / 2)) ** 2 for p in truth)
    expected.append("%.2f" % (100 * math.sqrt(num / sum(area.values()))))
shown = [re.findall(r"\| ([0-9.]+) % \[", row)[3] for row in rows]
if sorted(expected) != sorted(shown):
    problems.append(f"(b) per patch: table {shown}, worked out {expected}")
page = (scratch / "first.md").read_text()
balance = [l for l in page.splitlines() if l.startswith("| cornell-box | exact structure (patches) |")]
if not balance or not balance[0].endswith("| 0.00 % |"):
    problems.append(f"the exact structure's balance does not close: {balance}")
import claims
def check(name, got, expected):
    if got != expected:
        problems.append(f"{name}: got {got!r}, expected {expected!r}")
# The second claim's section: analysis/claims_schemes.py's section(results) when importable,
# its figure where claims.py's option says.
sys.modules["claims_schemes"] = types.SimpleNamespace(
    section=lambda results, jobs=2, figure=None: f"from {results} to {figure}")
check("schemes section", claims.schemes_section("R", 2, "F"), "from R to F")
# Every figure the committed page shows is an option's default (above).
defaults = {str(Path(o["default"]).resolve()) for o in json.loads(Path(sys.argv[3]).read_text())
            if isinstance(o["default"], str)}
shown = re.findall(r"\]\((figures/[^)]+\.png)\)", (root / "analysis/claims.md").read_text())
missing = [f for f in shown if str((root / "analysis" / f).resolve()) not in defaults]
if not shown or missing:
    problems.append(f"figures the page shows without an option of claims.py: {missing or 'none shown'}")
for p in problems:
    print("FAIL:", p)
sys.exit(1 if problems else 0)
PY
[[ $failed == 0 ]] && echo "claims_test: passed"
exit $failed
