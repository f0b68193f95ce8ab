#!/usr/bin/python3
"""The paper's claim 2, measured (issue 31 item 5): the paper's parallelisation (receivers)
against the shooter-centred scheme it replaced (shooters), on 4 to 64 nodes.

Reads experiments/claims/schemes.yaml with the sweep tool's own loader (its validation,
defaults and cell identity), runs every cell's ./simulate command itself (one host thread,
two cells at once), and keeps each result under RESULTS/claims/schemes/ named after the cell's
identity: a finished cell is not run again, a changed option or input is another cell. Beside
the sweep's cells it runs, as further cells of the same identity rule:
  - an --unlimited-memory twin of every cell that ran out of memory (exit 3), so that the
    time beyond memory is shown, marked as such;
  - on the scenes with a reference (analysis/reference/<scene>.json), --iterations
    checkpoints with --mesh, to find the first iteration whose element RMS error
    (analysis/ncube/accuracy.py) is within ERROR_FACTOR of the paper's converged error at
    R = 4, V = 0: bisection over the iterations, which assumes the error falls with the
    iterations (it does in every run seen: the meshes hold the light shot so far).
section(results_root) returns the markdown section analysis/claims.py puts in
analysis/claims.md; run alone it prints it:

  /usr/bin/python3 analysis/claims_schemes.py [--results results] [--jobs 2]

Writes analysis/figures/claims_schemes_speedup.png (the speedup curves)."""

from ncube.interpreter import use_project_python  # noqa: E402

use_project_python()   # Debian's /usr/bin/python3 (README.md, "Use")

import argparse
import concurrent.futures
import dataclasses
import json
import math
import os
import subprocess
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from ncube import accuracy, page, paths, plotting, sweep  # noqa: E402

ROOT = paths.ROOT
SWEEP = ROOT / "experiments" / "claims" / "schemes.yaml"
FIGURE = ROOT / "analysis" / "figures" / "claims_schemes_speedup.png"
ERROR_SCENES = ("cornell-box", "scene0")
ERROR_FACTOR = 1.1          # the fixed error: 1.1 x the paper's converged element RMS at R = 4
NODE_COUNTS = (4, 8, 16, 32, 64)
# platforms/cost_model.json's radiosity_increment_bytes and the message header.
INCREMENT_BYTES, HEADER_BYTES = 12, 8
EXIT_OUT_OF_MEMORY = 3
TIE = 0.01                  # a time ratio within 1 % of 1 counts as level


class CellFailed(RuntimeError):
    pass


def variant(cell, **options):
    """The cell with some options changed: another cell, of another identity."""
    return dataclasses.replace(cell, options=dict(cell.options, **options))


def run_cell(cell, folder, mesh=False):
    """The cell's result (and mesh) under `folder`, run now unless there; a run out of
    simulated memory (exit 3) is a result too (its status says so)."""
    stem = Path(cell.file).stem
    result, mesh_path = folder / f"{stem}.json", folder / f"{stem}.ply"
    if result.exists() and (not mesh or mesh_path.exists()
                            or json.loads(result.read_text())["status"] != "ok"):
        return result, (mesh_path if mesh_path.exists() else None)
    partial = folder / f"{stem}.partial.json"
    command = cell.command(str(partial))   # --quiet --threads 1
    if mesh:
        command += ["--mesh", str(folder / f"{stem}.partial.ply")]
    run = subprocess.run(command, env=paths.simulate_environment(), capture_output=True, text=True)
    if run.returncode not in (0, EXIT_OUT_OF_MEMORY) or not partial.exists():
        raise CellFailed(f"{cell.label} ({cell.file}): ./simulate exit {run.returncode}: "
                         f"{run.stderr.strip()}")
    if mesh and run.returncode == 0:
        os.replace(folder / f"{stem}.partial.ply", mesh_path)   # the mesh first
    os.replace(partial, result)
    return result, (mesh_path if mesh and run.returncode == 0 else None)


