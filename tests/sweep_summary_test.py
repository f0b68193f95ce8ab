#!/usr/bin/python3
"""A sweep answers its question (docs/sweeps.md, "The answer"): two small sweeps through the real
Snakemake, their printed tables, summary.csv and plots checked against the result files read
here on their own.

* a fixed node count (scene2, R x (V + 1) = 4, the nCube2 and the CM-5, 1 iteration): one row
  per cell, each platform's cells sorted by the measure and its fastest marked; R=1 V=3 out of
  memory on the nCube2 (scene2 needs more than one node's 4 MB: docs/model.md) listed as such;
  by_configuration.png and node_breakdown.png only (no speedup against a cell of the same node
  count); two series of distinct colours and markers, joined by lines, the out-of-memory cell
  marked, the legend outside the axes; cell files named with the platform, and results under
  the earlier names (without it) renamed, not run again;
* a varying node count (scene2, R = 1, 2, 4, 8, V = 0; R=1 out of memory, R=8 failed by a
  wrapper of ./simulate): time_vs_R, speedup and efficiency against R=2, the smallest node
  count that ran, named in the legend; the failed cell in the table and the plot; the progress
  line and Snakemake's log instead of its messages.

Two Snakemake runs into one results folder. First the fixed sweep alone, --verbose, over a folder
of the earlier naming: its three CM-5 cells' results made beforehand under the earlier names (by
the cell job's own function, ncube.run_cell.run, in this process), renamed by the run and not
run again, its three nCube2 cells run. Then both sweeps in one command (the sweep tool takes
several sweep files): the fixed sweep's cells all done, the varying sweep's run, each sweep
checked on its own cells."""
import json
import os
import signal
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "analysis"))
from ncube import plotting, run_cell, summary  # noqa: E402
from ncube.sweep import Sweep, load  # noqa: E402

SWEEP = [str(ROOT / "experiments" / "sweep")]
SIMULATE = os.path.abspath(os.environ["NCUBE_SIMULATE"])
failures = []


def check(condition, what):
    print(("ok   " if condition else "FAIL ") + what, flush=True)
    if not condition:
        failures.append(what)


def run_sweep(*args, env=None):
    return subprocess.run(SWEEP + [str(a) for a in args], capture_output=True, text=True,
                          timeout=240, env=env)


def figures(results_dir, sweep_file):
    """{file: (platform stem, R, V, status, seconds per iteration or None)} of every result of
    the sweep's cells."""
    found = {}
    own = {cell.file for cell in load(sweep_file).cells}
    for path in sorted((results_dir / "cells").glob("*.json")):
        if f"cells/{path.name}" not in own:
            continue
        result = json.loads(path.read_text())
        platform = Path(result["provenance"]["platform"]["file"]).stem
        found[f"cells/{path.name}"] = (platform, result["config"]["R"], result["config"]["V"],
                                       result["status"], result.get("seconds_per_iteration")
                                       if result["status"] == "ok" else None)
    return found


def drawn_plots(results_dir, name, work):
    """The sweep's plots drawn again here, each (file name, figure): the same bytes as the
    sweep's (checked), so what is inspected is what the user sees."""
    plan = json.loads((results_dir / "plan.json").read_text())
    sweep = Sweep.from_dict(next(s for s in plan["sweeps"] if s["name"] == name))
    drawn = []
    save = plotting.save

    def keep(fig, path):
        drawn.append((Path(path).name, fig))
        picture = save(fig, path)
        return picture

    plotting.save = keep
    try:
        table, loaded = summary.rows(sweep, results_dir)
        summary.plots(sweep, table, loaded, work / name)
    finally:
        plotting.save = save
    for file, _ in drawn:
        check((work / name / file).read_bytes() ==
              (results_dir / "sweeps" / name / file).read_bytes(),
              f"{name}: {file} drawn here is the sweep's, byte for byte")
    return dict(drawn)


def series_lines(axes):
    """The lines of the data series (those in the legend; not the 'linear' guide)."""
    return [line for line in axes.get_lines()
            if not line.get_label().startswith("_") and line.get_label() != "linear"]


