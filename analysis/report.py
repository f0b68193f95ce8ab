#!/usr/bin/python3
"""Compares the simulated sweeps with the paper's five tables: writes analysis/report.md and the
PNG figures under analysis/figures/.

usage: python3 analysis/report.py [--results DIR] [--partial] [--out-dir DIR]

Without a result for every cell of the paper sweeps it refuses in one line, writing nothing
(ncube.page); --partial writes the report anyway, with the missing cells "not run", into
--out-dir (report.md and figures/ there; the committed page in analysis/ is written only by a
complete run).

Inputs: analysis/paper_tables.json (the paper's tables), the paper sweeps as run into DIR
(DIR/plan.json, else experiments/*.json), their result files, platforms/*.json (fitted
parameters), analysis/calibration.json (optional: the cells the fit used). The output depends
only on these inputs (no dates, sorted iteration everywhere), so the same results give the same
report. The parts: ncube.paper.cells (inputs), ncube.paper.sections (text),
ncube.findings (F1-F6), ncube.paper.figures; every sweep's own CSV and plots come from
experiments/sweep (ncube.summary)."""

from ncube.interpreter import use_project_python  # noqa: E402

use_project_python()   # Debian's /usr/bin/python3 (README.md, "Use")

import argparse
from pathlib import Path

from ncube.paper import figures  # noqa: E402
from ncube.paper.cells import load_inputs  # noqa: E402
from ncube.paper.sections import (findings_section, header_section, headline_section,  # noqa: E402
                                  summary_section, tables_section)
from ncube.paper.text import relative  # noqa: E402
from ncube.paths import ANALYSIS, ROOT  # noqa: E402
from ncube import opening as op  # noqa: E402
from ncube import page  # noqa: E402

REPORT = ANALYSIS / "report.md"
SCRIPT = "analysis/report.py"


def configuration(cell):
    """("R=8 V=7", 249.0) of a headline cell "R=8 V=7 249"; None for "–" (cells not run)."""
    if len(cell.split()) != 3:
        return None
    R, V, value = cell.split()
    return f"{R} {V}", op.number(value)


