#!/usr/bin/python3
"""Predictions beyond the paper, stated before they can be checked: writes analysis/predictions.md.

usage: /usr/bin/python3 analysis/predictions.py [--results DIR]

Runs the sweeps of experiments/predictions/ through experiments/sweep into DIR (default
results/predictions/; a cell already finished there is read, not run again) and states, for
each question, the simulator's figure and the command that repeats it:

* octree-tables.yaml: the cells of the paper's Tables 1-4 with the octree of section 6 next
  to brute force; is V = 3..7 "substantially better" (section 6) with the octree?
* scene4-hypercubes.yaml: scene4 (51,200 patches) on the hypercubes of 64 to 8,192 nodes;
* render.yaml: the parallel rendering phase (section 2.3), each partition and distribution.

The output depends only on the result files (sorted, no dates, no host times)."""

from ncube.interpreter import use_project_python  # noqa: E402

use_project_python()   # Debian's /usr/bin/python3 (README.md, "Use")

import argparse
import os
import subprocess
import sys
from pathlib import Path


from ncube import opening as op  # noqa: E402
from ncube import options as opts  # noqa: E402
from ncube import page, results, summary  # noqa: E402
from ncube.paths import ANALYSIS, ROOT  # noqa: E402
from ncube.sweep import load_all  # noqa: E402

SWEEP_DIR = ROOT / "experiments" / "predictions"
SWEEP_FILES = ["octree-tables.yaml", "scene4-hypercubes.yaml", "render.yaml"]
OUTPUT = ANALYSIS / "predictions.md"
RESULTS = "results/predictions"


def rel(path):
    return os.path.relpath(path, ROOT)


def simulate_command(cell):
    """The short ./simulate command of a cell: the options that differ from the defaults."""
    args = ["./simulate", os.path.basename(cell.scene_file)]
    for name, value in cell.options.items():
        option = opts.OPTIONS[name]
        if name in ("R", "V") or value != option.default:
            if option.kind is bool:
                args += [option.flag] if value else []
            else:
                args += [option.flag, str(value)]
    platform = os.path.basename(cell.platform_file)
    if platform != "ncube2.json":
        args += ["--platform", f"platforms/{platform}"]
    return "`" + " ".join(args) + "`"


def sweep_command(name):
    return f"`experiments/sweep experiments/predictions/{name} --results {RESULTS}`"


def run_missing(sweeps, results_dir):
    """Runs experiments/sweep unless every cell has its finished result already."""
    missing = [c for s in sweeps for c in s.cells
               if results.mismatch(results.read(results_dir / c.file), c) is not None]
    if missing:
        print(f"predictions: {len(missing)} cells to run", file=sys.stderr)
        subprocess.run([sys.executable, str(ROOT / "experiments" / "sweep")] +
                       [str(SWEEP_DIR / f) for f in SWEEP_FILES] +
                       ["--results", str(results_dir)], check=True)
    else:   # the CSVs and plots, as experiments/sweep writes them
        for sweep in sweeps:
            summary.summarize(sweep, results_dir)


def status(result):
    return result["status"] if result else "missing"


def oom_text(result):
    """Why a result has no value, with the node over its memory when there is one."""
    state = status(result)
    oom = (result or {}).get("out_of_memory")
    if state == "out_of_memory" and oom:
        return (f"out of memory ({oom['role']} node {oom['node']}: {oom['needed_bytes']:,.0f} "
                f"of {oom['available_bytes']:,.0f} bytes)")
    return state


def seconds(value, state="out_of_memory"):
    """A measure for a table: its value, else why there is none."""
    if value is not None:
        return f"{value:,.2f}"
    return {"out_of_memory": "out of memory", "missing": "not run"}.get(state, state)