def distinct_styles(name, axes):
    lines = series_lines(axes)
    colours = [tuple(round(c, 3) for c in __import__("matplotlib").colors.to_rgba(line.get_color()))
               for line in lines]
    markers = [line.get_marker() for line in lines]
    check(len(set(colours)) == len(lines) and len(set(markers)) == len(lines) and
          all(line.get_linestyle() == "-" for line in lines),
          f"{name}: {len(lines)} series, each its own colour and marker, joined by lines "
          f"({markers})")
    figure = axes.figure
    figure.canvas.draw()
    legend = axes.get_legend().get_window_extent()
    check(legend.x0 >= axes.get_window_extent().x1,
          f"{name}: the legend is outside the axes, right of them")


def write_sweeps(work):
    (work / "fixed.yaml").write_text(
        "description: on 4 nodes, which R/V split is fastest for scene2, and on the CM-5?\n"
        "options: {scene: scene2, iterations: 1}\n"
        "grid:\n  platform: [ncube2, cm5]\n"
        "  split: [{R: 1, V: 3}, {R: 2, V: 1}, {R: 4, V: 0}]\n")
    (work / "varying.yaml").write_text(
        "options: {scene: scene2, iterations: 1}\ngrid: {R: [1, 2, 4, 8], V: [0]}\n")
    wrapper = work / "simulate-fails-R8"
    wrapper.write_text(f'#!/bin/sh\ncase " $* " in *" --R 8 "*) echo "simulate: broken for the '
                       f'test" >&2; exit 4;; esac\nexec {SIMULATE} "$@"\n')
    wrapper.chmod(0o755)


def run_both(work):
    """The two sweeps in one command (the varying one's R=8 failed by a wrapper of ./simulate)."""
    return run_sweep(work / "fixed.yaml", work / "varying.yaml", "--results", work / "res",
                     env=dict(os.environ, NCUBE_SIMULATE=str(work / "simulate-fails-R8")))


def test_fixed_nodes(work, done):
    results_dir = work / "res"
    check((results_dir / "sweeps" / "fixed" / "cells.csv").exists(),
          f"the fixed-node sweep runs to its complete table ({done.returncode}: "
          f"{done.stderr[-300:]})")
    if not (results_dir / "sweeps" / "fixed" / "cells.csv").exists():
        return
    found = figures(results_dir, work / "fixed.yaml")
    check(len(found) == 6 and sum(f.endswith(f"-cm5-{f[-17:-5]}.json") for f in found) == 3 and
          all("-cm5-" not in f for f, v in found.items() if v[0] == "ncube2"),
          f"cell files are named with the platform when it is not the default ({sorted(found)})")
    oom = [f for f, v in found.items() if v[3] == "out_of_memory"]
    check([found[f][:3] for f in oom] == [("ncube2", 1, 3)],
          f"scene2 at R=1 runs out of memory on the nCube2 only ({oom})")
    # The printed answer: per platform, the cells that ran by their time, the fastest marked.
    lines = done.stdout.splitlines()
    header = next((k for k, line in enumerate(lines) if line.startswith("platform ")), None)
    check(header is not None, "a table with a platform column is printed")
    if header is None:
        return
    rows = [line.split() for line in lines[header + 1:header + 7]]
    for platform in ("ncube2", "cm5"):
        ran = sorted((v[4], v[1], v[2]) for v in found.values()
                     if v[0] == platform and v[4] is not None)
        printed = [r for r in rows if r[0] == platform]
        order = [(int(r[1]), int(r[2])) for r in printed if r[3] == "ok"]
        check(order == [(R, V) for _, R, V in ran],
              f"{platform}: the cells that ran, fastest first ({order})")
        best = [r for r in printed if r[-1] == "best"]
        check(len(best) == 1 and (int(best[0][1]), int(best[0][2])) == ran[0][1:] and
              abs(float(best[0][4]) - ran[0][0]) <= max(0.051, ran[0][0] * 5e-4),
              f"{platform}: the fastest marked, {ran[0][1:]} at {ran[0][0]:.1f} s ({best})")
        check(f"platform=ncube2: fastest R={ran[0][1]} V={ran[0][2]}" in done.stdout
              if platform == "ncube2" else
              f"platform=cm5: fastest R={ran[0][1]} V={ran[0][2]}" in done.stdout,
              f"{platform}: the headline names its fastest split")
    check(["ncube2", "1", "3", "out", "of", "memory", "-", "-"] in rows,
          "the out-of-memory cell is a row with its status and no time")
    check(lines.index(next(line for line in lines if line.startswith("fixed: "))) < header,
          "the headline comes before the table")
    # summary.csv: the same rows and marks.
    import csv
    table = list(csv.DictReader((results_dir / "sweeps" / "fixed" / "summary.csv").open()))
    check(len(table) == 6 and [r["best"] for r in table].count("best") == 2 and
          {(r["platform"], r["R"], r["status"]) for r in table if not r["value"]} ==
          {("ncube2", "1", "out of memory")},
          "summary.csv: six rows, two best, the out-of-memory cell without a value")
    folder = results_dir / "sweeps" / "fixed"
    present = sorted(p.name for p in folder.glob("*.png"))
    check(present == ["by_configuration.png", "node_breakdown.png"],
          f"a fixed node count: the measure per configuration and the breakdown only ({present})")
    check((folder / "summary.md").read_text().startswith("# Sweep fixed\n\nfixed: seconds per "
                                                        "iteration"),
          "summary.md opens with the answer")
    drawn = drawn_plots(results_dir, "fixed", work)
    figure = drawn.get("by_configuration.png")
    if figure:
        axes = figure.axes[0]
        distinct_styles("by_configuration.png", axes)
        labels = sorted(line.get_label() for line in series_lines(axes))
        check(labels == ["platform=cm5", "platform=ncube2"], f"one series per platform ({labels})")
        marks = [t.get_text() for t in axes.texts]
        check(marks.count("out of memory") == 1 and
              any(line.get_label() == "_out of memory" for line in axes.get_lines()),
              f"the out-of-memory cell is marked on the plot ({marks})")
        check(axes.get_title().endswith("4 nodes in every cell (R x (V + 1))"),
              f"the plot names the node count ({axes.get_title()})")
    breakdown = drawn.get("node_breakdown.png")
    if breakdown:
        ticks = [t.get_text() for t in breakdown.axes[0].get_yticklabels()]
        check(len(ticks) == len(set(ticks)) and all(t.startswith("platform=") for t in ticks),
              f"node_breakdown names each bar with its platform, no two alike ({ticks[:2]})")


