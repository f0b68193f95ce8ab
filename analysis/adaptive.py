#!/usr/bin/python3
"""Adaptive subdivision (paper section 4.1) and dynamic load balancing (4.2), measured.

Runs ./simulate with --subdivide on the Cornell box and scene2 for R = 4, 8, 16, 64 (V = 0)
and R = 8, V = 7, each without and with --balance, and a run with memory pressure, then
writes analysis/adaptive.md: elements over the iterations, the imbalance between radiosity
processors (max / mean of elements and of busy time), simulated seconds per iteration with
and without balancing, and how close balancing gets to an even share.

  /usr/bin/python3 analysis/adaptive.py [--simulate build/simulate] [--iterations 30] [--jobs 2]

The table's runs have --unlimited-memory (scene2 with subdivision outgrows 4 MB per node
without balancing, which the memory-pressure runs show separately, with the 4 MB cap).
"""

from ncube.interpreter import use_project_python  # noqa: E402

use_project_python()   # Debian's /usr/bin/python3 (README.md, "Use")

import argparse
import concurrent.futures
import io
import json
import os
import subprocess
import sys
import tempfile

from ncube import input_file, page  # noqa: E402
from ncube import opening as op  # noqa: E402

SCENE_BYTES = 256 << 20  # the scene files' size limit of ./simulate's read gate

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CONFIGS = [(4, 0), (8, 0), (16, 0), (64, 0), (8, 7)]
SCENES = ["cornell-box.json", "scene2.json"]


def run(simulate, scene, R, V, iterations, balance, extra=("--unlimited-memory",)):
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "r.json")
        cmd = [simulate, scene, "--R", str(R), "--V", str(V), "--subdivide", "--iterations",
               str(iterations), "--quiet", "--threads", "1", "--json", out, *extra]
        if balance:
            cmd.append("--balance")
        code = subprocess.run(cmd, cwd=ROOT).returncode
        with open(out) as f:
            result = json.load(f)
        result["exit_code"] = code
        shown = [c for c in cmd[1:] if c not in ("--json", out)]
        result["command"] = " ".join(["./simulate"] + shown)
        return result


def imbalance(values):
    mean = sum(values) / len(values)
    return max(values) / mean if mean > 0 else 1.0


def summary(r):
    rps = [n for n in r["nodes"] if n["role"] == "radiosity"]
    busy = [n["compute_seconds"] + n["overhead_seconds"] for n in rps]
    last = r["elements_per_iteration"][-1] if r["elements_per_iteration"] else []
    per_iter = r["iteration_seconds"]
    return {
        "status": r["status"],
        "iterations": r["iterations"],
        "elements_start": r["scene"]["elements"],
        "elements_end": r["elements_at_end"],
        "element_imbalance": imbalance(last) if last else None,
        "time_imbalance": imbalance(busy),
        "seconds_per_iteration": r["seconds_per_iteration"],
        "last5_seconds_per_iteration": sum(per_iter[-5:]) / len(per_iter[-5:]) if per_iter else None,
        "patches_moved": r["patches_moved"],
        "elements_per_iteration": [sum(e) for e in r["elements_per_iteration"]],
        "iteration_seconds": per_iter,
        "command": r["command"],
    }


def plot_figure(rows, path):
    """Elements over the iterations, and simulated seconds per iteration without and with
    balancing, for scene2 (matplotlib, Debian's python3-matplotlib)."""
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return None
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4))
    for scene, R, V, pair in rows:
        if scene != "scene2.json":
            continue
        label = f"R={R}" + (f" V={V}" if V else "")
        left.plot(pair[False]["elements_per_iteration"], label=label)
        line, = right.plot(pair[False]["iteration_seconds"], label=label + " off")
        right.plot(pair[True]["iteration_seconds"], "--", color=line.get_color(), label=label + " on")
    left.set(xlabel="iteration", ylabel="elements", title="scene2, --subdivide: elements")
    right.set(xlabel="iteration", ylabel="simulated s", yscale="log",
              title="seconds per iteration, balancing off / on")
    left.legend(fontsize=8)
    right.legend(fontsize=7, ncol=2)
    fig.tight_layout()
    picture = io.BytesIO()
    fig.savefig(picture, format="png", dpi=90, metadata={"Software": None})
    plt.close(fig)
    page.write(path, picture.getvalue())  # the output rule, as the page
    return path