def figures_of(result, cell, beyond_memory=False, link_bandwidth=2.2e6):
    """One row of the study from a result file."""
    nodes = result["nodes"]
    sent = sum(n["bytes_sent"] for n in nodes)
    iterations = result["iterations"]
    shots = len(result["shooters"])
    busiest = max((n["bytes_sent"] for n in nodes), default=0.0)
    o = cell.options
    return {"scene": cell.scene, "scheme": o["parallelisation"], "R": o["R"], "V": o["V"],
            "nodes": o["R"] * (o["V"] + 1), "status": result["status"],
            "beyond_memory": beyond_memory, "converged": result["converged"],
            "iterations": iterations, "shots": shots, "elements": result["scene"]["elements"],
            "patches": result["scene"]["patches"], "samples": o["samples"],
            "simulated_seconds": result["simulated_seconds"],
            "bytes_per_iteration": sent / iterations if iterations else 0.0,
            "bytes_per_shot": sent / shots if shots else 0.0,
            "wire_share": (busiest / link_bandwidth / result["simulated_seconds"]
                           if result["simulated_seconds"] else 0.0),
            "wait_share": (sum(n["waiting_seconds"] for n in nodes) / len(nodes)
                           / result["simulated_seconds"] if result["simulated_seconds"] else 0.0),
            "peak_memory_bytes": max(n["peak_memory_bytes"] for n in nodes),
            "out_of_memory": result.get("out_of_memory"), "cell": cell.file}


def exchange_formula(R, elements):
    """docs/model.md's hand-worked bytes of one iteration of the shooters' exchange over the
    machine: recursive doubling, each node sending its whole vector (12 bytes an element plus
    the 8-byte header) once per dimension; R not a power of two first folds the R - p nodes
    above the largest power of two p in and gets the sum back."""
    p = 1 << (R.bit_length() - 1)
    vector = elements * INCREMENT_BYTES + HEADER_BYTES
    return vector * (p * int(math.log2(p)) + 2 * (R - p))


def element_error(mesh, reference, reference_path):
    return accuracy.compare(accuracy.solution_from_ply(mesh), reference, str(mesh),
                            str(reference_path))["element_rms"]


def time_to_error(cell, total_iterations, level, folder, reference, reference_path):
    """(iteration, simulated seconds, element RMS) of the first --iterations checkpoint whose
    element RMS is at most `level`, by bisection over 1..total_iterations; None if the
    converged run does not reach it."""
    def at(k):
        # The whole run is the cell itself (already run with its mesh), not a twin of it.
        checkpoint = cell if k == total_iterations else variant(cell, iterations=k)
        result_path, mesh = run_cell(checkpoint, folder, mesh=True)
        return (json.loads(result_path.read_text())["simulated_seconds"],
                element_error(mesh, reference, reference_path))
    seconds, error = at(total_iterations)
    if error > level:
        return None
    low, high, best = 0, total_iterations, (seconds, error)
    while high - low > 1:
        middle = (low + high) // 2
        s, e = at(middle)
        if e <= level:
            high, best = middle, (s, e)
        else:
            low = middle
    return high, best[0], best[1]


