#!/usr/bin/env bash
# Sweep plots (analysis/ncube/plotting.py) draw one line per configuration: a sweep that
# varies a third key (balance) beside R and V gets a line per balance value, named in the
# legend, and no line joins cells that differ in anything but the x axis. Synthetic cells: no
# simulation runs.
# Usage: bash tests/plot_series_test.sh <path-to-simulate-binary> <repo-root>
set -euo pipefail
root="${2:-$(cd "$(dirname "$0")/.." && pwd)}"
exec /usr/bin/python3 - "$root" <<'PY'
import sys
sys.path.insert(0, sys.argv[1] + "/analysis")
from ncube import options as opts
from ncube import plotting

# grid: {scene: [cornell-box], R: [2, 4], V: [0, 1], subdivide: [true], balance: [false, true]}
table = []
for balance in (False, True):
    for V in (0, 1):
        for R in (2, 4):
            row = {name: option.default for name, option in opts.OPTIONS.items()}
            row.update(scene="cornell-box", scene_label="cornell-box",
                       scene_file="scenes/cornell-box.json", R=R, V=V, nodes=R * (V + 1), subdivide=True,
                       balance=balance, platform="ncube2.json", cost_model="cost_model.json",
                       cfg="", value=1.0 + R + 10 * V + 100 * balance, speedup=1.0,
                       efficiency=1.0)
            table.append(row)

problems = []
figures = []
plotting.save = lambda fig, path: figures.append(fig) or path   # keep the figure, write nothing
plotting.time_vs_R(table, "seconds", "unused.png")
plotting.ratio_vs_nodes(table, "speedup", "unused.png")
for fig, x_key in zip(figures, ("R", "nodes")):
    axes = fig.axes[0]
    lines = [line for line in axes.get_lines() if line.get_label() != "linear"]
    labels = sorted(line.get_label() for line in lines)
    if len(lines) != 4:
        problems.append(f"{x_key}: {len(lines)} lines, not 4 (balance x V)")
    for line in lines:
        xs = list(line.get_xdata())
        if len(set(xs)) != len(xs):
            problems.append(f"{x_key}: line {line.get_label()!r} joins cells at the same x {xs}")
        ys = list(line.get_ydata())
        if x_key == "R" and len({round(y - x, 9) for x, y in zip(xs, ys)}) != 1:
            problems.append(f"line {line.get_label()!r} mixes configurations: {ys}")
    want = sorted(f"cornell-box V={V}, balance={b}" for V in (0, 1) for b in (False, True))
    if labels != want:
        problems.append(f"{x_key}: legend {labels}, expected {want}")
    legend = [t.get_text() for t in axes.get_legend().get_texts()]
    if sorted(t for t in legend if t != "linear") != want:
        problems.append(f"{x_key}: the legend shows {legend}")

if problems:
    print("FAIL: " + "; ".join(problems), file=sys.stderr)
    sys.exit(1)
print("PASS: one line per configuration, named in the legend")
PY
