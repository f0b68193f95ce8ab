"""A sweep's summary: sweeps/<name>/cells.csv (one row per cell), the answer (summary.csv and
summary.md: the cells of each series sorted by the measure, the best marked, the headline
first; ncube.runner prints it at the end of a run) and the plots the sweep's shape calls for
(ncube.plotting: the measure per configuration when every cell has the same node count, else
time against R, speedup and efficiency; a per-node breakdown).

usage: python3 -m ncube.summary PLAN SWEEP_NAME     (in the results folder)

A cell's scene is its file: two files with the same scene name (cornell-box.json and a model
cornell-box.obj) are two scenes, told apart by scene_labels in the CSV, the legends and the
breakdown. Speedup and efficiency are relative to the cell with the fewest nodes that ran of the
same scene file and the same other options: speedup = t(reference) / t, efficiency = speedup x
nodes(reference) / nodes; none where those cells ran on one node count."""
import csv
import io
import json
import os
import sys
from pathlib import Path, PurePath

from . import options as opts
from . import input_file, output_file, paths, results, series
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
    reference, counts = {}, {}
    for cell, _ in loaded:
        if values[cell.id] is None:
            continue
        key = _others(cell)
        counts.setdefault(key, set()).add(cell.R * (cell.V + 1))
        best = reference.get(key)
        if best is None or cell.R * (cell.V + 1) < best.R * (best.V + 1):
            reference[key] = cell
    # Speedup and efficiency only mean something against fewer nodes: none for a series that
    # ran on one node count (every cell of a fixed-node sweep).
    reference = {key: cell for key, cell in reference.items() if len(counts[key]) > 1}
    labels = scene_labels(sweep.cells)
    table = []
    for cell, result in loaded:
        value = values[cell.id]
        ref = reference.get(_others(cell))
        speedup = efficiency = None
        if value and ref is not None:
            speedup = values[ref.id] / value
            efficiency = speedup * ref.R * (ref.V + 1) / (cell.R * (cell.V + 1))
        ref_nodes = ref.R * (ref.V + 1) if ref is not None else None
        row = {"sweep": sweep.name, "cell": cell.id, "scene": cell.scene,
               "scene_label": labels[cell.scene_file], "scene_file": shown_path(cell.scene_file),
               "R": cell.R,
               "V": cell.V, "nodes": cell.R * (cell.V + 1),
               "platform": os.path.basename(cell.platform_file),
               "cost_model": os.path.basename(cell.cost_model_file),
               "cfg": " ".join(f"{k}:{v}" for k, v in sorted(cell.cfg.items())),
               "trace": cell.trace, "status": result["status"] if result else "missing",
               "measure": sweep.measure, "value": value, "speedup": speedup,
               "efficiency": efficiency, "file": cell.file,
               "reference": (f"R={ref.R} V={ref.V}, {ref_nodes} node{'s' if ref_nodes > 1 else ''}"
                             if ref is not None else None)}
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


MEASURE_TEXT = {"seconds_per_iteration": "seconds per iteration",
                "total_seconds": "total simulated seconds"}


def fixed_nodes(table):
    """The node count R x (V + 1) of every cell when it is the same in all, else None."""
    nodes = {row["nodes"] for row in table}
    return nodes.pop() if len(nodes) == 1 else None


def plots(sweep, table, loaded, folder):
    """The plots the sweep's shape calls for (ncube.plotting): by_configuration.png when every
    cell has the same node count, else time_vs_R.png, speedup.png and efficiency.png; and
    node_breakdown.png."""
    from . import plotting
    folder.mkdir(parents=True, exist_ok=True)
    label = MEASURE_TEXT[sweep.measure]
    nodes = fixed_nodes(table)
    names = bar_names(table)
    if nodes is not None:
        written = [plotting.by_configuration(
            table, label, f"{sweep.name}: {label}, {nodes} nodes in every cell (R x (V + 1))",
            folder / "by_configuration.png")]
    else:
        written = [plotting.time_vs_R(table, label, folder / "time_vs_R.png"),
                   plotting.ratio_vs_nodes(table, "speedup", folder / "speedup.png"),
                   plotting.ratio_vs_nodes(table, "efficiency", folder / "efficiency.png")]
    written.append(plotting.node_breakdown(loaded, names, folder / "node_breakdown.png"))
    written = [w for w in written if w]
    for name in PLOTS:   # a plot of the other shape, or one with nothing to show, is stale
        if folder / name not in written:
            (folder / name).unlink(missing_ok=True)
    return written


PLOTS = ("by_configuration.png", "time_vs_R.png", "speedup.png", "efficiency.png",
         "node_breakdown.png")