def test_earlier_names(work):
    """A results folder of the earlier naming (<scene>-R<R>-V<V>-<id>.json) goes on: its
    results are renamed, not run again (docs/sweeps.md, "A cell's identity"). The CM-5 cells'
    results are made here as their jobs would make them (ncube.run_cell.run) and given the
    earlier names; the fixed sweep is then run with --verbose."""
    results_dir = work / "res"
    cm5 = [c for c in load(work / "fixed.yaml").cells if "-cm5-" in c.file]
    handlers = {s: signal.getsignal(s) for s in (signal.SIGTERM, signal.SIGINT)}
    codes = [run_cell.run(c, results_dir) for c in cm5]
    for number, handler in handlers.items():   # run_cell.run sets its own, for its job
        signal.signal(number, handler)
    renamed = {}
    for cell in cm5:
        path = results_dir / cell.file
        legacy = path.with_name(path.name.replace("-cm5-", "-"))
        renamed[path] = path.read_bytes()
        path.rename(legacy)
    check(codes == [0, 0, 0], f"the CM-5 cells' results made under the earlier names ({codes})")
    done = run_sweep(work / "fixed.yaml", "--results", results_dir, "--verbose")
    check("Building DAG" in done.stderr and "cells done" not in done.stdout,
          "--verbose: Snakemake's messages instead of the progress line")
    log = results_dir / "logs" / "snakemake.log"
    log = log.read_text() if log.exists() else ""
    check(len(renamed) == 3 and done.returncode == 0 and
          "3 with a finished result file" in done.stdout and "3 to run" in done.stdout and
          "3 result file(s) of an earlier naming renamed" in done.stderr and
          all(p.exists() and p.read_bytes() == b for p, b in renamed.items()) and
          not any(p.with_name(p.name.replace("-cm5-", "-")).exists() for p in renamed) and
          not any(f"output: {c.file}" in log for c in cm5) and log.count("rule cell:") == 3,
          f"results under the earlier names are renamed, none runs again, the others run "
          f"({done.stdout.splitlines()[:1]})")


