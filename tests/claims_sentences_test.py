#!/usr/bin/env python3
"""The first claim's sentences against their intervals (analysis/ncube/claim_one.py,
docs/accuracy.md "Deciding the first claim"): a verdict follows from its interval and the
threshold alone; a sentence says "holds" of exactly the decisions whose interval holds, never
"holds" of one whose interval straddles or lies below the threshold; and every decision row of
the committed analysis/claims.md says the verdict its own printed interval gives, and its
sentence is the one claim_sentence writes from those rows.

usage: claims_sentences_test.py SOURCE_DIR"""
import re
import sys
from pathlib import Path

root = Path(sys.argv[1])
sys.path.insert(0, str(root / "analysis"))
from ncube import claim_one  # noqa: E402

failures = []


def check(condition, what):
    if not condition:
        failures.append(what)


T = claim_one.THRESHOLD
# The verdict from the interval alone.
check(claim_one.verdict(3.0, 2.5, 4.0) == "holds", "ratio and low end above: holds")
check(claim_one.verdict(3.0, 1.9, 4.0) == "undecided", "low end below the threshold: not holds")
check(claim_one.verdict(1.5, 1.2, 1.9) == "does not hold", "high end below: does not hold")
check(claim_one.verdict(2.0, 2.0, 2.5) == "holds", "at the threshold: holds (at least)")
check(claim_one.verdict(1.99, 1.5, 2.0) == "undecided", "high end at the threshold: undecided")
check(claim_one.direction(1.1, 3) == "hemicube less accurate", "direction above 1")
check(claim_one.direction(0.5, 0.9) == "hemicube more accurate", "direction below 1")
check(claim_one.direction(0.9, 1.1) == "not distinguishable", "direction straddling 1")


def decision(scene, measure, n, ratio, low, high, placement="centre"):
    return {"scene": scene, "measure": measure, "placement": placement, "resolution": n,
            "ratio": ratio, "low": low, "high": high, "rays": (0.01, 0.009, 0.011),
            "hemicube": (ratio * 0.01, low * 0.01, high * 0.01), "samples": 64}


every = [decision("a", "element", 100, 5, 3, 7), decision("a", "patch", 100, 4, 2.5, 6)]
check(claim_one.claim_sentence(every).startswith("**holds**"), "all hold: the sentence holds")
none = [decision("a", "element", 100, 1.2, 0.8, 1.6), decision("a", "patch", 100, 1.1, 0.9, 1.5)]
check(claim_one.claim_sentence(none).startswith("**does not hold**"), "none hold")
straddle = [decision("a", "element", 100, 2.4, 1.5, 3.1)]
sentence = claim_one.claim_sentence(straddle)
check(not sentence.startswith("**holds"), f"a straddling interval is not 'holds': {sentence}")
check("is undecided on a element at N = 100" in sentence, f"the straddling decision named: {sentence}")
mixed = every + none + straddle
sentence = claim_one.claim_sentence(mixed)
check(sentence.startswith("**holds only in part**"), f"mixed: {sentence}")
check("holds on a element at N = 100; a patch at N = 100" in sentence,
      f"mixed: the holding ones named: {sentence}")

# The committed page: every decision row's verdict is its printed interval's, and the sentence is
# claim_sentence of the rows.
page = (root / "analysis" / "claims.md").read_text()
row = re.compile(r"^\| (\S+) \| (element|patch) \| (centre|elements) N=(\d+) \| [^|]+ \| [^|]+ \| "
                 r"([0-9.]+) \[([0-9.]+), ([0-9.]+|∞)\] \| ([a-z ]+) \| ([a-z ]+) \|$")
rows = [m.groups() for m in map(row.match, page.splitlines()) if m]
check(rows, "analysis/claims.md has the first claim's decision rows")
for scene, measure, placement, n, ratio, low, high, said, direction in rows:
    ratio, low, high = float(ratio), float(low), float("inf") if high == "∞" else float(high)
    # The page prints two decimals: a verdict is checked where rounding cannot flip it.
    if min(abs(ratio - T), abs(low - T), abs(high - T)) > 0.005:
        check(said == claim_one.verdict(ratio, low, high),
              f"claims.md {scene} {measure} {placement} N={n}: says '{said}' of {ratio} [{low}, {high}]")
    if min(abs(low - 1), abs(high - 1)) > 0.005:
        check(direction == claim_one.direction(low, high),
              f"claims.md {scene} {measure} {placement} N={n}: says '{direction}' of [{low}, {high}]")
# After the page's opening (its own numbered sentences: tests/openings_test.py checks them).
body = page.split("<!-- end of the opening -->", 1)[-1]
sentences = [line[3:] for line in body.splitlines() if line.startswith("1. ")]
check(len(sentences) == 1, "one first-claim sentence in analysis/claims.md")
if rows and sentences:
    said = sentences[0].split(" (")[0]
    verdicts = {claim_one.verdict(float(r[4]), float(r[5]), float("inf") if r[6] == "∞" else float(r[6]))
                for r in rows}
    if verdicts == {"holds"}:
        check(said == "**holds**", f"every row holds, the sentence says {said}")
    elif "holds" not in verdicts:
        check(said in ("**does not hold**", "**is not shown to hold**"),
              f"no row holds, the sentence says {said}")
    else:
        check(said == "**holds only in part**", f"some rows hold, the sentence says {said}")

if failures:
    print("\n".join(failures))
    sys.exit(1)
print(f"claims sentences: {len(rows)} decision rows of analysis/claims.md checked")
