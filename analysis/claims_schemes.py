#!/usr/bin/python3
"""The paper's claim 2, measured: the paper's
parallelisation (receivers) against the shooter-centred schemes it replaced: `circulation`, built
from the abstracts of Çapın, Aykanat & Özgüç, and `shooters`, the project's own construction kept
as a variant; on 4 to 64 nodes, with --shooters-per-iteration swept at 16 nodes.

Reads experiments/claims/schemes.yaml with the sweep tool's own loader (its validation,
defaults and cell identity), runs every cell's ./simulate command itself (one host thread,
two cells at once), and keeps each result under RESULTS/claims/schemes/ named after the cell's
identity: a finished cell is not run again, a changed option or input is another cell. Beside
the sweep's cells it runs, as further cells of the same identity rule:
  - an --unlimited-memory twin of every cell that ran out of memory (exit 3), so that the
    time beyond memory is shown, marked as such;
  - on the scenes with a reference (analysis/reference/<scene>.json), --iterations
    checkpoints with --mesh, one after every iteration from the first on (no bisection: the
    error is measured after every shot a node holds, and the first checkpoint at or below the
    level is the time to it, whether or not the error falls steadily), up to the first one
    below the level minus the reference's own error (the band's late end). The level is fixed
    before the runs by a rule that needs light transport (docs/accuracy.md, "Claim 2's fixed
    error"): 1/ERROR_DIVISOR of the element error of the solution without light transport
    (B = E everywhere) under the one error measure (analysis/ncube/error_measure.py). An
    iteration is one shot for the paper's program and S shots for the shooter schemes, whose
    nodes hold no solution between the iteration's exchanges: every state a node of any
    scheme ever holds is a checkpoint (docs/model.md, "The study").
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
from ncube import accuracy, error_parts, page, paths, sweep  # noqa: E402

ROOT = paths.ROOT
SWEEP = ROOT / "experiments" / "claims" / "schemes.yaml"
FIGURE = ROOT / "analysis" / "figures" / "claims_schemes_speedup.png"
ERROR_SCENES = ("cornell-box", "scene0")
# The fixed error (docs/accuracy.md, "Claim 2's fixed error", chosen before the study's runs):
# a third of the element error of the solution without light transport (B = E). The first shot
# (the light's) leaves every surface it does not see black, each such element at the measure's
# largest error: its error is above the level plus the band (checked and shown on the page), so
# reaching the level takes light passed on between surfaces; and every scheme's converged
# answer is below the level minus the band (shown too), so every scheme reaches it.
ERROR_DIVISOR = 3
# The shooter-centred schemes, circulation first (it decides the claim).
OPPONENTS = ("circulation", "shooters")
OPPONENT = "circulation"
SWEPT_NODES = 16            # --shooters-per-iteration is swept at this node count
NODE_COUNTS = (4, 8, 16, 32, 64)
# The message sizes of platforms/cost_model.json, for the exchanges' formulas.
_COSTS = json.loads((ROOT / "platforms" / "cost_model.json").read_text())["parameters"]
INCREMENT_BYTES = _COSTS["radiosity_increment_bytes"]["value"]
HEADER_BYTES = _COSTS["message_header_bytes"]["value"]
SHOOTER_RECORD_BYTES = _COSTS["shooter_record_bytes"]["value"]
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
    given_S = o.get("shooters_per_iteration", 0)
    return {"scene": cell.scene, "scheme": o["parallelisation"], "R": o["R"], "V": o["V"],
            "S": given_S or (o["R"] if o["parallelisation"] in OPPONENTS else 1),
            "default_S": given_S == 0,
            "nodes": o["R"] * (o["V"] + 1), "status": result["status"],
            "beyond_memory": beyond_memory, "converged": result["converged"],
            "iterations": iterations, "shots": shots, "elements": result["scene"]["elements"],
            "patches": result["scene"]["patches"], "samples": o["samples"],
            "simulated_seconds": result["simulated_seconds"],
            "bytes_sent": sent,
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


def times_to_error(cell, total_iterations, level, band, folder, reference, reference_path):
    """The error after every --iterations checkpoint from the first on, and for the level and
    the level plus and minus the reference's error ("to_error", "to_error_early",
    "to_error_late"): (iteration, simulated seconds, element error) of the first checkpoint at
    or below it, None if the converged run is not. Stops at the first checkpoint below the
    lowest level (or at the whole run). One job: checkpoints are cells, run once, and two jobs
    must never run the same cell at once. Also "after_first": the error after the first
    iteration, and "errors": every checkpoint's (iteration, seconds, error)."""
    targets = {"to_error_early": level + band, "to_error": level, "to_error_late": level - band}
    found = dict.fromkeys(targets)
    errors = []
    for k in range(1, total_iterations + 1):
        # The whole run is the cell itself (already run with its mesh), not a twin of it.
        checkpoint = cell if k == total_iterations else variant(cell, iterations=k)
        result_path, mesh = run_cell(checkpoint, folder, mesh=True)
        seconds = json.loads(result_path.read_text())["simulated_seconds"]
        error = element_error(mesh, reference, reference_path)
        errors.append((k, seconds, error))
        for key, at in targets.items():
            if found[key] is None and error <= at:
                found[key] = (k, seconds, error)
        if found["to_error_late"] is not None:
            break
    return dict(found, after_first=errors[0][2] if errors else None, errors=errors)


