"""A sweep's summary: sweeps/<name>/cells.csv (one row per cell) and the usual plots (time
against R for each V, speedup, efficiency, a per-node breakdown), for any sweep.

usage: python3 -m ncube.summary PLAN SWEEP_NAME     (in the results folder)

A cell's scene is its file: two files with the same scene name (cornell-box.json and a model
cornell-box.obj) are two scenes, told apart by scene_labels in the CSV, the legends and the
breakdown. Speedup and efficiency are relative to the cell with the fewest nodes of the same
scene file and the same other options: speedup = t(reference) / t, efficiency = speedup x
nodes(reference) / nodes."""
import csv
import io
import json
import os
import sys
from pathlib import Path, PurePath

from . import options as opts
from . import output_file, paths, results
from .sweep import Sweep, protect_plan_inputs

COLUMNS = (["sweep", "cell", "scene", "scene_label", "scene_file", "R", "V", "nodes"] +
           [name for name in opts.OPTIONS if name not in ("R", "V")] +
           ["platform", "cost_model", "cfg", "trace", "status", "iterations_run", "converged",
            "measure", "value", "seconds_per_iteration", "simulated_seconds", "speedup",
            "efficiency", "host_seconds", "code_version", "file"])


def _distinguishing_end(file, files):
    """The fewest last components of `file`'s path that no other of `files` ends with (the
    whole path when it is the end of another)."""
    parts = PurePath(file).parts
    others = [PurePath(f).parts for f in files if f != file]
    for k in range(1, len(parts)):
        if all(other[-k:] != parts[-k:] for other in others):
            return "/".join(parts[-k:])
    return str(file)


def scene_labels(cells):
    """{scene file: label}, one label per file of the sweep: the scene's name when no other
    file of the sweep has that name, else the name and the shortest end of the file's path
    that tells it from the others: "cornell-box (cornell-box.json)", "cornell-box
    (models/cornell-box.obj)", "cornell-box (copy/cornell-box.obj)"."""
    names = {}
    for cell in cells:
        names.setdefault(cell.scene_file, cell.scene)
    sharing = {}
    for file, name in names.items():
        sharing.setdefault(name, []).append(file)
    labels = {file: name if len(sharing[name]) == 1 else
              f"{name} ({_distinguishing_end(file, sharing[name])})"
              for file, name in names.items()}
    if len(set(labels.values())) < len(labels):   # a scene named like another's label
        labels = {file: f"{name} ({file})" for file, name in names.items()}
    return labels


def shown_path(file):
    """A scene file as the CSV names it: relative to the repository when inside it."""
    path = Path(file)
    return str(path.relative_to(paths.ROOT)) if path.is_relative_to(paths.ROOT) else str(path)


def _others(cell):
    """What must match for two cells to be on one speedup curve: all but R and V. The scene is
    its file (and the files a model reads), not its name nor its content alone."""
    return json.dumps([cell.scene_file, cell.scene_sha256, cell.scene_parts_sha256,
                       cell.platform_sha256, cell.cost_model_sha256,
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
    labels = scene_labels(sweep.cells)
    table = []
    for cell, result in loaded:
        value = values[cell.id]
        ref = reference.get(_others(cell))
        speedup = efficiency = None
        if value and ref is not None:
            speedup = values[ref.id] / value
            efficiency = speedup * ref.R * (ref.V + 1) / (cell.R * (cell.V + 1))
        row = {"sweep": sweep.name, "cell": cell.id, "scene": cell.scene,
               "scene_label": labels[cell.scene_file], "scene_file": shown_path(cell.scene_file),
               "R": cell.R,
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
    labels = scene_labels(sweep.cells)
    folder.mkdir(parents=True, exist_ok=True)
    label = "seconds per iteration" if sweep.measure == "seconds_per_iteration" else "total simulated seconds"
    written = [plotting.time_vs_R(table, label, folder / "time_vs_R.png"),
               plotting.ratio_vs_nodes(table, "speedup", folder / "speedup.png"),
               plotting.ratio_vs_nodes(table, "efficiency", folder / "efficiency.png"),
               plotting.node_breakdown(loaded, labels, folder / "node_breakdown.png")]
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
    planned = json.loads(Path(plan).read_text())
    protect_plan_inputs(plan, planned)
    for document in planned["sweeps"]:
        if document["name"] == name:
            try:
                csv_path, figures = summarize(Sweep.from_dict(document))
            except OSError as e:   # a full disk: one line, the sweep says what to do
                print(f"summary: sweep {name}: {e.filename or 'its table and plots'} cannot be "
                      f"written: {e.strerror or e}", file=sys.stderr)
                return 5
            print(f"{name}: {csv_path} and {len(figures)} plots")
            return 0
    raise SystemExit(f"summary: no sweep {name!r} in {plan}")


if __name__ == "__main__":
    sys.exit(main())