def measure(results_root, jobs=2, sweep_file=SWEEP):
    """Every row of the study, running what is not yet in results_root/claims/schemes/."""
    folder = Path(results_root).resolve() / "claims" / "schemes"
    folder.mkdir(parents=True, exist_ok=True)
    cells = sweep.load(sweep_file).cells
    # The link bandwidth of the cells' machine (the sweep gives every cell the same platform).
    bandwidth = json.loads(Path(cells[0].platform_file).read_text())["parameters"][
        "link_bandwidth"]["value"]
    with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
        meshed = [c.scene in ERROR_SCENES for c in cells]
        runs = list(pool.map(lambda cm: run_cell(cm[0], folder, cm[1]), zip(cells, meshed)))
        rows, twins = [], []
        for cell, (result_path, _) in zip(cells, runs):
            result = json.loads(result_path.read_text())
            rows.append(figures_of(result, cell, link_bandwidth=bandwidth))
            if result["status"] == "out_of_memory":
                twins.append(variant(cell, unlimited_memory=True))
        for twin, (result_path, _) in zip(twins, pool.map(lambda c: run_cell(c, folder), twins)):
            rows.append(figures_of(json.loads(result_path.read_text()), twin, beyond_memory=True,
                                   link_bandwidth=bandwidth))
        # The time to the fixed error, on the scenes with a reference.
        levels, jobs_ = {}, []
        for scene in ERROR_SCENES:
            mine = [(c, r) for c, r in zip(cells, rows) if c.scene == scene]
            if not mine:
                continue
            reference_path = ROOT / "analysis" / "reference" / f"{scene}.json"
            reference = accuracy.read_reference(reference_path)
            if reference["scene_sha256"] != mine[0][0].scene_sha256:
                raise CellFailed(f"{reference_path} is of another {scene} (its scene_sha256 "
                                 "differs): run experiments/claims/references again")
            anchor = next((c for c, r in mine if r["scheme"] == "receivers" and r["R"] == 4
                           and r["V"] == 0), mine[0][0])
            _, anchor_mesh = run_cell(anchor, folder, mesh=True)
            converged_error = element_error(anchor_mesh, reference, reference_path)
            levels[scene] = (ERROR_FACTOR * converged_error, converged_error, anchor.R, anchor.V)
            for cell, row in mine:
                if row["status"] == "ok" and row["converged"] and row["nodes"] in NODE_COUNTS \
                        and shown_row(row, rows):
                    jobs_.append((row, pool.submit(time_to_error, cell, row["iterations"],
                                                   levels[scene][0], folder, reference,
                                                   reference_path)))
        for row, future in jobs_:
            row["to_error"] = future.result()
    return rows, levels


def best_receivers(rows, scene, nodes):
    """The paper's program at its fastest R x (V + 1) = nodes (converged runs within memory)."""
    candidates = [r for r in rows if r["scene"] == scene and r["scheme"] == "receivers"
                  and r["nodes"] == nodes and r["status"] == "ok" and not r["beyond_memory"]]
    return min(candidates, key=lambda r: r["simulated_seconds"], default=None)


def shown_row(row, rows):
    """Rows the tables show: every shooters row, the paper's at V = 0, and its best per count."""
    if row["scheme"] == "shooters" or row["V"] == 0:
        return True
    return best_receivers(rows, row["scene"], row["nodes"]) is row


def pick(rows, scene, scheme, R, V=0):
    """The row (within memory if it fits, else its --unlimited-memory twin)."""
    mine = [r for r in rows if r["scene"] == scene and r["scheme"] == scheme and r["R"] == R
            and r["V"] == V]
    fits = [r for r in mine if r["status"] == "ok" and not r["beyond_memory"]]
    return (fits or [r for r in mine if r["beyond_memory"]] or mine or [None])[0]


def baseline(rows, scene):
    """One node running the paper's program (beyond memory where a node cannot hold it)."""
    return pick(rows, scene, "receivers", 1)


def lines_of(rows, scene):
    """The three compared lines of a scene: {name: {nodes: row}}."""
    lines = {"receivers, V = 0": {}, "receivers, best R x (V + 1)": {}, "shooters": {}}
    for n in NODE_COUNTS:
        for name, row in (("receivers, V = 0", pick(rows, scene, "receivers", n)),
                          ("receivers, best R x (V + 1)", best_receivers(rows, scene, n)),
                          ("shooters", pick(rows, scene, "shooters", n))):
            if row is not None:
                lines[name][n] = row
    return lines


def why_missing(rows, scene, name, nodes):
    patches = next((r["patches"] for r in rows if r["scene"] == scene), None)
    if name != "receivers, best R x (V + 1)" and patches is not None and nodes > patches:
        return f"R > the {patches} patches"
    return "not in the sweep"