def test_varying_nodes(work, done):
    results_dir = work / "res"
    check(done.returncode == 4, f"a failed cell: exit 4 ({done.returncode})")
    # The terminal: a progress line, no Snakemake scheduling; all of it in the log.
    check("cells done" in done.stdout and "Building DAG" not in done.stdout + done.stderr and
          "simulate: broken for the test" in done.stderr,
          "the terminal shows the progress and the failed cell's message, not Snakemake's")
    log = results_dir / "logs" / "snakemake.log"
    check(log.exists() and "Building DAG" in log.read_text(), "Snakemake's output is in its log")
    found = figures(results_dir, work / "varying.yaml")
    times = {v[1]: v[4] for v in found.values()}
    check(sorted(times) == [1, 2, 4] and times[1] is None and None not in (times[2], times[4]),
          f"R=1 out of memory, R=2 and R=4 ran, R=8 failed ({times})")
    rows = [line.split() for line in done.stdout.splitlines()]
    check(["8", "0", "8", "failed", "-", "-"] in rows and
          ["1", "0", "1", "out", "of", "memory", "-", "-"] in rows,
          "the table lists the failed and the out-of-memory cells")
    folder = results_dir / "sweeps" / "varying"
    present = sorted(p.name for p in folder.glob("*.png"))
    check(present == ["efficiency.png", "node_breakdown.png", "speedup.png", "time_vs_R.png"],
          f"a varying node count: time against R, speedup, efficiency, breakdown ({present})")
    check((folder / "summary.csv").exists() and not (folder / "cells.csv").exists(),
          "with a failed cell: the answer written, the complete table not")
    drawn = drawn_plots(results_dir, "varying", work)
    speedup = drawn.get("speedup.png")
    if speedup and times.get(2) and times.get(4):
        axes = speedup.axes[0]
        lines = series_lines(axes)
        check(len(lines) == 1 and lines[0].get_label() == "scene2 V=0 (against R=2 V=0, 2 nodes)",
              f"speedup against the smallest node count that ran, named ({lines[0].get_label()})")
        points = list(zip(lines[0].get_xdata(), lines[0].get_ydata()))
        check(len(points) == 2 and points[0] == (2, 1.0) and
              abs(points[1][1] - times[2] / times[4]) < 1e-12,
              f"speedup(4) = t(2) / t(4) = {times[2] / times[4]:.4f} ({points})")
    plot = drawn.get("time_vs_R.png")
    if plot:
        marks = sorted(t.get_text() for t in plot.axes[0].texts)
        check(marks == ["failed", "out of memory"], f"time_vs_R marks both cells ({marks})")
        distinct_styles("time_vs_R.png", plot.axes[0])


def test_messages():
    """Without --verbose only a failed cell's own message reaches the terminal, found where a
    job's line starts inside one of Snakemake's (one pipe, two writers); failed cells counted
    for the progress line."""
    import io
    from ncube import outcome
    stream = io.BytesIO(b"Building DAG of jobs...\nError in rule cell:run_cell: cells/x.json: "
                        b"simulate exited with 4:\nsimulate: broken\n  command: a b\n"
                        b"    jobid: 3\nError in rule traced_cell:\n")
    log, shown = io.BytesIO(), []
    messages = outcome.SnakemakeMessages(stream, log, False, shown.append)
    messages.wait()
    check(shown == ["run_cell: cells/x.json: simulate exited with 4:\n", "simulate: broken\n",
                    "  command: a b\n"] and messages.failed_cells == 2 and
          log.getvalue() == stream.getvalue(),
          f"the terminal gets the failed cell's message only, the log everything ({shown})")


def main():
    os.environ["NCUBE_SIMULATE"] = SIMULATE   # as the sweep hands it to its jobs: absolute
    test_messages()
    with tempfile.TemporaryDirectory(prefix="ncube-sweep-summary-test-") as folder:
        write_sweeps(Path(folder))
        test_earlier_names(Path(folder))   # first: it runs the fixed sweep alone
        done = run_both(Path(folder))
        test_fixed_nodes(Path(folder), done)
        test_varying_nodes(Path(folder), done)
    print(f"sweep_summary_test: {len(failures)} failure(s)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