def no_transport_error(reference, reference_path, scene_file):
    """The element error of the solution without light transport: every element its patch's
    emission (B = E), under the one measure."""
    emission, _ = error_parts.scene_materials(scene_file)   # through the read gate
    solution = [(e[0], tuple(emission[e[0]])) for e in reference["elements"]]
    return accuracy.compare(solution, reference, "B = E", str(reference_path))["element_rms"]


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
            no_transport = no_transport_error(reference, reference_path,
                                              ROOT / "scenes" / f"{scene}.json")
            band = reference_error(reference)
            levels[scene] = (no_transport / ERROR_DIVISOR, converged_error, anchor.R,
                             anchor.V, band, no_transport)
            for cell, row in mine:
                if row["status"] == "ok" and row["converged"] and row["nodes"] in NODE_COUNTS \
                        and shown_row(row, rows):
                    jobs_.append((row, pool.submit(times_to_error, cell, row["iterations"],
                                                   levels[scene][0], band, folder, reference,
                                                   reference_path)))
        for row, future in jobs_:
            row.update(future.result())
    return rows, levels


def reference_error(reference):
    """The reference's own error as an element RMS (its file's self_agreement: K/4 against K
    samples); the level is uncertain by as much, since an RMS against a reference off by d
    differs from the RMS against the truth by at most d (the triangle inequality)."""
    return reference["self_agreement"]["element_rms"]


def band_of(row):
    """(earliest, latest) simulated seconds to the error, the level plus and minus the
    reference's error; latest None when the lower level is not reached."""
    early, late = row.get("to_error_early"), row.get("to_error_late")
    return (early[1] if early else None, late[1] if late else None)


def best_receivers(rows, scene, nodes):
    """The paper's program at its fastest R x (V + 1) = nodes (converged runs within memory)."""
    candidates = [r for r in rows if r["scene"] == scene and r["scheme"] == "receivers"
                  and r["nodes"] == nodes and r["status"] == "ok" and not r["beyond_memory"]]
    return min(candidates, key=lambda r: r["simulated_seconds"], default=None)


def shown_row(row, rows):
    """Rows the tables show: every shooters row, the paper's at V = 0, and its best per count."""
    if row["scheme"] in OPPONENTS or row["V"] == 0:
        return True
    return best_receivers(rows, row["scene"], row["nodes"]) is row


def pick(rows, scene, scheme, R, V=0):
    """The row (within memory if it fits, else its --unlimited-memory twin), at the default S."""
    mine = [r for r in rows if r["scene"] == scene and r["scheme"] == scheme and r["R"] == R
            and r["V"] == V and r.get("default_S", True)]
    fits = [r for r in mine if r["status"] == "ok" and not r["beyond_memory"]]
    return (fits or [r for r in mine if r["beyond_memory"]] or mine or [None])[0]


def baseline(rows, scene):
    """One node running the paper's program (beyond memory where a node cannot hold it)."""
    return pick(rows, scene, "receivers", 1)


