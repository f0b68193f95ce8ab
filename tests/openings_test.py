#!/usr/bin/env python3
"""Every results page opens with what it found, and no sentence of an opening says other than
its page's tables (analysis/ncube/opening.py, analysis/openings.py):

* the machinery: table cells with bars inside ("median |error|"), repeated headers, an opening
  put right under the title and replaced, not stacked, three to six sentences;
* every page of analysis/openings.PAGES has an opening right under its title, three to six
  sentences each with a figure and an italic "how sure", and it is the one its own tables give;
  a table figure changed (as by hand, or by a rerun whose page was not rewritten) makes its
  page fail that check;
* the paper's headline on the committed numbers, recomputed here without ncube.headline: from
  report.md's Tables 4 and 5, scene2 flips (R=64 V=0 ahead of every configuration with
  visibility processors, where the paper has R=8 V=7 ahead) and scene0 holds, with another best
  configuration than the paper's; from analysis/unknowns-worlds.json, the share of worlds the
  report gives; the opening says each;
* analysis/headline.json's "no positive factor flips it" follows from its own runs (each line
  with visibility processors above R=64 V=0's at a factor of zero and rising at least as fast);
* machines.md's opening says that the CM-5's same best split is built into the model, and the
  factor it gives is the one section 1's tables give. About 3 s.

usage: openings_test.py SOURCE_DIR"""
import json
import re
import sys
from pathlib import Path

root = Path(sys.argv[1])
sys.path.insert(0, str(root / "analysis"))
from ncube import opening as op  # noqa: E402
import openings  # noqa: E402

failures = []


def check(condition, what):
    if not condition:
        failures.append(what)


# --- The machinery.
check(op.cells("| median |error| | 13.1 % | |") == ["median |error|", "13.1 %", ""],
      f"bars inside a cell: {op.cells('| median |error| | 13.1 % | |')}")
page = ("# Title\n\nIntro.\n\n| a | still | still |\n|---|---|---|\n| x | 1 | 2 |\n\n"
        "**b, c**\n\n| R | V |\n|--:|--:|\n| 4 | 15 |\n")
found = op.tables(page)
check([label for label, _ in found] == ["", "b, c"], f"table labels: {found}")
check(found[0][1] == [{"a": "x", "still": "1", "still 2": "2"}], f"repeated header: {found[0]}")
three = [op.Sentence(f"figure {i}", "sure") for i in range(3)]
opened = op.with_opening(page, three, "analysis/x.py")
check(opened.split("\n")[2].startswith(op.HEADING), "the opening is right under the title")
check(op.with_opening(opened, three, "analysis/x.py") == opened, "an opening is replaced, not stacked")
check(op.sentences_of(opened) == ["figure 0. *sure.*", "figure 1. *sure.*", "figure 2. *sure.*"],
      f"sentences read back: {op.sentences_of(opened)}")
check(op.tables(opened) == found, "the opening's lines are not read as the page's tables")
for count in (2, 7):
    try:
        op.render([op.Sentence("x 1", "y")] * count, "s")
        failures.append(f"an opening of {count} sentences was accepted")
    except ValueError:
        pass

# --- Every page: an opening, each sentence with a figure and how sure, the one its tables give.
for name in openings.PAGES:
    path = root / "analysis" / name
    text = path.read_text()
    sentences = op.sentences_of(text)
    check(3 <= len(sentences) <= 6, f"{name}: {len(sentences)} opening sentences")
    check(text.split("\n")[2].startswith(op.HEADING), f"{name}: no opening right under its title")
    for s in sentences:
        check(re.search(r"\d", s.split(" *")[0]), f"{name}: a sentence without a figure: {s[:80]}")
        check(re.search(r"\. \*[^*]+\.\*$", s), f"{name}: a sentence without its italic how-sure: {s[:80]}")
    check(openings.reopened(path) == text,
          f"{name}: its opening is not what its tables give (analysis/openings.py rewrites it)")
    # Its script writes the same opening when it writes the whole page.
    source = (root / "analysis" / f"{openings.PAGES[name]}.py").read_text()
    check(re.search(r"op\.with_opening\(body, opening\(op\.tables\(body\)\)", source),
          f"analysis/{openings.PAGES[name]}.py does not open its page from its own tables")


def mutated(name, old, new):
    """The page with one table figure changed: its recomputed opening must differ."""
    path = root / "analysis" / name
    text = path.read_text()
    check(old in text, f"{name}: the figure to change is not in the page: {old!r}")
    changed = text.replace(old, new, 1)
    module = __import__(openings.PAGES[name])
    return op.with_opening(changed, module.opening(op.tables(changed)), "x") != \
        op.with_opening(text, module.opening(op.tables(text)), "x")


