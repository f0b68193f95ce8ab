#!/usr/bin/python3
"""A sweep keeps its scene files apart (docs/sweeps.md, "A cell's scene is its file"): three
files named cornell-box (the scene file, the model in tests/models and a copy of the model
whose MTL differs, so the OBJ's content is the same) are three labels in cells.csv and in the
legends, three lines in every plot and three baselines for speedup and efficiency. The expected
figures come from the cells' result files alone (their provenance names the scene file)."""
import csv
import json
import subprocess
import sys
import tempfile
from pathlib import Path
from types import SimpleNamespace

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "analysis"))
from ncube import plotting, summary  # noqa: E402
from ncube.sweep import Sweep  # noqa: E402

MODEL = ROOT / "tests" / "models" / "cornell-box.obj"
failures = []


def check(condition, what):
    print(("ok   " if condition else "FAIL ") + what, flush=True)
    if not condition:
        failures.append(what)


def close(a, b):
    return a is not None and b is not None and abs(a - b) <= 1e-12 * max(abs(a), abs(b))


def test_labels():
    """The labels of files sharing a name, worked out by hand."""
    def cells(*pairs):
        return [SimpleNamespace(scene=name, scene_file=file) for name, file in pairs]

    cases = [
        (cells(("scene2", "/r/scenes/scene2.json"), ("room", "/r/a/room.json")),
         ["scene2", "room"]),
        (cells(("box", "/r/scenes/box.json"), ("box", "/r/models/box.obj"),
               ("box", "/t/copy/box.obj"), ("scene0", "/r/scenes/scene0.json")),
         ["box (box.json)", "box (models/box.obj)", "box (copy/box.obj)", "scene0"]),
        # A path that is the end of another's: the whole path tells it apart.
        (cells(("box", "/a/box.json"), ("box", "/x/a/box.json")),
         ["box (/a/box.json)", "box (x/a/box.json)"]),
        # A scene named like another's label: every file by its whole path.
        (cells(("box", "/s/box.json"), ("box", "/s/box.obj"), ("box (box.obj)", "/s/b.json")),
         ["box (/s/box.json)", "box (/s/box.obj)", "box (box.obj) (/s/b.json)"]),
    ]
    for given, expected in cases:
        labels = summary.scene_labels(given)
        got = [labels[c.scene_file] for c in given]
        check(got == expected, f"scene labels {got} (expected {expected})")


def expected_figures(results_dir):
    """{scene file: {R: (seconds per iteration, speedup, efficiency)}} from the result files:
    each file's reference is its cell with the fewest nodes."""
    by_file = {}
    for path in sorted((results_dir / "cells").glob("*.json")):
        result = json.loads(path.read_text())
        scene_file = result["provenance"]["scene"]["file"]
        nodes = result["config"]["R"] * (result["config"]["V"] + 1)
        by_file.setdefault(scene_file, {})[result["config"]["R"]] = (
            nodes, result["seconds_per_iteration"], f"cells/{path.name}")
    figures = {}
    for scene_file, cells in by_file.items():
        ref_nodes, ref_time, _ = min(cells.values())
        figures[scene_file] = {R: (t, ref_time / t, ref_time / t * ref_nodes / nodes, name)
                               for R, (nodes, t, name) in cells.items()}
    return figures


