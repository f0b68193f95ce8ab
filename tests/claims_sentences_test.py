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
gives the ratios its tables give. The opening: its claim-1 sentence is on each method's own
structure and its counts (holds, undecided, does not hold, intervals below 1) and ratio ranges
are the ones worked out here from the printed decision rows' intervals; the same for its
sentence on the total error against Cycles and its sentence at equal simulated time.

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
MARK = "Against the receiver-centred structure (not deciding): "
sentences = [line[len(MARK):] for line in body.splitlines() if line.startswith(MARK)]
check(len(sentences) == 1, "one sentence on the receiver-centred table in analysis/claims.md")
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

# ---- The opening against the decisions it rests on (worked out here from the printed rows).
opening = page.split("<!-- end of the opening -->", 1)[0]
said = {int(m.group(1)): m.group(2) for m in re.finditer(r"^(\d)\. (.*)$", opening, re.M)}
check(3 <= len(said) <= 6, f"the opening has {len(said)} sentences, not three to six")
own_row = re.compile(r"^\| (\S+) \| (\(b\) own structure, element|\(b\) own structure, patch|"
                     r"\(a\) patch vs Cycles) \| (centre|elements) N=(\d+) \| M=\d+: [^|]+ \| [^|]+ \| "
                     r"([0-9.]+) \[([0-9.]+), ([0-9.]+|∞)\] \| ([a-z ]+) \|$")
own = [m.groups() for m in map(own_row.match, body.splitlines()) if m]
check(own, "the decisions against each method's own structure")


def interval_of(r):
    return float(r[4]), float(r[5]), float("inf") if r[6] == "∞" else float(r[6])


for r in own:
    ratio, low, high = interval_of(r)
    if min(abs(ratio - T), abs(low - T), abs(high - T)) > 0.005:
        check(r[7] == claim_one.verdict(ratio, low, high),
              f"own structure {r[:4]}: says '{r[7]}' of {ratio} [{low}, {high}]")


def counts_said(text, rows):
    """The sentence's "holds in H of N, is undecided in U, does not hold in D" and its count of
    intervals below 1 against the rows' verdicts worked out from their intervals."""
    verdicts = [claim_one.verdict(*interval_of(r)) for r in rows]
    below = sum(1 for r in rows if interval_of(r)[2] < 1)
    expected = (f"holds in {verdicts.count('holds')} of {len(rows)}, is undecided in "
                f"{verdicts.count('undecided')}, does not hold in {verdicts.count('does not hold')}")
    check(expected in text, f"opening: '{expected}' not in: {text[:300]}")
    if below:
        check(f"interval below 1, in {below})" in text, f"opening: {below} below 1 not in: {text[:300]}")
    else:
        check("interval below 1" not in text, f"opening: intervals below 1 said, none in the rows")


def ratio_span_said(text, rows, placement, words):
    values = [interval_of(r)[0] for r in rows if r[2] == placement]
    if not values:
        return
    low, high = min(values), max(values)
    m = re.search(re.escape(words) + r" ([0-9.]+)x(?: to ([0-9.]+)x)?", text)
    check(m, f"opening: no ratio {words}: {text[:300]}")
    if m:
        got_low, got_high = float(m.group(1)), float(m.group(2) or m.group(1))
        check(abs(got_low - low) < 0.006 and abs(got_high - high) < 0.006,
              f"opening {words}: {got_low} to {got_high}, the rows {low} to {high}")


b_rows = [r for r in own if r[1].startswith("(b)")]
a_rows = [r for r in own if r[1].startswith("(a)")]
first = next((t for t in said.values() if t.startswith("Claim 1")), "")
check("its own structure" in first, f"the opening's claim 1 is not on the own structure: {first[:200]}")
if b_rows and first:
    counts_said(first.split("; the hemicube's (b)")[0], b_rows)
    ratio_span_said(first, b_rows, "centre", "the hemicube's (b) is")
    ratio_span_said(first, b_rows, "elements", "method's at the shooter's centre and")
user = next((t for t in said.values() if t.startswith("What a user sees")), "")
if a_rows:
    check(user, "the opening says nothing of the total error against Cycles")
    counts_said(user.split("\"much more accurate\"")[-1], a_rows)
    ratio_span_said(user, a_rows, "centre", "the hemicube at the shooter's centre is")
    ratio_span_said(user, a_rows, "elements", "from each shooter element")


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


# The opening's sentence at equal simulated time against that table (its judged rows).
equal_rows = [r for r in table_after(body, "**At equal cost**") if r[-1] != "—"]
equal_said = next((t for t in said.values() if t.startswith("At equal simulated time")), "")
if equal_rows:
    check(equal_said, "the opening says nothing at equal simulated time")
    parsed = [re.match(r"([0-9.]+) \[([0-9.]+), ([0-9.]+|∞)\]", r[6]).groups() for r in equal_rows]
    counts_said(equal_said, [(None,) * 4 + p for p in parsed])

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