check(mutated("report.md", "R=64 V=0 198 | **no**", "R=64 V=0 298 | **no**"),
      "report.md: a changed headline figure does not change its opening")
check(mutated("unknowns.md", "| 13.9 % | 14.1 % | 13.1 % |", "| 13.9 % | 14.1 % | 15.1 % |"),
      "unknowns.md: a changed error does not change its opening")
check(mutated("machines.md", "| 64 | 0 | 198.2 |", "| 64 | 0 | 298.2 |"),
      "machines.md: a changed nCube2 time does not change its opening")
check(mutated("patch-order.md", "| 11.7 % |", "| 19.7 % |"),
      "patch-order.md: a changed error does not change its opening")
check(mutated("claims.md", "| 38.78 [20.04, 91.04] |", "| 28.78 [20.04, 91.04] |"),
      "claims.md: a changed ratio does not change its opening")

# --- The paper's headline, recomputed from report.md's tables and the paper's (no ncube.headline).
report = (root / "analysis" / "report.md").read_text()
paper = json.loads((root / "analysis" / "paper_tables.json").read_text())


def table_rows(number):
    """{(scene, R, V): simulated seconds} of report.md's Table <number> (None: no time)."""
    block = report.split(f"### Table {number}:")[1].split("\n## ")[0].split("\n### ")[0]
    rows = {}
    for line in block.splitlines():
        cells = [c.strip() for c in line.strip("|").split("|")]
        if len(cells) >= 6 and cells[1].isdigit() and cells[2].isdigit():
            value = re.match(r"^[\d,.]+$", cells[5])
            rows[(cells[0], int(cells[1]), int(cells[2]))] = \
                float(cells[5].replace(",", "")) if value else None
    return rows


def best(times, visibility):
    side = {rv: t for rv, t in times.items() if t is not None and
            (rv[1] > 0 if visibility else rv[1] == 0 and rv[0] > 1)}
    rv = min(side, key=side.get)
    return rv, side[rv]


table4, table5 = table_rows(4), table_rows(5)
sim2 = {(R, V): t for (s, R, V), t in table4.items() if s == "scene2"}
sim0 = {(R, V): t for (s, R, V), t in table5.items() if s == "scene0" and R > 1}
paper4 = next(t for t in paper["tables"] if t["table"] == 4)["rows"]
paper5 = next(t for t in paper["tables"] if t["table"] == 5)["rows"]
p2 = {(r["R"], r["V"]): r["scene2"] for r in paper4}
p0 = {(r["R"], r["V"]): r["scene0"] for r in paper5 if r["R"] > 1}
(v2, tv2), (n2, tn2) = best(sim2, True), best(sim2, False)
(pv2, ptv2), (pn2, ptn2) = best(p2, True), best(p2, False)
check(ptv2 < ptn2 and (pv2, pn2) == ((8, 7), (64, 0)), "the paper's scene2: R=8 V=7 ahead of R=64 V=0")
check(tn2 < tv2 and n2 == (64, 0), f"scene2 in the simulation: the naive ahead ({tn2} vs {tv2})")
(v0, tv0), (n0, tn0) = best(sim0, True), best(sim0, False)
(pv0, ptv0), (pn0, ptn0) = best(p0, True), best(p0, False)
check(tv0 < tn0, f"scene0 in the simulation: visibility processors ahead ({tv0} vs {tn0})")
check(ptv0 < ptn0 and pv0 == (8, 7), "the paper's scene0: R=8 V=7 ahead")
sentences = op.sentences_of(report)
flip = [s for s in sentences if "flips on scene2" in s]
check(len(flip) == 1 and f"R=64 V=0 {tn2:g}" in flip[0] and f"R=8 V=7 {tv2:g}" in flip[0],
      f"report.md's opening does not say scene2 flips with its figures ({tn2:g}, {tv2:g}): {flip}")
hold = [s for s in sentences if "holds on scene0" in s]
check(len(hold) == 1 and f"R={v0[0]} V={v0[1]} ({tv0:g}" in hold[0] and
      "another best configuration than the paper's R=8 V=7" in hold[0] and (v0 != pv0),
      f"report.md's opening does not say scene0 holds with another best configuration: {hold}")
check(not any("flips on scene0" in s or "holds on scene2" in s for s in sentences),
      "report.md's opening contradicts the tables on scene0 or scene2")

worlds = json.loads((root / "analysis" / "unknowns-worlds.json").read_text())["worlds"][1:]


def holds_in(world, scene, rows):
    times = {}
    for key, value in world["cells"].items():
        _, s, r, v = key.split()
        if s == scene and (int(r[2:]), int(v[2:])) in rows:
            times[(int(r[2:]), int(v[2:]))] = value
    return best(times, True)[1] < best(times, False)[1]


