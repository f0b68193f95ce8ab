#!/usr/bin/python3
"""Fits the free parameters of the cost model on the calibration cells (analysis/calibration.json).

The simulated seconds per iteration of the calibration cells are (nearly) affine in the fitted
flops parameters, so a few Newton steps with a finite-difference Jacobian solve
simulated(cell) = paper(cell) for all cells at once. The result is written into
platforms/cost_model.json (value and a "source" saying how it was obtained) and into
analysis/calibration-fit.json. Besides these fitted parameters, figures of the paper reach the
simulator only through the choices listed in analysis/model_choices.json (made after comparing
runs with the paper; the report lists both).

usage: analysis/calibrate.py [--dry-run] [--set OPTION=VALUE ...]
"""

from ncube.interpreter import use_project_python  # noqa: E402

use_project_python()   # Debian's /usr/bin/python3 (README.md, "Use")

import argparse
import json
import sys
import tempfile
from pathlib import Path

# numpy (0.1 s of CPU a start) is imported by the functions that use it: --help and refusals need none.

from ncube import page  # noqa: E402
from ncube import simulate as simulator
from ncube import sweep as sweeps
from ncube.paths import ANALYSIS, EXPERIMENTS, PLATFORMS

COST_MODEL = PLATFORMS / "cost_model.json"


def paper_value(tables, cell):
    table = next(t for t in tables["tables"] if t["table"] == cell["table"])
    row = next(r for r in table["rows"] if r["R"] == cell["R"] and r["V"] == cell["V"])
    return float(row[cell["scene"]])


def sweep_cell(cell):
    """The cell of the table's sweep (experiments/tableN.json): its options are the
    calibration run's."""
    sweep = sweeps.load(EXPERIMENTS / f"table{cell['table']}.json")
    return next(c for c in sweep.cells if (c.scene, c.R, c.V) == (cell["scene"], cell["R"], cell["V"]))


def write_cost_model(document, path):
    """Writes the cost model in its house style: one parameter per line."""
    lines = ["{", f'  "description": {json.dumps(document["description"])},', '  "parameters": {']
    items = list(document["parameters"].items())
    for k, (name, entry) in enumerate(items):
        comma = "," if k + 1 < len(items) else ""
        lines.append(f"    {json.dumps(name)}: {json.dumps(entry)}{comma}")
    lines += ["  }", "}"]
    path.write_text("\n".join(lines) + "\n")


def simulate(cell, values, document, workdir, changes):
    trial = json.loads(json.dumps(document))
    for name, value in values.items():
        trial["parameters"][name]["value"] = value
    model = Path(workdir) / "cost_model.json"
    write_cost_model(trial, model)
    spec = sweep_cell(cell)
    result = simulator.run(spec.scene_file, dict(spec.options, **changes), spec.platform_file,
                           model, spec.cfg, accept_out_of_memory=False, threads=0)
    return result["seconds_per_iteration"]   # the one definition (docs/reproduce.md)


@page.refusing_outputs("calibrate.py")
def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--dry-run", action="store_true", help="fit, but write nothing")
    parser.add_argument("--set", action="append", default=[], metavar="OPTION=VALUE",
                        help="a simulate option for the calibration runs (a what-if), as in a "
                             "sweep file: skip_facing_away=true, ray_test=first-blocker")
    args = parser.parse_args()
    page.will_run("calibrate.py", "the calibration cells of analysis/calibration.json itself "
                  "(a few runs per Newton step)")
    import numpy as np
    import yaml
    changes = {k: yaml.safe_load(v) for k, _, v in (item.partition("=") for item in args.set)}
    calibration = json.loads((ANALYSIS / "calibration.json").read_text())
    tables = json.loads((ANALYSIS / "paper_tables.json").read_text())
    document = json.loads(COST_MODEL.read_text())
    names, cells = calibration["parameters"], calibration["cells"]
    target = np.array([paper_value(tables, c) for c in cells])
    x = np.array([float(document["parameters"][n]["value"]) for n in names])

    def times(params, workdir):
        values = dict(zip(names, params))
        return np.array([simulate(c, values, document, workdir, changes) for c in cells])

    with tempfile.TemporaryDirectory() as workdir:
        y = times(x, workdir)
        for step in range(6):
            print(f"step {step}: " + ", ".join(f"{n}={v:.4g}" for n, v in zip(names, x)) +
                  " -> " + ", ".join(f"{t:.4g}" for t in y) + " (paper " +
                  ", ".join(f"{t:g}" for t in target) + ")", flush=True)
            if np.all(np.abs(y - target) <= 1e-4 * target):
                break
            jacobian = np.empty((len(cells), len(names)))
            for j in range(len(names)):
                probe = x.copy()
                probe[j] *= 1.05
                jacobian[:, j] = (times(probe, workdir) - y) / (probe[j] - x[j])
            x = np.maximum(np.linalg.solve(jacobian, target - y) + x, 1e-3)
            y = times(x, workdir)
    residual = (y - target) / target
    print("fitted: " + ", ".join(f"{n}={v:.6g}" for n, v in zip(names, x)) +
          "; relative residuals " + ", ".join(f"{r:+.2e}" for r in residual))
    if args.dry_run:
        return 0

    cell_text = "; ".join(f"Table {c['table']} {c['scene']} R={c['R']} V={c['V']} "
                          f"(paper {paper_value(tables, c):g} s per iteration)" for c in cells)
    for name, value in zip(names, x):
        entry = document["parameters"][name]
        entry["value"] = float(f"{value:.6g}")
        entry["source"] = (f"fitted by analysis/calibrate.py so that the simulation matches {cell_text}; "
                           "every other cell of analysis/report.md is a prediction")
    write_cost_model(document, COST_MODEL)
    fit = {"parameters": {n: float(f"{v:.6g}") for n, v in zip(names, x)},
           "cells": [dict(c, paper=paper_value(tables, c), simulated=float(f"{t:.6g}"))
                     for c, t in zip(cells, y)]}
    page.write(ANALYSIS / "calibration-fit.json", json.dumps(fit, indent=1) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