def octree_section(sweep, loaded):
    by = {}
    for cell, result in loaded:
        by[(cell.scene, cell.R, cell.V, cell.options["visibility"])] = (
            cell, results.measure(result, sweep.measure), oom_text(result))
    configs = sorted({k[:3] for k in by}, key=lambda k: (k[0], k[1] * (k[2] + 1), k[1], k[2]))
    lines = ["## 1. The octree (section 6) in the cells of Tables 1-4", "",
             "The paper (section 6): with a faster visibility computation (\"e.g. octrees\") "
             "the configurations with V = 3..7 would \"perform substantially better\". "
             "Seconds per iteration (mean of the first 20 iterations, 64 samples) of every "
             "configuration of Tables 1-4 (scene3: only Table 4's configurations of about "
             "64 nodes), brute force against the octree; ratio = brute force / octree.", "",
             f"All figures: {sweep_command('octree-tables.yaml')}, then "
             f"`{RESULTS}/sweeps/octree-tables/cells.csv`; one cell: the command in the row "
             "(add `--visibility brute-force` for the other column).", "",
             "| scene | R | V | nodes | brute force | octree | ratio | octree cell |",
             "|---|---:|---:|---:|---:|---:|---:|---|"]
    ratios = {}
    for scene, R, V in configs:
        _, brute, brute_state = by[(scene, R, V, "brute-force")]
        cell, octree, octree_state = by[(scene, R, V, "octree")]
        ratio = brute / octree if brute and octree else None
        ratios[(scene, R, V)] = ratio
        lines.append(f"| {scene} | {R} | {V} | {R * (V + 1)} | {seconds(brute, brute_state)} | "
                     f"{seconds(octree, octree_state)} | {'' if ratio is None else f'{ratio:.2f}'} | "
                     f"{simulate_command(cell)} |")
    lines += ["", "**Predictions.**", ""]
    for scene in sorted({k[0] for k in configs}):
        lines.append(f"* {scene}:")
        mid = [(k, r) for k, r in ratios.items() if k[0] == scene and 3 <= k[2] <= 7 and r]
        flat = [(k, r) for k, r in ratios.items() if k[0] == scene and k[2] == 0 and r]
        if mid:
            lo, hi = min(r for _, r in mid), max(r for _, r in mid)
            lines.append(f"  the octree makes V = 3..7 {lo:.2f} to {hi:.2f} times "
                         f"as fast as brute force ({len(mid)} configurations); V = 0: "
                         + (f"{min(r for _, r in flat):.2f} to {max(r for _, r in flat):.2f}"
                            if flat else "none") + ".")
        full = [(by[(s, R, V, 'octree')][1], R, V, by[(s, R, V, 'octree')][0])
                for s, R, V in configs if s == scene and R * (V + 1) >= 60
                and by[(s, R, V, 'octree')][1]]
        if full:
            best = min(full, key=lambda t: t[0])
            brute_best = min([(by[(s, R, V, 'brute-force')][1], R, V) for s, R, V in configs
                              if s == scene and R * (V + 1) >= 60
                              and by[(s, R, V, 'brute-force')][1]], default=None)
            lines.append(f"  Fastest configuration of about 64 nodes with the octree: R={best[1]} "
                         f"V={best[2]}, {best[0]:,.2f} s per iteration "
                         f"({simulate_command(best[3])})" + (
                             "" if brute_best is None else
                             f"; with brute force: R={brute_best[1]} V={brute_best[2]}, "
                             f"{brute_best[0]:,.2f} s") + ".")
            mid64 = [t for t in full if 3 <= t[2] <= 7]
            flat64 = [t for t in full if t[2] == 0]
            if mid64 and flat64:
                m, f = min(mid64, key=lambda t: t[0]), flat64[0]
                verdict = "better" if m[0] < f[0] else "not better"
                lines.append(f"  With the octree, is V = 3..7 better than V = 0 at about 64 "
                             f"nodes? {verdict}: the best of V = 3..7, R={m[1]} V={m[2]}, "
                             f"{m[0]:,.2f} s, against R={f[1]} V=0, {f[0]:,.2f} s "
                             f"(ratio V=0 / V=3..7: {f[0] / m[0]:.2f}).")
    return lines + [""]


def scene4_section(sweep, loaded):
    lines = ["## 2. scene4 (51,200 patches) on hypercubes of 64 to 8,192 nodes", "",
             "Brute force, 16 samples, 1 iteration (the first iteration: every radiosity "
             "processor shoots one light), every node busy: R = nodes / (V + 1). "
             "Simulated seconds of that iteration; \"out of memory\" where a node's modeled "
             "memory does not hold its share (docs/scenes.md).", "",
             f"All figures: {sweep_command('scene4-hypercubes.yaml')}.", "",
             "| nodes | R | V | seconds per iteration | command |", "|---:|---:|---:|---:|---|"]
    rows = sorted(((cell.R * (cell.V + 1), cell.V, cell, results.measure(result, sweep.measure),
                    oom_text(result)) for cell, result in loaded), key=lambda t: (t[0], t[1]))
    for nodes, V, cell, value, state in rows:
        lines.append(f"| {nodes:,} | {cell.R} | {V} | {seconds(value, state)} | "
                     f"{simulate_command(cell)} |")
    lines += ["", "**Predictions: the best configuration at each size.**", ""]
    for nodes in sorted({r[0] for r in rows}):
        ok = [r for r in rows if r[0] == nodes and r[3] is not None]
        if ok:
            best = min(ok, key=lambda r: r[3])
            lines.append(f"* {nodes:,} nodes: R={best[2].R} V={best[1]}, "
                         f"{best[3]:,.2f} s per iteration.")
        else:
            lines.append(f"* {nodes:,} nodes: no configuration fits.")
    return lines + [""]


