#!/usr/bin/python3
"""Compares the simulated sweeps with the paper's five tables: writes analysis/report.md and the
PNG figures under analysis/figures/.

usage: python3 analysis/report.py [--results DIR]

Inputs: analysis/paper_tables.json (the paper's tables), the paper sweeps as run into DIR
(DIR/plan.json, else experiments/*.json), their result files, platforms/*.json (fitted
parameters), analysis/calibration.json (optional: the cells the fit used). The output depends
only on these inputs (no dates, sorted iteration everywhere), so the same results give the same
report. The parts: ncube.paper.cells (inputs), ncube.paper.sections (text),
ncube.findings (F1-F6), ncube.paper.figures; every sweep's own CSV and plots come from
experiments/sweep (ncube.summary)."""
import argparse
import os
import sys
from pathlib import Path

if sys.executable != "/usr/bin/python3" and Path("/usr/bin/python3").exists():
    os.execv("/usr/bin/python3", ["/usr/bin/python3"] + sys.argv)  # Debian's, with matplotlib

from ncube.paper import figures  # noqa: E402
from ncube.paper.cells import load_inputs  # noqa: E402
from ncube.paper.sections import (findings_section, header_section, summary_section,  # noqa: E402
                                  tables_section)
from ncube.paper.text import relative  # noqa: E402
from ncube.paths import ANALYSIS, ROOT  # noqa: E402

REPORT = ANALYSIS / "report.md"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--results", type=Path, default=ROOT / "results",
                        help="the results folder of experiments/reproduce (default: results/)")
    args = parser.parse_args()
    figures.FIGURES = ANALYSIS / "figures"
    inputs = load_inputs(args.results.resolve())
    findings_lines, findings = findings_section(inputs)
    lines = (header_section(inputs) + tables_section(inputs) + summary_section(inputs) +
             findings_lines + figures.figures_section(inputs))
    REPORT.write_text("\n".join(lines).rstrip() + "\n")
    print(f"wrote {relative(REPORT)}: " + ", ".join(f"{f.name} {f.status}" for f in findings))


if __name__ == "__main__":
    main()