def bar_names(table):
    """{cell id: the scene's label, every other key that varies, R and V}."""
    keys = series.varied(table, series.SERIES)
    return {row["cell"]: series.series_label(row, keys) + f" R={row['R']} V={row['V']}"
            for row in table}


# The answer: one row per cell, the cells of each series (every varied key but R and V) sorted
# by the measure, the best of each marked (summary.csv, summary.md and the terminal).
ANSWER_STATUS = {"ok": "ok", "out_of_memory": "out of memory", "missing": "failed"}


def answer(table):
    """(series keys, [row]): each row {series, R, V, nodes, status, value, ratio, best, file},
    the series in the order of the sweep's cells, within one the cells that ran by the measure,
    then those out of memory, then the failed; ratio is the value over the series' best."""
    keys = series.varied(table, series.SERIES)
    groups = {}
    for row in table:
        groups.setdefault(series.series_label(row, keys) if keys else "", []).append(row)
    order = {"ok": 0, "out_of_memory": 1}
    rows = []
    for name, members in groups.items():
        members = sorted(members, key=lambda r: (order.get(r["status"], 2),
                                                 r["value"] if r["value"] is not None else 0,
                                                 r["R"], r["V"]))
        best = members[0]["value"] if members and members[0]["value"] is not None else None
        for k, row in enumerate(members):
            value = row["value"]
            rows.append({"series": name, "R": row["R"], "V": row["V"], "nodes": row["nodes"],
                         "status": ANSWER_STATUS.get(row["status"], row["status"]),
                         "value": value,
                         "ratio": value / best if value is not None and best else None,
                         "best": k == 0 and value is not None, "file": row["file"],
                         "keys": {key: series.shown(key, row.get(key)) for key in keys}})
    return keys, rows


def _seconds(value):
    """Tenths from 100 s on, else four significant digits (a small scene's 0.6868 s)."""
    if value is None:
        return "-"
    return f"{value:.1f}" if value >= 100 else f"{value:.4g}"


def headline(sweep, table, keys, rows):
    """The sentences that answer the sweep's question: the fastest configuration of each
    series, the next one and by how much; whether the fastest is the same in every series."""
    label = MEASURE_TEXT[sweep.measure]
    iterations = {row.get("iterations") for row in table}
    nodes = fixed_nodes(table)
    shape = (f"{nodes} nodes in every cell" if nodes is not None
             else f"{min(r['nodes'] for r in table)} to {max(r['nodes'] for r in table)} nodes")
    count = iterations.pop() if len(iterations) == 1 else -1
    length = "" if count == -1 else f", {count} iteration{'s' if count != 1 else ''}"
    lines = [f"{sweep.name}: {label} (lower is better), {len(table)} cells, {shape}{length}."]
    winners = {}
    for name in dict.fromkeys(r["series"] for r in rows):
        members = [r for r in rows if r["series"] == name]
        ran = [r for r in members if r["value"] is not None]
        prefix = f"{name}: " if name else ""
        if not ran:
            lines.append(f"{prefix}no cell ran to the end.")
            continue
        best = ran[0]
        where = f"R={best['R']} V={best['V']}" + ("" if nodes is not None else
                                                  f" ({best['nodes']} nodes)")
        winners[name] = (best["R"], best["V"])
        text = f"{prefix}fastest {where}, {_seconds(best['value'])} s"
        if len(ran) > 1:
            text += (f"; next R={ran[1]['R']} V={ran[1]['V']}, {_seconds(ran[1]['value'])} s "
                     f"({ran[1]['ratio']:.2f}x the fastest)")
        others = [r for r in members if r["value"] is None]
        if others:
            text += "; " + ", ".join(f"R={r['R']} V={r['V']} {r['status']}" for r in others)
        lines.append(text + ".")
    if len(winners) > 1:
        same = len(set(winners.values())) == 1
        lines.append(("The same configuration is fastest for every " if same else
                      "The fastest configuration differs between the values of ")
                     + ", ".join(series.KEY_NAMES.get(k, k) for k in keys) + "."
                     + _one_factor(rows, winners))
    return lines


def _one_factor(rows, winners):
    """" cm5 takes 0.4997x to 0.5000x ncube2's time ...": when each series' values are within
    1 % of one factor times the first series' in every configuration both ran, the agreement of
    their orders is the model's (one speed factor) more than a finding: said so."""
    first, *others = list(winners)
    values = {(r["series"], r["R"], r["V"]): r["value"] for r in rows if r["value"] is not None}
    said = []
    for name in others:
        ratios = [values[(name, R, V)] / values[(first, R, V)] for (s, R, V) in values
                  if s == first and (name, R, V) in values]
        if len(ratios) < 2 or max(ratios) > min(ratios) * 1.01:
            return ""
        said.append(f"{name} takes {min(ratios):.4f}x to {max(ratios):.4f}x")
    return (" In every configuration that ran in both, " + ", ".join(said) + f" {first}'s time: "
            "nearly one factor, so the order of the configurations is nearly the same by "
            "construction.")