def render_section(sweep, loaded):
    lines = ["## 3. Parallel rendering (section 2.3), 800 x 600", "",
             "The rendering phase after the radiosity run (docs/model.md, \"Parallel "
             "rendering\"): its simulated seconds (`render.simulated_seconds`), its imbalance "
             "(max / mean of the nodes' rasterisation seconds) and, for scale, the radiosity "
             "run's seconds per iteration (mean of its 2 iterations). \"Out of memory\" in the "
             "rendering phase: the hypercube distribution (recursive doubling) leaves every "
             "node holding all elements, the ring at most the share it passes on and the one "
             "arriving (docs/model.md).", "",
             f"All figures: {sweep_command('render.yaml')}; one cell: the command in the row.",
             "", "| scene | R | V | partition | distribution | rendering s | imbalance | "
             "radiosity s per iteration | rendering / iteration | command |",
             "|---|---:|---:|---|---|---:|---:|---:|---:|---|"]
    rows = []
    for cell, result in loaded:
        render = (result or {}).get("render") if result and result.get("status") == "ok" else None
        rows.append((cell.scene, cell.R, cell.V, cell.options["render_parallel"],
                     cell.options["render_distribution"], cell, render,
                     results.measure(result, sweep.measure), oom_text(result)))
    rows.sort(key=lambda r: r[:5])
    best = {}
    for scene, R, V, part, dist, cell, render, per_iteration, state in rows:
        if render is None:
            lines.append(f"| {scene} | {R} | {V} | {part} | {dist} | {seconds(None, state)} | | | | "
                         f"{simulate_command(cell)} |")
            continue
        t = render["simulated_seconds"]
        lines.append(f"| {scene} | {R} | {V} | {part} | {dist} | {t:,.3f} | "
                     f"{render['imbalance']:.3f} | {per_iteration:,.2f} | "
                     f"{t / per_iteration:.3f} | {simulate_command(cell)} |")
        key = (scene, R, V)
        if key not in best or t < best[key][0]:
            best[key] = (t, part, dist)
    lines += ["", "**Predictions: the fastest rendering per configuration.**", ""]
    for (scene, R, V), (t, part, dist) in sorted(best.items()):
        lines.append(f"* {scene} R={R} V={V}: {part} with {dist}, {t:,.3f} s.")
    return lines + [""]


UNSURE = "one deterministic run per cell, no interval (a prediction)"
FIRST_UNSURE = ("one deterministic run per cell and no interval: a prediction, stated before any "
                "measurement; the model's error on the paper's own cells (analysis/report.md) is "
                "the nearest measure of how far to trust it")