def fmt_bytes(b):
    return f"{b / 1e6:.2f} MB" if b >= 1e6 else f"{b / 1e3:.1f} KB" if b >= 1e3 else f"{b:.0f} B"


def fmt_time(row):
    if row is None:
        return "—"
    if row["status"] != "ok":
        return "out of memory"
    return f"{row['simulated_seconds']:.1f}" + (" †" if row["beyond_memory"] else "")


def memory_cell(row, cap):
    if row is None:
        return "—"
    text = f"{row['peak_memory_bytes'] / 2**20:.2f} MB"
    return text + (" (exit 3)" if row["status"] == "out_of_memory" else "") if \
        not row["beyond_memory"] else text + " †"


def plot(rows, scenes, path):
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, len(scenes), figsize=(4.6 * len(scenes), 4), squeeze=False,
                             layout="constrained")
    for ax, scene in zip(axes[0], scenes):
        base = baseline(rows, scene)
        # Fixed colours and markers per line (the V = 0 line hollow and larger, as the best
        # R x (V + 1) line lies on it wherever V = 0 is best).
        for (name, points), (style, colour, size) in zip(
                lines_of(rows, scene).items(),
                (("o-", "tab:blue", 9), ("s--", "tab:orange", 5), ("^-", "tab:green", 6))):
            ok = sorted(((n, r) for n, r in points.items() if r["status"] == "ok"),
                        key=lambda p: p[0])
            if name.startswith("receivers, best") and all(r["V"] == 0 for _, r in ok):
                ok = []     # the V = 0 line (scenes without V > 0 cells)
            if not ok or base is None:
                continue
            xs = [n for n, _ in ok]
            ys = [base["simulated_seconds"] / r["simulated_seconds"] for _, r in ok]
            ax.plot(xs, ys, style, color=colour, markersize=size, label=name,
                    markerfacecolor="none" if size == 9 else colour)
            hollow = [(x, y) for (n, r), x, y in zip(ok, xs, ys) if r["beyond_memory"]]
            if hollow:
                ax.plot(*zip(*hollow), "x", color="black", markersize=9)
        ax.plot(NODE_COUNTS, NODE_COUNTS, ":", color="grey", label="linear")
        ax.set_xscale("log", base=2)
        ax.set_yscale("log", base=2)
        ax.set_xlabel("nodes")
        ax.set_ylabel("speedup over one node (paper's program)")
        what = "to convergence" if scene in ERROR_SCENES else "first 64 shots"
        ax.set_title(f"{scene}: {what}" + ("" if base is None or not base["beyond_memory"]
                                           else " (x: beyond 4 MB)"), fontsize=9)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7)
    plotting.save(fig, path)


def comparisons(rows):
    """(scene, nodes, shooters' / paper's time to convergence, the same to the fixed error)
    for every node count where both schemes ran within memory; the paper's program at its
    best R x (V + 1)."""
    out = []
    for scene in ERROR_SCENES:
        for n in NODE_COUNTS:
            paper, shooters = best_receivers(rows, scene, n), pick(rows, scene, "shooters", n)
            if paper is None or shooters is None or shooters["status"] != "ok" \
                    or shooters["beyond_memory"]:
                continue
            to_error = None
            if paper.get("to_error") and shooters.get("to_error"):
                to_error = shooters["to_error"][1] / paper["to_error"][1]
            out.append((scene, n, shooters["simulated_seconds"] / paper["simulated_seconds"],
                        to_error))
    return out


def smallest_fitting_R(rows, scene, scheme):
    fits = [r["R"] for r in rows if r["scene"] == scene and r["scheme"] == scheme
            and r["V"] == 0 and r["status"] == "ok" and not r["beyond_memory"]]
    return min(fits, default=None)


