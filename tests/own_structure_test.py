"""analysis/ncube/own_structure.py and the sentences analysis/claims_hemicube.py makes from its
tables, against values worked out here (no runs; about 2 s):

* the ratio of two errors against two truths, given the same truth twice, is
  error_parts.ratio_interval's to the last bit (the same draws of patches);
* the front of a hand-made set of (cost, error) points is the one read off by hand;
* at equal cost the hemicube's best cell within the rays' time is chosen, and a rays' cell
  cheaper than every hemicube cell has none;
* every sentence of the section agrees with its table: the counts of holds / undecided / does
  not hold and the ratios' range recounted from canned decisions, and the verdicts turn when
  the figures do."""
import sys
from pathlib import Path

root = Path(sys.argv[1])
sys.path.insert(0, str(root / "analysis"))
import numpy as np  # noqa: E402

import claims_hemicube as ch  # noqa: E402
from ncube import claim_one, error_parts, own_structure  # noqa: E402

problems = []

# --- two truths, given the same one: the one-truth ratio exactly --------------------------
rng = np.random.default_rng(7)
patches = 9
patch_of = np.repeat(np.arange(patches), 4)
area = rng.uniform(0.5, 2.0, len(patch_of))
truth_y = rng.uniform(0.2, 1.0, len(patch_of))
truth = error_parts.Truth(truth_y, area, patch_of, patches, np.zeros(len(patch_of), bool), widen=0.003)
a = truth_y * (1 + rng.normal(0, 0.2, len(truth_y)))
b = truth_y * (1 + rng.normal(0, 0.05, len(truth_y)))
if own_structure.ratio_interval(a, truth, b, truth) != error_parts.ratio_interval(a, b, truth):
    problems.append("two truths given the same one differ from error_parts.ratio_interval")
# Against a truth moved by the top's own error the top's RMS is 0, the ratio 0.
moved = error_parts.Truth(a, area, patch_of, patches, np.zeros(len(patch_of), bool))
ratio, low, high = own_structure.ratio_interval(a, moved, b, truth)
if ratio != 0.0 or low != 0.0:
    problems.append(f"against itself the top's ratio is {ratio} [{low}, {high}], expected 0")

# --- the front, read off by hand ------------------------------------------------------------
points = [(1.0, 0.5), (2.0, 0.6), (2.0, 0.3), (4.0, 0.3), (8.0, 0.1), (0.5, 0.9), (8.0, 0.2)]
# (0.5, 0.9) cheapest; (1, 0.5) beats nothing cheaper; (2, 0.6) beaten by (1, 0.5);
# (2, 0.3) on it; (4, 0.3) beaten by (2, 0.3); (8, 0.1) on it; (8, 0.2) beaten by (8, 0.1).
if own_structure.front(points) != [0, 2, 4, 5]:
    problems.append(f"front {own_structure.front(points)}, expected [0, 2, 4, 5]")
if own_structure.front([(1.0, 0.2), (1.0, 0.2)]) != [0]:
    problems.append("a tie in cost and error keeps more than the first")

# --- at equal cost --------------------------------------------------------------------------
def cell(kind, value, seconds, error, placement="centre"):
    return {"scene": "s", "V": 0, "status": "ok", "converged": True, "id": f"{kind}{value}{placement}",
            "form_factors": "hemicube" if kind == "h" else "ray-traced",
            "parallelisation": "shooters" if kind == "h" else "receivers", "placement": placement,
            "value": value, "simulated_seconds": seconds, "host_seconds": seconds,
            "a_patch": (error, error * 0.9, error * 1.1)}

rows = [cell("r", 1, 10.0, 0.10), cell("r", 64, 100.0, 0.02), cell("h", 20, 2.0, 0.30),
        cell("h", 100, 9.0, 0.20), cell("h", 400, 50.0, 0.05), cell("h", 20, 200.0, 0.01, "elements")]
