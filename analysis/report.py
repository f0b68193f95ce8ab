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
from ncube.paper.sections import (findings_section, header_section, summary_section,  # noqa: E402
                                  tables_section)
from ncube.paper.text import relative  # noqa: E402
from ncube.paths import ANALYSIS, ROOT  # noqa: E402
from ncube import page  # noqa: E402

REPORT = ANALYSIS / "report.md"


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
             findings_lines + figures.figures_section(inputs))
    page.write(report, "\n".join(lines).rstrip() + "\n")
    print(f"wrote {relative(report)}: " + ", ".join(f"{f.name} {f.status}" for f in findings))


if __name__ == "__main__":
    main()