def lines_of(rows, scene):
    """The four compared lines of a scene: {name: {nodes: row}}."""
    lines = {"receivers, V = 0": {}, "receivers, best R x (V + 1)": {}, "circulation": {},
             "shooters": {}}
    for n in NODE_COUNTS:
        for name, row in (("receivers, V = 0", pick(rows, scene, "receivers", n)),
                          ("receivers, best R x (V + 1)", best_receivers(rows, scene, n)),
                          ("circulation", pick(rows, scene, "circulation", n)),
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
    from ncube import plotting   # matplotlib (1 s a start) where the figure is drawn, not before
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, len(scenes), figsize=(4.6 * len(scenes), 4), squeeze=False,
                             layout="constrained")
    for ax, scene in zip(axes[0], scenes):
        base = baseline(rows, scene)
        # Fixed colours and markers per line (the V = 0 line hollow and larger, as the best
        # R x (V + 1) line lies on it wherever V = 0 is best).
        for (name, points), (style, colour, size) in zip(
                lines_of(rows, scene).items(),
                (("o-", "tab:blue", 9), ("s--", "tab:orange", 5), ("D-", "tab:red", 6),
                 ("^-", "tab:green", 6))):
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


def opponent_at(rows, scene, scheme, nodes, measure):
    """The shooter scheme at `nodes` at its best --shooters-per-iteration for `measure`: of its
    rows there (the default S, and the swept S at SWEPT_NODES) within memory, the earliest to
    the fixed error ("error"; None if none reaches it) or to convergence ("convergence")."""
    mine = [r for r in rows if r["scene"] == scene and r["scheme"] == scheme
            and r["R"] == nodes and r["V"] == 0 and r["status"] == "ok"
            and not r["beyond_memory"]]
    if measure == "error":
        mine = [r for r in mine if r.get("to_error")]
        return min(mine, key=lambda r: (r["to_error"][1], r["S"]), default=None)
    return min(mine, key=lambda r: (r["simulated_seconds"], r["S"]), default=None)


def comparisons(rows, scheme=OPPONENT):
    """One dict per node count where the paper's program (at its best R x (V + 1)) and
    `scheme` (at its best S) both converged within memory: the opponent's time over the
    paper's to convergence, and to the fixed error with its band (lowest, highest: the
    opponent's earliest over the paper's latest and the reverse; None where a band end is
    not reached)."""
    out = []
    for scene in ERROR_SCENES:
        for n in NODE_COUNTS:
            paper = best_receivers(rows, scene, n)
            other = opponent_at(rows, scene, scheme, n, "convergence")
            if paper is None or other is None:
                continue
            c = {"scene": scene, "nodes": n, "R": other["R"], "paper": paper, "other": other,
                 "S": {"convergence": other["S"]},
                 "convergence": other["simulated_seconds"] / paper["simulated_seconds"],
                 "error": None, "error_band": (None, None)}
            fastest = opponent_at(rows, scene, scheme, n, "error")
            if paper.get("to_error") and fastest is not None:
                c["S"]["error"] = fastest["S"]
                c["error"] = fastest["to_error"][1] / paper["to_error"][1]
                (o_early, o_late), (p_early, p_late) = band_of(fastest), band_of(paper)
                # A band end not reached is infinitely late: the ratio's low end then 0, its
                # high end unbounded (None).
                c["error_band"] = (o_early / p_late if p_late else 0.0,
                                   o_late / p_early if o_late else None)
            out.append(c)
    return out


def judged(c, which):
    """'faster' (the opponent faster beyond TIE, over the whole band), 'not faster' (the
    opponent not faster beyond TIE, over the whole band), or 'undecided' (the band straddles)."""
    if which == "convergence":   # deterministic: no reference enters it
        low = high = c["convergence"]
    else:
        low, high = c["error_band"]
    if high is not None and high < 1 - TIE:
        return "faster"
    if low >= 1 - TIE:
        return "not faster"
    return "undecided"


def fmt_ratio(c, which):
    if which == "convergence":
        return f"{c['convergence']:.2f}x"
    low, high = c["error_band"]
    return (f"{c['error']:.2f}x [{low:.2f}, "
            f"{'unbounded' if high is None else f'{high:.2f}'}]")


def fmt_span(values):
    low, high = f"{min(values):.2f}x", f"{max(values):.2f}x"
    return low if low == high else f"{low} to {high}"


def fitting_Rs(rows, scene, scheme):
    return ", ".join(str(R) for R in sorted({r["R"] for r in rows if r["scene"] == scene
                                             and r["scheme"] == scheme and r["V"] == 0
                                             and r["status"] == "ok" and not r["beyond_memory"]
                                             and r.get("default_S", True)}))


def smallest_fitting_R(rows, scene, scheme):
    fits = [r["R"] for r in rows if r["scene"] == scene and r["scheme"] == scheme
            and r["V"] == 0 and r["status"] == "ok" and not r["beyond_memory"]]
    return min(fits, default=None)


