#!/usr/bin/env python3
"""The claims page's generated sentences against their tables. The first claim's sentences against their intervals (analysis/ncube/claim_one.py,
docs/accuracy.md "Deciding the first claim"): a verdict follows from its interval and the
threshold alone; a sentence says "holds" of exactly the decisions whose interval holds, never
"holds" of one whose interval straddles or lies below the threshold; and every decision row of
the committed analysis/claims.md says the verdict its own printed interval gives, and its
sentence is the one claim_sentence writes from those rows. Also on the committed page: no
converged cell's total error (a) is as large as that of the solution without light transport
(B = E, its row in the structures' table); every balance row adds up (absorbed, leaves the
scene, the structure's own loss and the rest make the emitted power); claim 2's fixed error is a
third of B = E's and the paper's first shot lies above it and its band; and claim 2's decision
gives the ratios its tables give.

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

# ---- The page's other generated sentences against their tables.
def table_after(text, heading):
    """The rows (lists of cells) of the first table after the heading line."""
    lines = text.split(heading, 1)[1].splitlines() if heading in text else []
    rows, started = [], False
    for line in lines[1:]:
        if line.startswith("|"):
            started = True
            if not set(line.replace("|", "").strip()) <= set("-: "):
                rows.append([c.strip() for c in line.strip().strip("|").split("|")])
        elif started:
            break
    return rows[1:] if rows else []   # without the header row


def value(cell):
    m = re.match(r"(-?[0-9.]+)", cell)
    return float(m.group(1)) if m else None


structures = table_after(body, "## The structure's own error (c)")
check(structures, "the structures' table")
dark = {r[0]: r for r in structures if r[1] == "no light transport (B = E)"}
for r in structures:
    if r[1].startswith("exact structure") or r[1].startswith("every element"):
        total = sum(value(c) for c in r[4:8])
        check(abs(total - 100) < 0.03, f"{r[0]} {r[1]}: the balance adds to {total:.2f} %")
for scene, r in dark.items():
    cells = table_after(body, f"### {scene}\n")
    check(cells, f"{scene}: the error taken apart")
    for c in cells:
        if "(not converged)" in c[2]:
            continue
        for column, name in ((4, "(a) element"), (5, "(a) patch")):
            if value(c[column]) is not None and value(r[column - 2]) is not None:
                check(value(c[column]) < value(r[column - 2]),
                      f"{scene} {c[0]} {c[1]}: {name} {c[column]} not below B = E's {r[column - 2]}")
check(len(dark) >= 2, f"B = E's rows: {sorted(dark)}")

ratios = {"convergence": [], "error": []}
for scene in ("cornell-box", "scene0"):
    heading = f"### {scene}: to convergence and to a fixed error"
    if heading not in body:
        continue
    text = body.split(heading, 1)[1]
    level = re.search(r"element error at most ([0-9.]+), 1/3 of the ([0-9.]+) of the solution", text)
    first = re.search(r"after its first shot .*? is at ([0-9.]+)", text)
    band = re.search(r"the reference's own error ([0-9.]+)\)", text)
    check(level and first and band, f"{scene}: the fixed error's paragraph")
    if level and first and band:
        L, dark_error = float(level.group(1)), float(level.group(2))
        check(abs(L - dark_error / 3) < 1e-4, f"{scene}: the level {L} is not a third of {dark_error}")
        check(float(first.group(1)) > L + float(band.group(1)),
              f"{scene}: the first shot's {first.group(1)} is not above the level and its band")
    scheme_rows = table_after(body, heading)
    swept = table_after(text, "--shooters-per-iteration S at")
    for n in sorted({r[0] for r in scheme_rows}, key=int):
        paper = [r for r in scheme_rows if r[0] == n and r[1].startswith("receivers") and value(r[5]) is not None]
        other = [(value(r[5]), value(r[6])) for r in scheme_rows if r[0] == n and r[1] == "circulation"
                 and value(r[5]) is not None]
        if n == "16":
            other += [(value(r[3]), value(r[4])) for r in swept if r[1] == "circulation"]
        if not paper or not other:
            continue
        best = min(paper, key=lambda r: value(r[5]))
        ratios["convergence"].append(min(o[0] for o in other) / value(best[5]))
        errors = [o[1] for o in other if o[1] is not None]
        if errors and value(best[6]) is not None:
            ratios["error"].append(min(errors) / value(best[6]))
decision = next((line for line in body.splitlines() if line.startswith("Claim 2 (no need")), "")
if ratios["convergence"]:
    for which, words in (("error", "the paper's time to the fixed error"),
                         ("convergence", "its time to convergence")):
        low, high = min(ratios[which]), max(ratios[which])
        said = re.search(r"([0-9.]+)x(?: to ([0-9.]+)x)? " + re.escape(words), decision)
        check(said, f"claim 2's decision gives no ratio to {which}: {decision[:200]}")
        if said:
            # The tables print times to 0.1 s: the ratios from them are checked to 2 %.
            got_low, got_high = float(said.group(1)), float(said.group(2) or said.group(1))
            check(abs(got_low - low) <= 0.02 * low + 0.01 and abs(got_high - high) <= 0.02 * high + 0.01,
                  f"claim 2 to {which}: the sentence says {got_low} to {got_high}, the tables "
                  f"give {low:.2f} to {high:.2f}")

if failures:
    print("\n".join(failures))
    sys.exit(1)
print(f"claims sentences: {len(rows)} decision rows of analysis/claims.md checked")