picked = []
original = own_structure.pair_ratio
own_structure.pair_ratio = lambda top, bottom, key, *rest: (top[key][0] / bottom[key][0],) * 3
try:
    for e in own_structure.at_equal_cost(rows, None, None, None, "a_patch"):
        picked.append((e["rays"]["value"], e["hemicube"]["id"] if e["hemicube"] else None))
    early = own_structure.at_equal_cost([cell("r", 1, 1.0, 0.1), cell("h", 20, 2.0, 0.3)],
                                        None, None, None, "a_patch")
finally:
    own_structure.pair_ratio = original
if picked != [(1, "h100centre"), (64, "h400centre")]:
    problems.append(f"at equal cost picked {picked}, expected N=100 within 10 s and N=400 within 100 s")
if early[0]["hemicube"] is not None:
    problems.append("a rays' cell cheaper than every hemicube cell was given one")

# --- the sentences against their tables ---------------------------------------------------
def decision(measure, placement, ratio, low, high):
    return {"scene": "s", "measure": measure, "placement": placement, "resolution": 20,
            "samples": 64, "rays": (0.01, 0.0, 0.02), "hemicube": (0.1, 0.0, 0.2),
            "ratio": ratio, "low": low, "high": high, "verdict": claim_one.verdict(ratio, low, high)}

canned = [decision("a_patch", "centre", 3.0, 2.5, 4.0), decision("a_patch", "centre", 2.5, 1.5, 3.0),
          decision("a_patch", "centre", 4.0, 3.0, 5.0),
          decision("a_patch", "centre", 1.1, 0.9, 1.3), decision("a_patch", "elements", 0.8, 0.7, 0.9)]
s = ch.verdict_sentence(canned, "a_patch", "centre")
if "holds in 2 of 4 comparisons, is undecided in 1, does not hold in 1 (ratios 1.10 to 4.00)" not in s:
    problems.append("canned centre: " + s)
s = ch.verdict_sentence(canned, "a_patch", "elements")
if "holds in 0 of 1 comparisons, is undecided in 0, does not hold in 1 (ratios 0.80 to 0.80)" not in s:
    problems.append("canned elements: " + s)
if ch.verdict_sentence(canned, "b_own_patch", "centre") is not None:
    problems.append("a measure without decisions made a sentence")
# The verdict turns with the interval: the undecided one's low end raised to 2 holds.
canned[1] = decision("a_patch", "centre", 2.5, 2.0, 3.0)
if "holds in 3 of 4" not in ch.verdict_sentence(canned, "a_patch", "centre"):
    problems.append("the sentence did not turn with the interval")
equal = [{"rays": None, "hemicube": {}, "ratio": 0.5, "low": 0.4, "high": 0.6, "verdict": "does not hold"},
         {"rays": None, "hemicube": None},
         {"rays": None, "hemicube": {}, "ratio": 5.0, "low": 2.2, "high": 9.0, "verdict": "holds"}]
s = ch.equal_cost_sentence(equal, "a_patch")
if "holds in 1 of 2, is undecided in 0, does not hold in 1 (ratios 0.50 to 5.00)" not in s:
    problems.append("canned equal cost: " + s)
if ch.equal_cost_sentence([{"rays": None, "hemicube": None}], "a_patch") is not None:
    problems.append("equal cost with no hemicube cell within time made a sentence")

# --- the proximity accident, read off a hand-made structure ------------------------------
scene = {"patches": [
    {"vertices": [[0, 0, 0], [0, 0, 2], [2, 0, 2], [2, 0, 0]], "elements": [1, 1]},     # floor, up
    {"vertices": [[1.01, 0, 0], [1.01, 0, 2], [1.01, 0.5, 2], [1.01, 0.5, 0]]}]}       # a face at x = 1.01 facing -x
structure = {"elements": [[0, 4, 0, 0, 0], [1, 1, 0, 0, 0]], "above_one": [[1, 0, 3.5]]}
groups = own_structure.proximity(scene, structure, "centre")
if len(groups) != 1 or groups[0]["shooter"] != 0 or groups[0]["receiver"] != 1 \
        or abs(groups[0]["distance"] - 0.01) > 1e-12 or groups[0]["largest"] != 3.5:
    problems.append(f"proximity {groups}, expected the floor's centre 0.01 in front of patch 1")

if problems:
    print("\n".join(problems))
    sys.exit(1)
print("own_structure: ok")