count2 = sum(holds_in(w, "scene2", set(sim2)) for w in worlds)
count0 = sum(holds_in(w, "scene0", set(sim0)) for w in worlds)
row2 = [line for line in report.splitlines() if line.startswith("| scene2 | 4 | R=")]
check(len(row2) == 1 and row2[0].startswith("| scene2 | 4 | R=8 V=7 222 | R=64 V=0 244 | yes |")
      and row2[0].endswith(f"| **no** | {count2} of {len(worlds)} |"),
      f"report.md's headline row for scene2 is not the paper's yes, the simulation's no in "
      f"{count2} of {len(worlds)} worlds: {row2}")
check(any(f"it holds in {count2} of {len(worlds)} worlds" in s for s in flip),
      f"report.md's opening does not give scene2's {count2} of {len(worlds)} worlds")
check(any(f"it holds in {count0} of {len(worlds)} worlds" in s for s in hold),
      f"report.md's opening does not give scene0's {count0} of {len(worlds)} worlds")

# --- headline.json: "no positive factor" follows from its own runs.
study = json.loads((root / "analysis" / "headline.json").read_text())
base, probe = study["committed"], study["probe_factor"]
for name, entry in study["parameters"].items():
    slope = {rv: (entry["at_probe"][rv] - base[rv]) / (probe - 1) for rv in base}
    lines = {rv: (base[rv] - slope[rv], slope[rv]) for rv in base}   # value at 0, slope
    naive = lines["R=64 V=0"]
    never = all(lines[rv][0] >= naive[0] and lines[rv][1] >= naive[1]
                for rv in lines if not rv.endswith("V=0"))
    if entry["flip_factor"] is None:
        check(never, f"headline.json: {name}: 'no factor flips it', but a line crosses")
    else:
        check(not never and entry["checks"]["past"]["holds"] and
              not entry["checks"]["short"]["holds"],
              f"headline.json: {name}: a flip factor its checks do not bear out")
    row = [line for line in report.splitlines() if line.startswith(f"| {name} |")]
    check(row and (("none" in row[0]) == (entry["flip_factor"] is None)),
          f"report.md's row for {name} is not headline.json's")

# --- machines.md: the CM-5's factor, from section 1's tables, and "built into the model".
machines = (root / "analysis" / "machines.md").read_text()
ratios = []
for label, rows in op.tables(machines):
    if "," in label and rows and "CM-5" in rows[0]:
        for r in rows:
            if not r["CM-5"].startswith("out") and not r["nCube2"].startswith("out"):
                ratios.append(float(r["nCube2"].replace(",", "")) / float(r["CM-5"].replace(",", "")))
first = op.sentences_of(machines)[0]
check(1.98 < min(ratios) and max(ratios) < 2.01, f"the CM-5's factor: {min(ratios)} to {max(ratios)}")
check(f"{min(ratios):.2f} to {max(ratios):.2f} times as fast" in first and
      "built into the model" in first and "CM-5" in first,
      f"machines.md's first sentence does not say the CM-5's factor is built into the model: {first}")

# --- README.md's "What it found": every figure of a line is in the openings of the pages that
# line links to.
readme = (root / "README.md").read_text()
found_block = readme.split("## What it found", 1)[1].split("\n## ", 1)[0]
bullets = re.split(r"\n\* ", found_block)[1:]
check(len(bullets) >= 5, f"README.md's 'What it found' has {len(bullets)} lines")
for bullet in bullets:
    linked = re.findall(r"`(analysis/[\w-]+\.md)`", bullet)
    check(linked, f"README.md: a finding without its page: {bullet[:60]}")
    # The figures a user reads first are the openings' (the README quotes them).
    pages_text = " ".join(" ".join(op.sentences_of((root / page).read_text())) for page in linked)
    page_numbers = set(re.findall(r"(?<![\w.])\d+(?:\.\d+)?(?![\w])", pages_text))
    for number in re.findall(r"(?<![\w.])\d+(?:\.\d+)?(?![\w])", bullet):
        check(number in page_numbers,
              f"README.md: {number} ({bullet[:50]}...) is not a figure of {', '.join(linked)}")

if failures:
    print("\n".join(f"FAIL: {f}" for f in failures))
    sys.exit(1)
print(f"openings: {len(openings.PAGES)} pages checked against their tables; scene2 flips "
      f"({tn2:g} vs {tv2:g}, holds in {count2} of {len(worlds)} worlds), scene0 holds "
      f"({tv0:g} vs {tn0:g}, {count0} of {len(worlds)})")