def opening(found):
    """The page's opening, from its own table: the elements subdivision makes, what balancing
    gains where it moves patches, where it moves none."""
    rows = found[0][1]
    gain_column = "gain"
    elements = {r["scene"]: r["elements start → end"] for r in rows}
    same = all(r["elements start → end"] == elements[r["scene"]] for r in rows)
    moved = [r for r in rows if op.number(r["patches moved"])]
    still = [r for r in rows if not op.number(r["patches moved"])]
    one_run = "one run with and one without balancing per configuration, deterministic; no interval"
    sentences = [op.Sentence(
        "Adaptive subdivision over the run grows " +
        "; ".join(f"{scene} from {span.replace(' → ', ' to ')} elements"
                  for scene, span in elements.items()) +
        (", the same at every R and V" if same else " (at the last R and V of the table; "
                                                         "they differ between R and V)"),
        "counted, deterministic: the parallel runs make the cuts the sequential one makes "
        "(tested bit for bit)")]
    if moved:
        sentences.append(op.Sentence(
            "Load balancing makes the iterations after the cuts faster where it moves patches: " +
            ", ".join(f"{r['scene']} R={r['R']} V={r['V']} {r[gain_column]} "
                      f"({r['patches moved']} patches moved, element imbalance "
                      f"{r['element imbalance (off → on)']})" for r in moved), one_run))
    if still:
        sentences.append(op.Sentence(
            "It moves nothing in " + ", ".join(f"{r['scene']} R={r['R']} V={r['V']}"
                                               for r in still) +
            f" (element imbalance without it {min(op.number(r['element imbalance (off → on)']) for r in still):.2f}"
            f" to {max(op.number(r['element imbalance (off → on)']) for r in still):.2f}: below "
            "the threshold, or no patch small enough to move without overshooting)", one_run))
    return sentences