def verdict(rows):
    """The claim's sentence, from the figures: holds when the paper's program is nowhere slower
    than the shooters (a ratio within TIE of 1 counts as level), holds only where when it is
    slower somewhere, does not hold when it is slower everywhere."""
    pairs = comparisons(rows)
    if not pairs:
        return "Claim 2 is not measured: no node count where both schemes converged in memory."
    ratios = [(f"{scene} at {n} nodes", which, ratio) for scene, n, to_converge, to_error in pairs
              for which, ratio in (("convergence", to_converge), ("error", to_error))
              if ratio is not None]
    slower = [r for r in ratios if r[2] < 1 - TIE]    # the paper's program slower
    faster = [r for r in ratios if r[2] > 1 + TIE]
    head = ("holds" if not slower else "holds only where the shooters are not faster" if faster
            else "does not hold")
    parts = [f"Claim 2 (no need to distribute radiosity values after the form factors) "
             f"**{head}**: "]

    def span(which):
        values = [r for _, w, r in ((a, b, c) for a, b, c in ratios) if w == which]
        return (f"{min(values):.2f}x to {max(values):.2f}x" if values else "not measured")
    parts.append(f"on {len(pairs)} node counts of the Cornell box and scene0 the shooters take "
                 f"{span('error')} the paper's time to the fixed error and {span('convergence')} "
                 "its time to convergence (the paper's program at its best R x (V + 1))")
    if slower:
        parts.append("; the shooters are faster on " + ", ".join(
            f"{where} to {which} ({ratio:.2f}x)" for where, which, ratio in slower) +
            ", as they shoot R patches an iteration")
    exchange = [r for r in rows if r["scheme"] == "shooters" and r["status"] == "ok"]
    paper_v0 = [r for r in rows if r["scheme"] == "receivers" and r["status"] == "ok"
                and r["V"] == 0 and r["R"] > 1]
    per_shot = max((r["bytes_per_shot"] for r in exchange), default=0)
    paper_per_shot = max((r["bytes_per_shot"] for r in paper_v0), default=0)
    wire = max((r["wire_share"] for r in exchange), default=0)
    shots = [pick(rows, scene, "shooters", n)["shots"] / best_receivers(rows, scene, n)["shots"]
             for scene, n, _, _ in pairs]
    parts.append(f". The exchange itself is not what costs: up to {fmt_bytes(per_shot)} a shot "
                 f"against the paper's at most {fmt_bytes(paper_per_shot)} (V = 0: its shooter "
                 f"candidates and decisions), yet at most {100 * wire:.2f} % of the simulated "
                 "time on the busiest node's links"
                 + ("; the shooters lose time by shooting more, R shooters at once chosen from "
                    "the unshot radiosities of the iteration's start "
                    f"({min(shots):.2f}x to {max(shots):.2f}x the paper's shots to "
                    "convergence), each node a whole shot an iteration whatever R"
                    if faster else ""))
    big = sorted({r["scene"] for r in rows if r["scene"] not in ERROR_SCENES})
    per_shot_ratios = [pick(rows, scene, "shooters", n)["simulated_seconds"]
                       / pick(rows, scene, "receivers", n)["simulated_seconds"]
                       for scene in big for n in NODE_COUNTS
                       if pick(rows, scene, "shooters", n) and pick(rows, scene, "receivers", n)
                       and pick(rows, scene, "shooters", n)["status"] == "ok"
                       and pick(rows, scene, "receivers", n)["status"] == "ok"]
    if per_shot_ratios:
        parts.append(f". A shot costs the shooters no more: for the first 64 shots of "
                     f"{' and '.join(big)} they take {min(per_shot_ratios):.2f}x to "
                     f"{max(per_shot_ratios):.2f}x the paper's time at V = 0 (with "
                     "--unlimited-memory)")
    never = [s for s in big if smallest_fitting_R(rows, s, "shooters") is None
             and any(r["scene"] == s and r["scheme"] == "shooters" for r in rows)]
    if never:
        parts.append(". What the claim buys is memory: the shooters hold the whole scene on "
                     "every node and run out of a 4 MB node at every R on "
                     + " and ".join(never) + " (exit 3), which the paper's program runs from "
                     + " and ".join(f"R = {smallest_fitting_R(rows, s, 'receivers')} ({s})"
                                    for s in never))
    return "".join(parts) + "."