def verdict(rows):
    """The claim's sentence, from the figures, decided against the circulation opponent
    (circulation) at its best S: holds when the paper's program is nowhere slower (a ratio
    within TIE of 1 counts as level; to the error, over the whole band of the reference's
    error), does not hold when it is slower everywhere, holds only where the opponent is not
    faster otherwise; the points the band leaves open are named."""
    pairs = comparisons(rows, OPPONENT)
    if not pairs:
        return "Claim 2 is not measured: no node count where both schemes converged in memory."
    points = [(c, which) for c in pairs for which in ("error", "convergence")
              if which == "convergence" or c["error"] is not None]
    state = {(id(c), which): judged(c, which) for c, which in points}
    faster = [(c, w) for c, w in points if state[(id(c), w)] == "faster"]
    level = [(c, w) for c, w in points if state[(id(c), w)] == "not faster"]
    open_ = [(c, w) for c, w in points if state[(id(c), w)] == "undecided"]
    head = ("holds" if not faster and not open_ else
            "does not hold" if faster and not level else
            "holds only where circulation is not faster" if faster else
            "is not decided")
    where = lambda c, w: (f"{c['scene']} at {c['nodes']} nodes to {w} ({fmt_ratio(c, w)}, "
                          f"S = {c['S'][w]})")
    parts = ["Claim 2 (no need to distribute radiosity values after the form factors), held "
             f"against circulation, a shooter-centred scheme built from the abstracts of Çapın, "
             f"Aykanat & Özgüç (at its best S), "
             f"**{head}**: on {len(pairs)} node count{'s' if len(pairs) > 1 else ''} of "
             + " and ".join(sorted({c['scene'] for c in pairs}))
             + f", the paper's program is not slower (within {100 * TIE:.0f} %) at "
             f"{len(level)} of {len(points)} points"]
    if faster:
        parts.append("; circulation is faster at " + ", ".join(where(c, w) for c, w in faster))
    if open_:
        parts.append("; the reference's error band leaves open " +
                     ", ".join(where(c, w) for c, w in open_))

    def span(cs, which):
        values = [c[which] for c in cs if c[which] is not None]
        return fmt_span(values) if values else "not measured"
    parts.append(f". Circulation takes {span(pairs, 'error')} the paper's time to the fixed "
                 f"error and {span(pairs, 'convergence')} its time to convergence")
    variant = comparisons(rows, "shooters")
    if variant:
        parts.append(f"; the `shooters` variant {span(variant, 'error')} and "
                     f"{span(variant, 'convergence')}")
    shots = [c["other"]["shots"] / c["paper"]["shots"] for c in pairs]
    parts.append(f". At its fastest S to convergence circulation shoots {fmt_span(shots)} the "
                 "paper's shots (several shooters chosen at once from the unshot radiosities of "
                 "the iteration's start)")
    first = [c for c in pairs if c["error"] is not None and c["paper"]["to_error"][0] == 1]
    if first:
        parts.append(f"; where one shot reaches the fixed error ("
                     + ", ".join(f"{c['scene']} at {c['nodes']} nodes" for c in first)
                     + "), the time to it is the light's shot alone, which the paper's program "
                     "shares among its radiosity processors and a shooter-centred node computes "
                     "alone")
    ring = [r for r in rows if r["scheme"] == OPPONENT and r["status"] == "ok"]
    paper_v0 = [r for r in rows if r["scheme"] == "receivers" and r["status"] == "ok"
                and r["V"] == 0 and r["R"] > 1]
    if ring and paper_v0:
        parts.append(f"; it sends up to {fmt_bytes(max(r['bytes_per_shot'] for r in ring))} a "
                     f"shot against the paper's at most "
                     f"{fmt_bytes(max(r['bytes_per_shot'] for r in paper_v0))} (V = 0), at most "
                     f"{100 * max(r['wire_share'] for r in ring):.2f} % of the simulated time "
                     "on the busiest node's links")
    big = sorted({r["scene"] for r in rows if r["scene"] not in ERROR_SCENES})
    for scheme in OPPONENTS:
        never = [s for s in big if smallest_fitting_R(rows, s, scheme) is None
                 and any(r["scene"] == s and r["scheme"] == scheme for r in rows)]
        fits = [(s, smallest_fitting_R(rows, s, scheme)) for s in big
                if smallest_fitting_R(rows, s, scheme) is not None]
        if never:
            parts.append(f". `{scheme}` holds the whole scene on every node and runs out of a "
                         "4 MB node at every R on " + " and ".join(never) + " (exit 3)")
        elif fits and scheme == OPPONENT:
            parts.append(". Memory does not decide it against circulation: on "
                         + " and ".join(f"{s} it fits at R = {fitting_Rs(rows, s, scheme)}, the "
                                        f"paper's program at R = {fitting_Rs(rows, s, 'receivers')}"
                                        for s, _ in fits) + " (V = 0, of the R run)")
    return "".join(parts) + "."