@page.refusing_outputs("adaptive.py")
def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--simulate", default=os.path.join(ROOT, "build", "simulate"))
    ap.add_argument("--iterations", type=int, default=30)
    ap.add_argument("--jobs", type=int, default=2, help="simulations run at once")
    ap.add_argument("--output", default=os.path.join(ROOT, "analysis", "adaptive.md"))
    args = ap.parse_args()
    page.will_run("adaptive.py", "its 22 runs (the Cornell box and scene2, with and without "
                  "--balance) itself", args.simulate)
    jobs = []
    for scene in SCENES:
        # Through the read gate: the scene is an input, so no page is written onto it.
        patches = len(json.loads(input_file.read_input_text(
            os.path.join(ROOT, "scenes", scene), "scene file", SCENE_BYTES))["patches"])
        for R, V in CONFIGS:
            if R > patches:  # a radiosity processor needs a patch
                print(scene, R, V, "skipped:", patches, "patches", file=sys.stderr)
                continue
            jobs.append((scene, R, V))
    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        futures = {(scene, R, V, b): pool.submit(run, args.simulate, scene, R, V, args.iterations, b)
                   for scene, R, V in jobs for b in (False, True)}
        # Memory pressure: scene2 at R = 8, V = 0 with the 4 MB cap (every node holds all the
        # geometry, so the elements' growth is what runs out).
        pressure_futures = {b: pool.submit(run, args.simulate, "scene2.json", 8, 0, args.iterations,
                                           b, ()) for b in (False, True)}
        rows = []
        for scene, R, V in jobs:
            pair = {b: summary(futures[(scene, R, V, b)].result()) for b in (False, True)}
            for b in (False, True):
                print(scene, R, V, b, pair[b]["status"], pair[b]["seconds_per_iteration"],
                      file=sys.stderr)
            rows.append((scene, R, V, pair))
        pressure = {b: f.result() for b, f in pressure_futures.items()}

    lines = ["# Adaptive subdivision and load balancing, measured (sections 4.1, 4.2)", "",
             "Generated by `/usr/bin/python3 analysis/adaptive.py --iterations %d` "
             "(every run: `--subdivide` with its defaults, contrast 0.5, max level 3; "
             "`--threads 1`). Times are simulated nCube2 seconds. Element imbalance is max / mean "
             "of the radiosity processors' elements at the last shooter selection; time "
             "imbalance is max / mean of their busy (compute + message overhead) seconds over "
             "the run; 1.00 is the ideal even share. Gain = 1 - (s/iteration with balancing) / "
             "(without), over the last five iterations (after the elements have been cut)."
             % args.iterations, "",
             "| scene | R | V | elements start → end | element imbalance (off → on) | time imbalance (off → on) "
             "| s/iteration, last 5 (off → on) | gain | patches moved |",
             "|---|--:|--:|---|---|---|---|--:|--:|"]
    gains = []
    for scene, R, V, pair in rows:
        off, on = pair[False], pair[True]
        if off["status"] != "ok" or on["status"] != "ok":
            lines.append(f"| {scene} | {R} | {V} | {off['elements_start']} → {on['elements_end']} | "
                         f"status {off['status']} → {on['status']} | | | | {on['patches_moved']} |")
            continue
        gain = 1 - on["last5_seconds_per_iteration"] / off["last5_seconds_per_iteration"]
        gains.append((scene, R, V, gain))
        lines.append(
            f"| {scene} | {R} | {V} | {off['elements_start']:,} → {off['elements_end']:,} | "
            f"{off['element_imbalance']:.2f} → {on['element_imbalance']:.2f} | "
            f"{off['time_imbalance']:.2f} → {on['time_imbalance']:.2f} | "
            f"{off['last5_seconds_per_iteration']:.1f} → {on['last5_seconds_per_iteration']:.1f} | "
            f"{100 * gain + 0.0:.1f} % | {on['patches_moved']} |")
    lines += ["", "## Elements over the iterations", "",
              "Sum over the radiosity processors at each shooter selection, without balancing "
              "(balancing moves elements, it does not make or cut them: the counts with it are "
              "the same), identical for every R and V (the same cuts: parallel equals sequential, "
              "see the figure). Every fifth iteration:", ""]
    for scene, R, V, pair in rows:
        if R == 8:
            e = pair[False]["elements_per_iteration"]
            lines.append(f"- {scene}, R = {R}, V = {V}: " + ", ".join(f"{x:,}" for x in e[::5]))
    figures = os.path.join(os.path.dirname(os.path.abspath(args.output)), "figures")
    os.makedirs(figures, exist_ok=True)
    plot = plot_figure(rows, os.path.join(figures, "adaptive.png"))
    if plot:
        lines += ["", "![elements and simulated seconds per iteration](figures/adaptive.png)"]
    lines += ["", f"## Memory pressure: scene2, R = 8, V = 0, {args.iterations} iterations, 4 MB per node", ""]
    for b in (False, True):
        r = pressure[b]
        oom = r.get("out_of_memory", {})
        lines.append(f"- `{r['command']}`: status **{r['status']}** (exit {r['exit_code']}), "
                     f"{r['iterations']} iterations, {r['elements_at_end']:,} elements, "
                     f"{r['patches_moved']} patches moved"
                     + (f"; node {oom['node']} needed {oom['needed_bytes']:,.0f} of "
                        f"{oom['available_bytes']:,.0f} bytes" if oom else ""))
    if gains:
        lines += ["", "## Does section 6's \"considerably\" hold?", "",
                  "Gain in simulated seconds per iteration over the last five iterations, and how "
                  "close the elements come to an even share (max / mean, 1.00 is even) with "
                  "balancing. The rule (docs/model.md, \"Load balancing\") moves a processor's "
                  "patches only when it holds more than (1 + threshold) x the mean (threshold "
                  "0.2), and only patches that fit the smaller of its excess and the receiver's "
                  "deficit, so it never overshoots; a processor whose elements sit in few large "
                  "patches gives nothing.", ""]
        for scene, R, V, pair in rows:
            off, on = pair[False], pair[True]
            if off["status"] != "ok" or on["status"] != "ok":
                continue
            gain = 1 - on["last5_seconds_per_iteration"] / off["last5_seconds_per_iteration"]
            if on["patches_moved"] == 0:
                why = ("below the threshold" if off["element_imbalance"] <= 1.2 else
                       "no patch small enough to move")
                reading = (f"nothing moved ({why}; imbalance {off['element_imbalance']:.2f}); time "
                           f"per iteration changed by {abs(100 * gain):.4f} % (with --subdivide the "
                           f"loads travel with the candidates either way)")
            else:
                reading = (f"**{100 * gain:.1f} % faster**, imbalance {off['element_imbalance']:.2f} "
                           f"→ {on['element_imbalance']:.2f}, {on['patches_moved']} patches moved")
            lines.append(f"- {scene}, R = {R}, V = {V}: {reading}")
        moved = [g for g in gains if g[3] > 0.001]
        if moved:
            lines += ["", f"Where balancing moved patches, the following iterations ran "
                      f"{100 * min(g[3] for g in moved):.0f} to {100 * max(g[3] for g in moved):.0f} % "
                      "faster: section 6's \"considerably\" holds in that sense for scene2. With "
                      "fewer patches per processor (large R) the element counts are more uneven "
                      "to start with, and the patches left to move are too few to even them out "
                      "fully (see the imbalance with balancing)."]
    body = "\n".join(lines) + "\n"
    page.write(args.output, op.with_opening(body, opening(op.tables(body)), "analysis/adaptive.py"))
    print("wrote", args.output, file=sys.stderr)


if __name__ == "__main__":
    main()