def answer_text(sweep, table):
    """The terminal's and summary.md's table, plain text, the headline first."""
    keys, rows = answer(table)
    columns = [*keys, "R", "V"] + ([] if fixed_nodes(table) is not None else ["nodes"]) + \
              ["status", MEASURE_TEXT[sweep.measure], "x best", ""]
    columns = [series.KEY_NAMES.get(c, c) for c in columns]
    body = []
    for row in rows:
        body.append([str(row["keys"][k]) for k in keys] + [str(row["R"]), str(row["V"])] +
                    ([] if fixed_nodes(table) is not None else [str(row["nodes"])]) +
                    [row["status"], _seconds(row["value"]),
                     "-" if row["ratio"] is None else f"{row['ratio']:.2f}",
                     "<- best" if row["best"] else ""])
    widths = [max(len(c), *(len(r[k]) for r in body)) for k, c in enumerate(columns)]
    numeric = {len(keys), len(keys) + 1, len(columns) - 3, len(columns) - 2} | \
              ({len(keys) + 2} if fixed_nodes(table) is None else set())

    def line(cells):
        return "  ".join(c.rjust(w) if k in numeric else c.ljust(w)
                         for k, (c, w) in enumerate(zip(cells, widths))).rstrip()

    return headline(sweep, table, keys, rows), [line(columns)] + [line(r) for r in body]


def write_answer(sweep, table, folder, figures):
    """summary.csv and summary.md beside cells.csv (through the output rule)."""
    keys, rows = answer(table)
    out = io.StringIO(newline="")
    writer = csv.writer(out)
    writer.writerow([series.KEY_NAMES.get(k, k) for k in keys] + ["R", "V", "nodes", "status", "measure", "value", "x_best", "best",
                     "file"])
    for row in rows:
        writer.writerow([row["keys"][k] for k in keys] +
                        [row["R"], row["V"], row["nodes"], row["status"], sweep.measure,
                         "" if row["value"] is None else row["value"],
                         "" if row["ratio"] is None else f"{row['ratio']:.4f}",
                         "best" if row["best"] else "", row["file"]])
    output_file.write(folder / "summary.csv", out.getvalue())
    lines, table_lines = answer_text(sweep, table)
    text = [f"# Sweep {sweep.name}", ""] + [" ".join(lines), ""]
    if sweep.description:
        text += [f"Question: {sweep.description}", ""]
    text += ["```"] + table_lines + ["```", "",
             "x best: the measure over the best of its series. Plots: "
             + ", ".join(f"[{f.name}]({f.name})" for f in figures) + "; every cell: "
             "[cells.csv](cells.csv).", ""]
    output_file.write(folder / "summary.md", "\n".join(text))
    return [folder / "summary.csv", folder / "summary.md"]


def conclude(sweep, results_dir, stream=None):
    """After a run: the answer on the terminal; and, when the sweep's table was not written
    (a cell failed), summary.csv, summary.md and the plots with the failed cells marked (the
    complete cells.csv comes only with every cell finished). Returns the files written."""
    folder = Path(results_dir) / "sweeps" / sweep.name
    table, loaded = rows(sweep, results_dir)
    written = []
    if not (folder / "cells.csv").exists() or not (folder / "summary.md").exists():
        figures = plots(sweep, table, loaded, folder)
        written = write_answer(sweep, table, folder, figures)
    lines, table_lines = answer_text(sweep, table)
    print("\n".join(["", *lines, "", *table_lines, ""]), file=stream or sys.stdout, flush=True)
    return written


def summarize(sweep, results_dir="."):
    folder = Path(results_dir) / "sweeps" / sweep.name
    folder.mkdir(parents=True, exist_ok=True)
    table, loaded = rows(sweep, results_dir)
    figures = plots(sweep, table, loaded, folder)
    write_answer(sweep, table, folder, figures)
    write_csv(table, folder / "cells.csv")   # last: its presence means the summary is done
    return folder / "cells.csv", figures


def main():
    plan, name = sys.argv[1], sys.argv[2]
    try:
        planned = input_file.read_json(plan, "sweep plan", input_file.SCENE_FILE_BYTES)
    except input_file.InputFileError as e:
        print(f"summary: {e}", file=sys.stderr)
        return 2
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