def markdown(rows, levels, host=None):
    cap = 4 * 2**20
    out = ["## Claim 2: receivers against shooter-centred schemes", "",
           "Written by `analysis/claims_schemes.py` from `experiments/claims/schemes.yaml` "
           "(docs/model.md, \"The shooter-centred scheme\" and \"The circulation opponent\"). "
           "`receivers`: the paper's program. `circulation`: the opponent, built from the abstracts of Çapın, "
           "Aykanat & Özgüç's scheme (Parallel Rendering Symposium 1993; Computers & Graphics "
           "1996) as far as its abstracts say it: static shares of the patches, every node's "
           "best patch shot at once, the light distributed round a ring (what is sourced and "
           "what is assumed: docs/model.md). `shooters`: the project's own earlier "
           "construction, kept as a variant (the S best patches of the whole scene shot at "
           "once, whole increment vectors summed by recursive doubling). Ray-traced form "
           "factors (M = 64 on the scenes with a reference; scene2 at M = 16 for host time: "
           "less computing a shot, so the exchange's share there is larger than at M = 64); "
           "nCube2 nodes of 4 MB. R is at most the scene's patches (the Cornell box 17, scene0 "
           "52), so the shooter schemes reach 16 and 32 nodes there and the paper's program 64 "
           "only with V > 0. Times are simulated seconds; † marks a run with "
           "`--unlimited-memory` (its node could not hold it).", "",
           "**The quantity.** Simulated seconds to convergence (the paper's criterion, 1e-4 "
           "of the emitted power) and to a fixed error, and their ratios, opponent over the "
           "paper's program at its best R x (V + 1), for the same node count. Both are "
           "deterministic: a rerun gives the same seconds to the last digit (no random "
           "number enters a run: the rays' parts are fixed), so there is no sampling interval. "
           "The time to the error rests on the reference, whose own error (its K/4 against K "
           "self-agreement, element RMS) moves the level: the band [earliest, latest] is the "
           "time to the level plus and minus that error, and a ratio's band pairs the "
           "opponent's earliest with the paper's latest and the reverse. A point is decided "
           "only when the whole band is on one side of 1 ± 1 %.", ""]
    if host is not None:
        runs, summed, wall = host
        out += [f"Host time: {runs} runs of ./simulate in the results folder's claims/schemes/ "
                f"(cells, twins, checkpoints), {summed:.0f} s summed over their result files' "
                "host_seconds (each run's wall seconds on the machine it ran on, loaded or not; "
                "the study's CPU time from an empty folder: docs/reproduce.md)"
                + (f"; {wall:.0f} s wall from an empty results folder, two runs at once"
                   if wall is not None else "") + ".", ""]
    out += ["![speedup](figures/claims_schemes_speedup.png)", "",
            "Speedup: one node's simulated time (the paper's program at R = 1, †: beyond "
            "memory) over the time on N nodes; to convergence on the Cornell box and scene0, "
            "for the first 64 shots on scene2.", ""]
    for scene in ERROR_SCENES:
        if scene not in levels:
            continue
        level, converged, anchor_R, anchor_V, band, no_transport = levels[scene]
        anchor = next((r for r in rows if r["scene"] == scene and r["scheme"] == "receivers"
                       and r["R"] == anchor_R and r["V"] == anchor_V and r.get("after_first")
                       is not None), None)
        out += [f"### {scene}: to convergence and to a fixed error", "",
                f"Fixed error (chosen before the runs, docs/accuracy.md): element error at most "
                f"{level:.4f}, 1/{ERROR_DIVISOR} of the {no_transport:.4f} of the solution "
                f"without light transport (B = E) against `analysis/reference/{scene}.json` "
                "(the one error measure, analysis/ncube/error_measure.py)"
                + (f"; the paper's program after its first shot (the light's; R = {anchor_R}, "
                   f"V = {anchor_V}) is at {anchor['after_first']:.4f}, above it, so reaching it "
                   "takes light passed on between surfaces" if anchor else "")
                + f"; converged, the paper's program is at {converged:.4f} (R = {anchor_R}, "
                f"V = {anchor_V}). The band is the time to {level + band:.4f} and to "
                f"{level - band:.4f} (the level plus and minus the reference's own error "
                f"{band:.4f}). The error is measured after every iteration from the first on "
                "(an iteration is a shot for the paper's program, S shots for the shooter "
                "schemes, whose nodes hold no solution between two exchanges); the time is that "
                "of the first checkpoint at or below the level.", "",
                "| nodes | scheme | R | V | iterations (shots) | s to convergence | "
                "s to the error (iteration) | bytes / iteration | bytes / shot | wire share | "
                "waiting | memory / node | band of s to the error |",
                "|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
        for n in NODE_COUNTS:
            for name, points in lines_of(rows, scene).items():
                row = points.get(n)
                if row is None:
                    out.append(f"| {n} | {name} | — ({why_missing(rows, scene, name, n)}) "
                               "| — | — | — | — | — | — | — | — | — | — |")
                    continue
                if name == "receivers, best R x (V + 1)" and row["V"] == 0:
                    continue    # the V = 0 row above
                out.append(table_row(row, cap))
        out.append("")
        swept = [r for r in rows if r["scene"] == scene and r["scheme"] in OPPONENTS
                 and r["R"] == SWEPT_NODES and r["V"] == 0]
        if any(not r["default_S"] for r in swept):
            out += [f"{scene}, --shooters-per-iteration S at {SWEPT_NODES} nodes (S = "
                    f"{SWEPT_NODES}: one a node, the default, as above):", "",
                    "| S | scheme | iterations (shots) | s to convergence | s to the error "
                    "(iteration) | band of s to the error |", "|---:|---|---:|---:|---:|---:|"]
            for r in sorted(swept, key=lambda r: (OPPONENTS.index(r["scheme"]), r["S"])):
                to = r.get("to_error")
                out.append(f"| {r['S']} | {r['scheme']} | {r['iterations']} ({r['shots']}) | "
                           f"{fmt_time(r)} | "
                           f"{'not reached' if to is None else f'{to[1]:.1f} ({to[0]})'} | "
                           f"{fmt_band(r)} |")
            out.append("")
    for scene in sorted({r["scene"] for r in rows} - set(ERROR_SCENES)):
        samples = sorted({r["samples"] for r in rows if r["scene"] == scene})
        out += [f"### {scene}: memory and the first 64 shots (M = "
                f"{', '.join(map(str, samples))})", "",
                "| nodes | scheme | R | fits 4 MB | memory / node | s for 64 shots | "
                "bytes / iteration | bytes / shot | wire share |",
                "|---:|---|---:|---|---:|---:|---:|---:|---:|"]
        for n in (1,) + NODE_COUNTS:
            for scheme in ("receivers",) + OPPONENTS:
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
    out += exchange_checks(rows)
    out += ["### Decision", "", verdict(rows), "",
            "**What it rests on.** The simulated nCube2 (docs/model.md: its calibrated cost "
            "model and network) running each scheme's node program; the same ray-traced form "
            "factors in all three, so a shot's light is the same computation and only the "
            "order of shots, the messages and the memory differ; the references of "
            "`analysis/reference/` for the fixed error.", "",
            "**Threats to validity.**", "",
            "- The opponent is built from abstracts only (no paper text was "
            "reachable): its static assignment, its ring, several shooters at once and the "
            "circulated light distribution are sourced; the shares (the paper's partition by "
            "elements), the whole scene's geometry on every node, the candidates' ring and the "
            "data that circulate are assumed (docs/model.md). A different reading, for example "
            "geometry circulated instead of replicated, changes its memory and bytes, not its "
            "shots.",
            "- Feda & Purgathofer and Recker et al. used hemicubes (Çapın et al.'s abstracts "
            "do not say which form factors); all schemes here use the paper's ray-traced form "
            "factors, so claim 2 is measured on the parallelisation alone, not on the form "
            "factors' cost.",
            f"- The fixed error is 1/{ERROR_DIVISOR} of the error of no light transport: a level "
            "every scheme reaches and none reaches with the light's shot alone; a stricter "
            "level would favour whichever converges closer to the reference, and the band "
            "bounds the level's own uncertainty only through the reference's self-agreement (a "
            "bias shared by the reference's samples is not in it: docs/accuracy.md).",
            "- Two small scenes (17 and 52 patches) decide it; "
            + " and ".join(f"{scene} ({next(r['patches'] for r in rows if r['scene'] == scene)} "
                           f"patches, M = {', '.join(str(m) for m in sorted({r['samples'] for r in rows if r['scene'] == scene}))})"
                           for scene in sorted({r["scene"] for r in rows} - set(ERROR_SCENES)))
            + " run their first 64 shots only, for memory and the cost of a shot.",
            "- The time to the error is known at the checkpoints only: after every iteration, "
            "so for the shooter schemes after every S shots (their nodes hold no solution in "
            "between).",
            "- Simulated seconds depend on the calibrated cost model: a machine with cheaper "
            "messages relative to computing would narrow the exchange's cost, which is small "
            "here anyway (wire share above).", ""]
    return "\n".join(out)


def fmt_band(row):
    early, late = band_of(row)
    if row.get("to_error") is None:
        return "—"
    return (f"[{'—' if early is None else f'{early:.1f}'}, "
            f"{'not reached' if late is None else f'{late:.1f}'}]")


def table_row(row, cap):
    to = row.get("to_error")
    to_text = "not reached" if to is None else f"{to[1]:.1f} ({to[0]})"
    return (f"| {row['nodes']} | {row['scheme']} | {row['R']} | {row['V']} | "
            f"{row['iterations']} ({row['shots']}) | {fmt_time(row)} | {to_text} | "
            f"{fmt_bytes(row['bytes_per_iteration'])} | "
            f"{fmt_bytes(row['bytes_per_shot'])} | "
            f"{100 * row['wire_share']:.2f} % | {100 * row['wait_share']:.0f} % | "
            f"{memory_cell(row, cap)} | {fmt_band(row)} |")


def circulation_formula(R, elements):
    """docs/model.md's bytes of one iteration of the circulation scheme over the machine,
    without the candidates' ring: each owner's block (12 bytes an element plus the 8-byte
    header) passes R - 1 hops, (R - 1) (12 E + 8 R)."""
    return (R - 1) * (elements * INCREMENT_BYTES + HEADER_BYTES * R)


def exchange_checks(rows):
    out = ["### The exchanges against docs/model.md's formulas", ""]
    checks = [r for r in rows if r["scheme"] == "shooters" and r["status"] == "ok"
              and r["default_S"]]
    wrong = [r for r in checks if abs(r["bytes_per_iteration"]
                                      - exchange_formula(r["R"], r["elements"])) > 0.5]
    out.append("`shooters`, bytes an iteration over the machine, R x log2 R x (12 x elements "
               "+ 8) for R a power of two: "
               + (f"all {len(checks)} shooters runs at the default S agree with it to the byte."
                  if not wrong else
                  "**differs** in " + ", ".join(f"{r['scene']} R = {r['R']} "
                                                f"({r['bytes_per_iteration']:.0f} against "
                                                f"{exchange_formula(r['R'], r['elements'])})"
                                                for r in wrong) + "."))
    ring = [r for r in rows if r["scheme"] == OPPONENT and r["status"] == "ok"]
    candidate = SHOOTER_RECORD_BYTES + HEADER_BYTES

    def expected(r):   # the light's blocks every iteration, the candidates once more
        return (r["iterations"] * circulation_formula(r["R"], r["elements"])
                + (r["iterations"] + 1) * r["R"] * (r["R"] - 1) * candidate)
    off = [r for r in ring if abs(r["bytes_sent"] - expected(r)) > 0.5]
    out += ["", "`circulation`, bytes of a run over the machine, iterations x (R - 1) x "
            "(12 x elements + 8 R) for the light's blocks plus (iterations + 1) x R x (R - 1) x "
            f"{candidate} for the candidates' ring: "
            + (f"all {len(ring)} circulation runs agree with it to the byte." if not off else
               "**differs** in " + ", ".join(f"{r['scene']} R = {r['R']} S = {r['S']} "
                                             f"({r['bytes_sent']:.0f} against {expected(r):.0f})"
                                             for r in off) + "."), ""]
    return out


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


@page.refusing_outputs("claims_schemes.py")
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