def opening(found):
    """The report's opening, from its own tables: the error, the findings, the paper's headline
    per scene (with where its best configuration differs) and what would flip scene2 back."""
    summary = op.table(found, "Summary", "median |error|")
    every = next(r for r in summary if r["cells"] == "all distinct cells")
    worlds = op.table(found, "Over the unknowns' worlds")
    over = next(k for k in worlds[0] if k.startswith("over "))
    error_span = worlds[0][over]
    findings = worlds[1:]
    verdict = "this report (the default world)"
    reproduced = [r["figure"] for r in findings if r[verdict] == "reproduced"]
    missed = [r["figure"] for r in findings if r[verdict] == "not reproduced"]
    unchecked = [r["figure"] for r in findings
                 if r[verdict] not in ("reproduced", "not reproduced")]
    counts = "; ".join(f"{r['figure']} {op.number(r[over]):.0f}" for r in findings)
    n_worlds = over.split()[1]
    sentences = [op.Sentence(
        f"The simulation gives the paper's section 5 times to a median |error| of "
        f"{every['median |error|']} over its {every['n']} distinct cells (90th percentile "
        f"{every['90th pct |error|']}, bias {every['bias']}: negative is faster than the nCube2)",
        f"the default world; over the {n_worlds} worlds of analysis/unknowns.md the median "
        f"|error| of its 40 cells lies between {error_span.replace(' – ', ' and ')} (5th to "
        "95th percentile)"),
        op.Sentence(
        f"{len(reproduced)} of the paper's {len(findings)} findings are reproduced "
        f"({', '.join(reproduced) or 'none'}), {len(missed)} not ({', '.join(missed) or 'none'})"
        + (f", {len(unchecked)} not checked ({', '.join(unchecked)})" if unchecked else ""),
        f"each decided by its stated thresholds in the default world; reproduced in how many of "
        f"the {n_worlds} worlds: {counts}")]
    rows = op.table(found, "The paper's headline", "simulation: holds")
    by_scene = {r["scene"]: r for r in rows}
    agreeing, undecided = [], []
    for scene in ("scene2", "scene0", "scene1", "scene3"):
        r = by_scene[scene]
        paper_v = configuration(r["paper: fastest with V > 0"])
        paper_n = configuration(r["paper: fastest naive"])
        sim_v = configuration(r["simulation: fastest with V > 0"])
        sim_n = configuration(r["simulation: fastest naive"])
        if None in (paper_v, paper_n, sim_v, sim_n):
            undecided.append(scene)
            continue
        paper_holds, sim_holds = r["paper: holds"] == "yes", r["simulation: holds"] == "yes"
        unit = "s per iteration" if r["table"] == "4" else "s to convergence"
        paper_best = paper_v if paper_holds else paper_n
        sim_best = sim_v if sim_holds else sim_n
        worlds_text = f"it holds in {r['worlds where it holds']} worlds"
        if paper_holds != sim_holds:
            sim_order = (sim_v, sim_n) if sim_holds else (sim_n, sim_v)
            paper_order = (paper_v, paper_n) if paper_holds else (paper_n, paper_v)
            sentences.append(op.Sentence(
                f"The paper's headline, that a configuration with visibility processors beats the "
                f"naive parallelisation (V = 0), {'holds' if sim_holds else 'flips'} on {scene} "
                f"(Table {r['table']}): the simulation's best is {sim_order[0][0]} "
                f"{sim_order[0][1]:g} {unit} against {sim_order[1][0]} {sim_order[1][1]:g}, where "
                f"the paper's best is {paper_order[0][0]} {paper_order[0][1]:g} against "
                f"{paper_order[1][0]} {paper_order[1][1]:g}; F4 below compares only the "
                "configurations with visibility processors", worlds_text))
        elif paper_holds:
            differs = (f", with another best configuration than the paper's {paper_best[0]} "
                       f"({paper_v[1]:g} against {paper_n[1]:g} for {paper_n[0]})"
                       if sim_best[0] != paper_best[0] else "")
            sentences.append(op.Sentence(
                f"The headline holds on {scene} (Table {r['table']}): {sim_v[0]} "
                f"({sim_v[1]:g} {unit}) beats the naive {sim_n[0]} ({sim_n[1]:g}){differs}",
                worlds_text))
        else:
            agreeing.append((scene, r, sim_best, paper_best, worlds_text))
    if agreeing:
        sentences.append(op.Sentence(
            "On " + " and ".join(s for s, *_ in agreeing) + " the naive parallelisation is "
            "fastest in the paper's own Table 4 as in the simulation (" +
            "; ".join(f"{s}: {sim[0]} in both" if sim[0] == paper[0] else
                      f"{s}: {sim[0]}, the paper {paper[0]}" for s, _, sim, paper, _ in agreeing) +
            "), so the paper's conclusion rests on " +
            " and ".join(r["scene"] for r in rows if r["paper: holds"] == "yes"),
            "; ".join(f"{s}: {w}" for s, _, _, _, w in agreeing)))
    if undecided:
        sentences.append(op.Sentence(
            f"The paper's headline is not decided on {', '.join(undecided)}: cells of its "
            "table have no result (a partial report)", "not run"))
    if len(sentences) >= 6:
        return sentences
    try:
        needed = op.table(found, "What would flip scene2 back", "what would do it")
        orders = op.table(found, "What would flip scene2 back", "patch order")
        sizing = op.table(found, "What would flip scene2 back", "flip factor")
    except KeyError:
        return sentences
    flips = [r for r in sizing if not r["flip factor"].startswith("none")]
    none = [r["parameter"] for r in sizing if r not in flips]
    ratio_column = next(k for k in orders[0] if k.startswith("fastest V > 0 /"))
    closest = min(orders, key=lambda r: op.number(r[ratio_column]))
    parts = []
    if none:
        parts.append(f"no factor on the {', the '.join(none[:-1])}"
                     f"{' or the ' if len(none) > 1 else ''}{none[-1]} alone does it")
    parts += [f"the {r['parameter']} times {r['flip factor']} does" for r in flips]
    parts.append(f"it would take {needed[0]['how much']} more on the naive alone "
                 f"({needed[0]['against'].split(' of')[0]}) or {needed[1]['what would do it']} "
                 f"by {needed[1]['how much']}")
    sentences.append(op.Sentence(
        "For scene2 to flip back, " + "; ".join(parts) + f"; the patch order comes closest: "
        f"with a {closest['patch order']} order the fastest configuration with visibility "
        f"processors takes a median {closest[ratio_column].split()[0]} times the naive's time "
        f"and is ahead in {closest['holds']} of {closest['worlds']} worlds",
        "the factors from what-if runs of the Table 4 configurations with the model unchanged "
        "(analysis/headline.py), each configuration's time affine in the factor" +
        "".join(f"; {r['parameter']} checked {r['check past it'].split(' (')[0]} and "
                f"{r['check short of it'].split(' (')[0]}" for r in flips) +
        f"; the patch orders over the {sum(op.number(r['worlds']) for r in orders):.0f} worlds"))
    return sentences
    flips = [r for r in sizing if op.number(r["flip factor"]) is not None and
             not r["flip factor"].startswith("none")]
    none = [r["parameter"] for r in sizing if r not in flips]
    sentences.append(op.Sentence(
        "For scene2 to flip back the model would need, one parameter at a time, " +
        "; or ".join(f"the {r['parameter']} times {r['flip factor']} ({r['overtaking R=64 V=0']} "
                     "overtaking R=64 V=0)" for r in flips) +
        (f"; no factor on the {' or the '.join(none)} does it" if none else ""),
        "what-if runs of its Table 4 configurations, the model unchanged; each factor checked "
        "10 % past it and 10 % short of it: " +
        "; ".join(f"{r['parameter']}: {r['check past it'].split(' (')[0]}, "
                  f"{r['check short of it'].split(' (')[0]}" for r in flips)))
    return sentences