def opening(found):
    """The page's opening, from its own tables: the octree against brute force and whether it
    makes visibility processors pay at 64 nodes (section 1), scene4 on the largest hypercube
    (section 2), the fastest rendering and its share of an iteration (section 3)."""
    octree = op.table(found, "1. The octree", "octree")
    scenes = sorted({r["scene"] for r in octree})
    full = [r for r in octree if 60 <= int(r["nodes"]) <= 64]
    best, best_v = {}, {}
    for scene in scenes:
        mine = [r for r in full if r["scene"] == scene and op.number(r["octree"]) is not None]
        best[scene] = min(mine, key=lambda r: op.number(r["octree"]))
        middle = [r for r in mine if 3 <= int(r["V"]) <= 7]
        best_v[scene] = min(middle, key=lambda r: op.number(r["octree"])) if middle else None
    slower = all(op.number(best_v[s]["octree"]) > op.number(best[s]["octree"])
                 for s in scenes if best_v[s])
    ratios = {v0: [op.number(r["ratio"]) for r in octree
                   if (r["V"] == "0" if v0 else 3 <= int(r["V"]) <= 7) and
                   op.number(r["ratio"]) is not None] for v0 in (True, False)}
    sentences = [op.Sentence(
        "With the octree of section 6 the fastest configuration of about 64 nodes is " +
        "; ".join(f"{s}: R={best[s]['R']} V={best[s]['V']} ({best[s]['octree']} s per iteration, "
                  f"brute force {best[s]['brute force']})" for s in scenes) +
        f"; the best with V = 3..7 is {'slower' if slower else 'not slower'} on every scene (" +
        "; ".join(f"{s} R={best_v[s]['R']} V={best_v[s]['V']} {best_v[s]['octree']} s"
                  for s in scenes if best_v[s]) + ")" +
        (", so section 6's \"substantially better\" does not come true against V = 0"
         if slower else ""), FIRST_UNSURE),
        op.Sentence(
        f"The octree is {min(ratios[True]):.2f} to {max(ratios[True]):.2f} times as fast as brute "
        f"force at V = 0 and {min(ratios[False]):.2f} to {max(ratios[False]):.2f} times at "
        "V = 3..7 (every cell of Tables 1-4): it speeds up V = 3..7 substantially, V = 0 more",
        UNSURE)]
    scene4 = op.table(found, "2. scene4", "seconds per iteration")
    sizes = {}
    for r in scene4:
        if op.number(r["seconds per iteration"]) is not None and \
                not r["seconds per iteration"].startswith("out"):
            n = op.number(r["nodes"])
            if n not in sizes or op.number(r["seconds per iteration"]) < \
                    op.number(sizes[n]["seconds per iteration"]):
                sizes[n] = r
    small, large = sizes[min(sizes)], sizes[max(sizes)]
    sentences.append(op.Sentence(
        f"scene4 (51,200 patches) takes {large['seconds per iteration']} s for its first "
        f"iteration on {large['nodes']} nodes at R={large['R']} V={large['V']}, "
        f"{op.number(small['seconds per iteration']) / op.number(large['seconds per iteration']):.0f}"
        f" times as fast as the best of {small['nodes']} nodes (R={small['R']} V={small['V']}, "
        f"{small['seconds per iteration']} s)", UNSURE))
    render = op.table(found, "3. Parallel rendering", "rendering s")
    timed = [r for r in render if op.number(r["rendering / iteration"]) is not None]
    shares = [op.number(r["rendering / iteration"]) for r in timed if r["scene"] == "scene2"]
    fastest = min((r for r in timed if r["scene"] == "scene2"),
                  key=lambda r: op.number(r["rendering s"]))
    sentences.append(op.Sentence(
        f"Rendering scene2 at 800 x 600 takes {min(shares):.3g} to {max(shares):.3g} of a "
        f"radiosity iteration; fastest {fastest['partition']} with {fastest['distribution']} at "
        f"R={fastest['R']} V={fastest['V']} ({fastest['rendering s']} s)", UNSURE))
    return sentences


@page.refusing_outputs("predictions.py")
def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--results", type=Path, default=ROOT / RESULTS,
                        help=f"the results folder (default: {RESULTS}/)")
    args = parser.parse_args()
    results_dir = args.results.resolve()
    page.will_run("predictions.py", f"the cells of {page.shown(SWEEP_DIR)}/ without a result in "
                  f"{page.shown(results_dir)}/ through experiments/sweep")
    sweeps = load_all([SWEEP_DIR / f for f in SWEEP_FILES])
    run_missing(sweeps, results_dir)
    sections = {"octree-tables": octree_section, "scene4-hypercubes": scene4_section,
                "render": render_section}
    lines = ["# Predictions beyond the paper", "",
             "Generated by `/usr/bin/python3 analysis/predictions.py` from the sweeps in "
             "`experiments/predictions/` (run through `experiments/sweep` into "
             f"`{RESULTS}/`). Stated before they can be checked: none of these "
             "configurations was measured by the paper. Seconds are simulated nCube2 seconds.",
             ""]
    for sweep in sweeps:
        _, loaded = summary.rows(sweep, results_dir)
        lines += sections[sweep.name](sweep, loaded)
    body = "\n".join(lines).rstrip() + "\n"
    page.write(OUTPUT, op.with_opening(body, opening(op.tables(body)), "analysis/predictions.py"))
    print(f"wrote {rel(OUTPUT)}")


if __name__ == "__main__":
    main()
