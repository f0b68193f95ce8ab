#!/usr/bin/python3
"""Fits the free parameters of the cost model on the calibration cells (analysis/calibration.json).

The simulated seconds per iteration of the calibration cells are (nearly) affine in the fitted
flops parameters, so a few Newton steps with a finite-difference Jacobian solve
simulated(cell) = paper(cell) for all cells at once. The result is written into
platforms/cost_model.json (value and a "source" saying how it was obtained) and into
analysis/calibration-fit.json. This is the only way figures of the paper reach the simulator.

usage: analysis/calibrate.py [--dry-run] [--simulate-args "..."]
"""
import argparse
import json
import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
COST_MODEL = ROOT / "platforms" / "cost_model.json"


def paper_value(tables, cell):
    table = next(t for t in tables["tables"] if t["table"] == cell["table"])
    row = next(r for r in table["rows"] if r["R"] == cell["R"] and r["V"] == cell["V"])
    return float(row[cell["scene"]])


def sweep_of(table_number):
    return json.loads((ROOT / "experiments" / f"table{table_number}.json").read_text())


def write_cost_model(document, path):
    """Writes the cost model in its house style: one parameter per line."""
    lines = ["{", f'  "description": {json.dumps(document["description"])},', '  "parameters": {']
    items = list(document["parameters"].items())
    for k, (name, entry) in enumerate(items):
        comma = "," if k + 1 < len(items) else ""
        lines.append(f"    {json.dumps(name)}: {json.dumps(entry)}{comma}")
    lines += ["  }", "}"]
    path.write_text("\n".join(lines) + "\n")


def simulate(cell, values, document, workdir, extra=()):
    trial = json.loads(json.dumps(document))
    for name, value in values.items():
        trial["parameters"][name]["value"] = value
    model = Path(workdir) / "cost_model.json"
    write_cost_model(trial, model)
    out = Path(workdir) / "cell.json"
    subprocess.run([str(ROOT / "simulate"), f"{cell['scene']}.json", "--R", str(cell["R"]),
                    "--V", str(cell["V"]), "--iterations", str(sweep_of(cell["table"])["iterations"]),
                    "--samples", str(sweep_of(cell["table"])["samples"]),
                    "--cost-model", str(model), "--json", str(out), "--quiet", *extra], check=True)
    result = json.loads(out.read_text())
    per_iteration = result["seconds_per_iteration"]
    return sum(per_iteration) / len(per_iteration)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--dry-run", action="store_true", help="fit, but write nothing")
    parser.add_argument("--simulate-args", default="",
                        help="more simulate options for the calibration runs (a what-if)")
    args = parser.parse_args()
    calibration = json.loads((ROOT / "analysis" / "calibration.json").read_text())
    tables = json.loads((ROOT / "analysis" / "paper_tables.json").read_text())
    document = json.loads(COST_MODEL.read_text())
    names, cells = calibration["parameters"], calibration["cells"]
    target = np.array([paper_value(tables, c) for c in cells])
    x = np.array([float(document["parameters"][n]["value"]) for n in names])

    def times(params, workdir):
        values = dict(zip(names, params))
        extra = args.simulate_args.split()
        return np.array([simulate(c, values, document, workdir, extra) for c in cells])

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
    (ROOT / "analysis" / "calibration-fit.json").write_text(json.dumps(fit, indent=1) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