@page.refusing_outputs("report.py")
def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--results", type=Path, default=ROOT / "results",
                        help="the results folder of experiments/reproduce (default: results/)")
    parser.add_argument("--partial", action="store_true",
                        help="write the report even when cells have no result (shown as not run; "
                             "then into --out-dir)")
    parser.add_argument("--out-dir", type=Path, default=ANALYSIS,
                        help="where report.md and figures/ go (default analysis/, the committed "
                             "report: a complete run only)")
    args = parser.parse_args()
    report = args.out_dir / "report.md"
    figures.FIGURES = args.out_dir / "figures"
    if args.out_dir.exists() and not args.out_dir.is_dir():
        page.refuse("report.py", f"--out-dir {args.out_dir}: not a folder")
    inputs = load_inputs(args.results.resolve())
    needed = sorted({c.key for c in inputs.cells if c.key} |
                    ({inputs.timeline.key} if inputs.timeline else set()))
    missing = sorted({c.key for c in inputs.cells if c.key and c.result is None} |
                     ({inputs.timeline.key} if inputs.timeline and inputs.timeline.result is None
                      else set()))
    if not args.partial:
        page.require_results("report.py", missing, len(needed), args.results,
                             "run experiments/reproduce first")
    # Its figures' names are the committed ones (analysis/figures/*.png): checked as a folder.
    page.check_outputs("report.py", [report], committed=[REPORT], complete=not missing,
                       how="give --out-dir")
    if missing and figures.FIGURES.resolve() == (ANALYSIS / "figures").resolve():
        page.refuse("report.py", "a page of an incomplete run would replace the committed "
                                 "figures in analysis/figures/: give --out-dir")
    findings_lines, findings = findings_section(inputs)
    lines = (header_section(inputs) + tables_section(inputs) + summary_section(inputs) +
             headline_section(inputs, findings) + findings_lines +
             figures.figures_section(inputs))
    body = "\n".join(lines).rstrip() + "\n"
    page.write(report, op.with_opening(body, opening(op.tables(body)), SCRIPT))
    print(f"wrote {relative(report)}: " + ", ".join(f"{f.name} {f.status}" for f in findings))


if __name__ == "__main__":
    main()