def markdown(rows, levels, host=None):
    cap = 4 * 2**20
    out = ["## Claim 2: receivers against shooters", "",
           "Written by `analysis/claims_schemes.py` from `experiments/claims/schemes.yaml` "
           "(docs/model.md, \"The shooter-centred scheme\"). `receivers`: the paper's program; "
           "`shooters`: the shooter-centred scheme of section 2.2's earlier work, one shooter "
           "per node and iteration, the radiosity increments summed over all nodes by recursive "
           "doubling. Ray-traced form factors (M = 64 on the scenes with a reference; scene2 and "
           "scene3 at M = 16 for host time: less computing a shot, so the exchange's share "
           "there is larger than at M = 64); nCube2 nodes of 4 MB. R is at most the "
           "scene's patches (the Cornell box 17, scene0 52), so the shooters reach 16 and 32 "
           "nodes there and the paper's program 64 only with V > 0. Times are simulated "
           "seconds; † marks a run with `--unlimited-memory` (its node could not hold it). "
           "scene2 and scene3 run their first 64 shots only (to convergence costs minutes of "
           "host time a cell: docs/model.md).", ""]
    if host is not None:
        runs, summed, wall = host
        out += [f"Host time: {runs} runs of ./simulate in the results folder's claims/schemes/ "
                f"(cells, twins, checkpoints), {summed:.0f} s summed over their result files' "
                "host_seconds"
                + (f"; {wall:.0f} s wall from an empty results folder, two runs at once"
                   if wall is not None else "") + ".", ""]
    out += ["![speedup](figures/claims_schemes_speedup.png)", "",
            "Speedup: one node's simulated time (the paper's program at R = 1, †: beyond "
            "memory) over the time on N nodes; to convergence on the Cornell box and scene0, "
            "for the first 64 shots on scene2 and scene3.", ""]
    for scene in ERROR_SCENES:
        if scene not in levels:
            continue
        level, converged, anchor_R, anchor_V = levels[scene]
        out += [f"### {scene}: to convergence and to a fixed error", "",
                f"Fixed error: element RMS at most {level:.4f} ({ERROR_FACTOR} x the paper's "
                f"converged {converged:.4f} at R = {anchor_R}, V = {anchor_V}, against "
                f"`analysis/reference/{scene}.json`); the time is that of the first "
                "`--iterations` checkpoint that reaches it (an iteration is a shot for the "
                "paper's program, R shots for the shooters).", "",
                "| nodes | scheme | R | V | iterations (shots) | s to convergence | "
                "s to the error (iteration) | bytes / iteration | bytes / shot | wire share | "
                "waiting | memory / node |",
                "|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
        for n in NODE_COUNTS:
            for name, points in lines_of(rows, scene).items():
                row = points.get(n)
                if row is None:
                    out.append(f"| {n} | {name} | — ({why_missing(rows, scene, name, n)}) "
                               "| — | — | — | — | — | — | — | — | — |")
                    continue
                if name == "receivers, best R x (V + 1)" and row["V"] == 0:
                    continue    # the V = 0 row above
                to = row.get("to_error")
                to_text = "not reached" if to is None else f"{to[1]:.1f} ({to[0]})"
                out.append(f"| {n} | {row['scheme']} | {row['R']} | {row['V']} | "
                           f"{row['iterations']} ({row['shots']}) | {fmt_time(row)} | {to_text} | "
                           f"{fmt_bytes(row['bytes_per_iteration'])} | "
                           f"{fmt_bytes(row['bytes_per_shot'])} | "
                           f"{100 * row['wire_share']:.2f} % | {100 * row['wait_share']:.0f} % | "
                           f"{memory_cell(row, cap)} |")
        out.append("")
    for scene in sorted({r["scene"] for r in rows} - set(ERROR_SCENES)):
        samples = sorted({r["samples"] for r in rows if r["scene"] == scene})
        out += [f"### {scene}: memory and the first 64 shots (M = "
                f"{', '.join(map(str, samples))})", "",
                "| nodes | scheme | R | fits 4 MB | memory / node | s for 64 shots | "
                "bytes / iteration | bytes / shot | wire share |",
                "|---:|---|---:|---|---:|---:|---:|---:|---:|"]
        for n in (1,) + NODE_COUNTS:
            for scheme in ("receivers", "shooters"):
                capped = [r for r in rows if r["scene"] == scene and r["scheme"] == scheme
                          and r["R"] == n and r["V"] == 0 and not r["beyond_memory"]]
                if not capped:
                    continue
                row = capped[0]
                shown = pick(rows, scene, scheme, n)
                fits = "yes" if row["status"] == "ok" else "no (exit 3)"
                out.append(f"| {n} | {scheme} | {n} | {fits} | "
                           f"{row['peak_memory_bytes'] / 2**20:.2f} MB | "
                           f"{fmt_time(shown)} | {fmt_bytes(shown['bytes_per_iteration'])} | "
                           f"{fmt_bytes(shown['bytes_per_shot'])} | "
                           f"{100 * shown['wire_share']:.2f} % |")
        out.append("")
    checks = [r for r in rows if r["scheme"] == "shooters" and r["status"] == "ok"]
    wrong = [r for r in checks if abs(r["bytes_per_iteration"]
                                      - exchange_formula(r["R"], r["elements"])) > 0.5]
    out += ["### The shooters' exchange against docs/model.md's formula", "",
            "Bytes an iteration over the machine, R x log2 R x (12 x elements + 8) for R a "
            "power of two: "
            + (f"all {len(checks)} shooters runs agree with it to the byte." if not wrong else
               "**differs** in " + ", ".join(f"{r['scene']} R = {r['R']} "
                                             f"({r['bytes_per_iteration']:.0f} against "
                                             f"{exchange_formula(r['R'], r['elements'])})"
                                             for r in wrong) + "."),
            "", verdict(rows), ""]
    return "\n".join(out)


def section(results_root, jobs=2, sweep_file=SWEEP, figure=FIGURE):
    """The markdown section (claims.py includes it in analysis/claims.md); runs what is
    missing under results_root/claims/schemes/ and writes the speedup figure."""
    started = time.monotonic()
    folder = Path(results_root).resolve() / "claims" / "schemes"
    fresh = not folder.exists() or not any(folder.glob("*.json"))
    rows, levels = measure(results_root, jobs, sweep_file)
    plot(rows, [s for s in ERROR_SCENES if any(r["scene"] == s for r in rows)]
         + sorted({r["scene"] for r in rows} - set(ERROR_SCENES)), figure)
    # The wall time from an empty folder, kept beside the cells for the runs that reuse them.
    wall_file = folder / "wall-seconds-from-empty.txt"
    if fresh:
        wall_file.write_text(f"{time.monotonic() - started:.0f}\n")
    runs = [json.loads(p.read_text()) for p in folder.glob("*.json")]
    host = (len(runs), sum(r["host_seconds"] for r in runs),
            float(wall_file.read_text()) if wall_file.exists() else None)
    return markdown(rows, levels, host)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--results", type=Path, default=ROOT / "results")
    parser.add_argument("--jobs", type=int, default=2, help="cells run at once")
    parser.add_argument("--sweep", type=Path, default=SWEEP)
    parser.add_argument("--figure", type=Path, default=FIGURE)
    args = parser.parse_args()
    page.will_run("claims_schemes.py", f"the cells of {page.shown(args.sweep)} without a result "
                  f"in {page.shown(args.results)}/claims/schemes/ itself")
    try:
        print(section(args.results, args.jobs, args.sweep, args.figure))
    except sweep.SweepError as e:
        print(f"claims_schemes: {e}", file=sys.stderr)
        return 2
    except (CellFailed, accuracy.AccuracyError) as e:
        print(f"claims_schemes: {e}", file=sys.stderr)
        return 4
    return 0


if __name__ == "__main__":
    sys.exit(main())
