"""A sweep's summary: sweeps/<name>/cells.csv (one row per cell) and the usual plots (time
against R for each V, speedup, efficiency, a per-node breakdown), for any sweep.

usage: python3 -m ncube.summary PLAN SWEEP_NAME     (in the results folder)

Speedup and efficiency are relative to the cell with the fewest nodes of the same scene and
the same other options: speedup = t(reference) / t, efficiency = speedup x nodes(reference)
/ nodes."""
import csv
import io
import json
import os
import sys
from pathlib import Path

from . import options as opts
from . import output_file, results
from .sweep import Sweep

COLUMNS = (["sweep", "cell", "scene", "R", "V", "nodes"] +
           [name for name in opts.OPTIONS if name not in ("R", "V")] +
           ["platform", "cost_model", "cfg", "trace", "status", "iterations_run", "converged",
            "measure", "value", "seconds_per_iteration", "simulated_seconds", "speedup",
            "efficiency", "host_seconds", "code_version", "file"])


def _others(cell):
    """What must match for two cells to be on one speedup curve: all but R and V."""
    return json.dumps([cell.scene_sha256, cell.platform_sha256, cell.cost_model_sha256,
                       {k: v for k, v in cell.options.items() if k not in ("R", "V")},
                       cell.cfg], sort_keys=True)


def rows(sweep, results_dir="."):
    loaded = [(cell, results.read(Path(results_dir) / cell.file)) for cell in sweep.cells]
    values = {cell.id: results.measure(result, sweep.measure) for cell, result in loaded}
    reference = {}
    for cell, _ in loaded:
        if values[cell.id] is None:
            continue
        key = _others(cell)
        best = reference.get(key)
        if best is None or cell.R * (cell.V + 1) < best.R * (best.V + 1):
            reference[key] = cell
    table = []
    for cell, result in loaded:
        value = values[cell.id]
        ref = reference.get(_others(cell))
        speedup = efficiency = None
        if value and ref is not None:
            speedup = values[ref.id] / value
            efficiency = speedup * ref.R * (ref.V + 1) / (cell.R * (cell.V + 1))
        row = {"sweep": sweep.name, "cell": cell.id, "scene": cell.scene, "R": cell.R,
               "V": cell.V, "nodes": cell.R * (cell.V + 1),
               "platform": os.path.basename(cell.platform_file),
               "cost_model": os.path.basename(cell.cost_model_file),
               "cfg": " ".join(f"{k}:{v}" for k, v in sorted(cell.cfg.items())),
               "trace": cell.trace, "status": result["status"] if result else "missing",
               "measure": sweep.measure, "value": value, "speedup": speedup,
               "efficiency": efficiency, "file": cell.file}
        row.update({k: v for k, v in cell.options.items() if k not in ("R", "V")})
        if result:
            row.update({"iterations_run": result["iterations"], "converged": result["converged"],
                        "seconds_per_iteration": result["seconds_per_iteration"],
                        "simulated_seconds": result["simulated_seconds"],
                        "host_seconds": result["host_seconds"],
                        "code_version": result["provenance"]["code_version"]})
        table.append(row)
    return table, loaded


def write_csv(table, path):
    out = io.StringIO(newline="")
    writer = csv.DictWriter(out, COLUMNS)
    writer.writeheader()
    for row in table:
        writer.writerow({k: ("" if row.get(k) is None else row.get(k)) for k in COLUMNS})
    output_file.write(path, out.getvalue())


def plots(sweep, table, loaded, folder):
    from . import plotting
    folder.mkdir(parents=True, exist_ok=True)
    label = "seconds per iteration" if sweep.measure == "seconds_per_iteration" else "total simulated seconds"
    written = [plotting.time_vs_R(table, label, folder / "time_vs_R.png"),
               plotting.ratio_vs_nodes(table, "speedup", folder / "speedup.png"),
               plotting.ratio_vs_nodes(table, "efficiency", folder / "efficiency.png"),
               plotting.node_breakdown(loaded, folder / "node_breakdown.png")]
    return [w for w in written if w]


def summarize(sweep, results_dir="."):
    folder = Path(results_dir) / "sweeps" / sweep.name
    folder.mkdir(parents=True, exist_ok=True)
    table, loaded = rows(sweep, results_dir)
    figures = plots(sweep, table, loaded, folder)
    write_csv(table, folder / "cells.csv")   # last: its presence means the summary is done
    return folder / "cells.csv", figures


def main():
    plan, name = sys.argv[1], sys.argv[2]
    for document in json.loads(Path(plan).read_text())["sweeps"]:
        if document["name"] == name:
            csv_path, figures = summarize(Sweep.from_dict(document))
            print(f"{name}: {csv_path} and {len(figures)} plots")
            return 0
    raise SystemExit(f"summary: no sweep {name!r} in {plan}")


if __name__ == "__main__":
    sys.exit(main())