def test_sweep(work):
    copy = work / "copy"
    copy.mkdir()
    (copy / "cornell-box.obj").write_bytes(MODEL.read_bytes())
    # The copy's white walls glow too: another first shooter, so other times per iteration
    # (a shared baseline would show in its speedups).
    mtl = MODEL.with_suffix(".mtl").read_text()
    check("Kd 0.725 0.71 0.68\n" in mtl, "the model's MTL has the white the copy changes")
    (copy / "cornell-box.mtl").write_text(
        mtl.replace("Kd 0.725 0.71 0.68\n", "Kd 0.725 0.71 0.68\nKe 1 1 1\n"))
    (work / "files.yaml").write_text(
        "measure: seconds_per_iteration\noptions: {iterations: 1, samples: 4}\n"
        f"grid: {{scene: [cornell-box.json, {MODEL}, copy/cornell-box.obj], R: [1, 2]}}\n")
    results_dir = work / "res"
    done = subprocess.run([str(ROOT / "experiments" / "sweep"), str(work / "files.yaml"),
                           "--results", str(results_dir)], capture_output=True, text=True,
                          timeout=240)
    check(done.returncode == 0, "the sweep runs" + ("" if done.returncode == 0 else
                                                    f" ({done.stderr[-300:]})"))
    if done.returncode != 0:
        return
    expected = expected_figures(results_dir)
    files = {str(ROOT / "scenes" / "cornell-box.json"): "cornell-box (cornell-box.json)",
             str(MODEL): "cornell-box (models/cornell-box.obj)",
             str(copy / "cornell-box.obj"): "cornell-box (copy/cornell-box.obj)"}
    check(sorted(expected) == sorted(files) and all(sorted(e) == [1, 2] for e in expected.values()),
          f"the result files: R=1 and R=2 of each of the three files ({sorted(expected)})")
    if sorted(expected) != sorted(files):
        return
    times = {f: tuple(expected[f][R][0] for R in (1, 2)) for f in files}
    check(len(set(times.values())) == 3, f"the three files run in different times ({times})")

    # cells.csv: the scene name, the file and the label; speedup against the file's own R=1.
    rows = list(csv.DictReader((results_dir / "sweeps" / "files" / "cells.csv").open()))
    check(len(rows) == 6 and {r["scene"] for r in rows} == {"cornell-box"},
          "cells.csv: six cells of scenes named cornell-box")
    for row in rows:
        shown = Path(row["scene_file"])
        scene_file = str(shown if shown.is_absolute() else ROOT / shown)
        figures = expected.get(scene_file, {}).get(int(row["R"]))
        what = f"cells.csv {row['scene_label']} R={row['R']}"
        check(figures is not None and row["file"] == figures[3] and
              row["scene_label"] == files[scene_file], f"{what}: its file and label")
        if figures:
            check(close(float(row["value"]), figures[0]) and
                  close(float(row["speedup"]), figures[1]) and
                  close(float(row["efficiency"]), figures[2]),
                  f"{what}: speedup {row['speedup']} (expected {figures[1]}), efficiency "
                  f"{row['efficiency']} (expected {figures[2]})")
    check(all(float(r["speedup"]) == 1.0 for r in rows if r["R"] == "1"),
          "speedup 1 at R=1 for each file")
    check(len({r["scene_label"] for r in rows}) == 3 and len({r["scene_file"] for r in rows}) == 3,
          "three labels and three files in cells.csv")

    # The plots: one line per file, named by its label, through that file's own figures. The
    # figures drawn here are the sweep's PNGs byte for byte.
    plan = json.loads((results_dir / "plan.json").read_text())
    sweep = Sweep.from_dict(next(s for s in plan["sweeps"] if s["name"] == "files"))
    drawn = []
    save = plotting.save

    def keep(fig, path):
        drawn.append((Path(path).name, fig.axes[0], [line for line in fig.axes[0].get_lines()
                                                      if line.get_label() != "linear"]))
        return save(fig, path)

    plotting.save = keep
    table, loaded = summary.rows(sweep, results_dir)
    summary.plots(sweep, table, loaded, work / "plots")
    plotting.save = save
    for name in ("time_vs_R.png", "speedup.png", "efficiency.png", "node_breakdown.png"):
        check((work / "plots" / name).read_bytes() ==
              (results_dir / "sweeps" / "files" / name).read_bytes(),
              f"{name}: the sweep's plot is the one checked here")
    column = {"time_vs_R.png": 0, "speedup.png": 1, "efficiency.png": 2}
    for name, axes, lines in drawn:
        if name == "node_breakdown.png":
            ticks = sorted(t.get_text() for t in axes.get_yticklabels())
            want = sorted(f"{label} R={R} V=0 rad" for label in files.values() for R in (1, 2))
            check(ticks == want, f"{name}: bars named by the labels ({ticks[:2]}...)")
            continue
        got = {line.get_label(): [(x, y) for x, y in zip(line.get_xdata(), line.get_ydata())]
               for line in lines}
        # speedup and efficiency name their reference, the file's own R=1 (its fewest nodes)
        against = "" if name == "time_vs_R.png" else " (against R=1 V=0, 1 node)"
        want = {f"{files[f]} V=0{against}": [(R, expected[f][R][column[name]]) for R in (1, 2)]
                for f in files}   # nodes = R at V=0
        check(len(lines) == 3 and sorted(got) == sorted(want) and
              all(len(got[k]) == 2 and all(x == wx and close(y, wy) for (x, y), (wx, wy)
                                           in zip(got[k], want[k])) for k in want),
              f"{name}: three lines, one per file through its own figures ({got})")
        legend = sorted(t.get_text() for t in axes.get_legend().get_texts() if t.get_text() != "linear")
        check(legend == sorted(want), f"{name}: the legend names the three files ({legend})")


def main():
    test_labels()
    with tempfile.TemporaryDirectory(prefix="ncube-sweep-files-test-") as folder:
        test_sweep(Path(folder))
    print(f"sweep_scene_files_test: {len(failures)} failure(s)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
