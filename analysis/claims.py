#!/usr/bin/python3
"""The paper's claims, measured: error against simulated time to convergence.

Reads the sweep files experiments/claims/accuracy*.yaml with the sweep tool's own loader (the
same validation, defaults and cell identity as experiments/sweep), runs every cell's ./simulate
command itself with --mesh added (a sweep cell has no mesh output: docs/accuracy.md, "The
study"), keeps each cell's result and mesh under RESULTS/claims/ named after the cell's
identity (a finished cell is not run again; a changed option or input is another cell), and
compares each mesh with its scene's reference (analysis/reference/<scene>.json, made by
experiments/claims/references) by analysis/ncube/accuracy.py. Writes analysis/claims.md and
the figures under analysis/figures/ it shows (claims_accuracy.png, claims_pictures.png,
claims_schemes_speedup.png, claims_cost.png), each where its option (--out, --figure,
--pictures-figure, --schemes-figure, --cost-figure) says: nothing else is written.

  /usr/bin/python3 analysis/claims.py [--results results] [--jobs 2] [--sweeps FILE ...]

A series is a cell's every option but its accuracy knob (samples for ray-traced form factors,
hemicube_resolution for the hemicube), so that the hemicube's and the shooters' cells, added
as further sweep files, become further lines of the same plots and rows of the same tables."""

from ncube.interpreter import use_project_python  # noqa: E402

use_project_python()   # Debian's /usr/bin/python3 (README.md, "Use")

import argparse
import concurrent.futures
import json
import os
import re
import subprocess
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
# numpy (0.1 s of CPU a start) is imported by the functions that use it: a refusal needs none.

from ncube import (accuracy, claim_one, error_parts, page, paths, runner,  # noqa: E402
                   sweep)
from ncube import opening as op  # noqa: E402

ROOT = paths.ROOT
KNOBS = ("samples", "hemicube_resolution")   # the accuracy knob of each form-factor method
# What tells series apart in the legend, in this order, when the sweep sets it.
SERIES_KEYS = ("form_factors", "hemicube_placement", "parallelisation", "R", "V")


def knob(cell):
    """The accuracy knob of the cell's form-factor method, and its value."""
    method = cell.options.get("form_factors", "ray-traced")
    name = "hemicube_resolution" if method == "hemicube" else "samples"
    return name, cell.options.get(name)


def series_of(cell):
    return tuple(sorted((k, json.dumps(v)) for k, v in cell.options.items() if k not in KNOBS))


def series_label(cell):
    o = cell.options
    method = o.get("form_factors", "ray-traced")
    label = method + (f" ({o['hemicube_placement']})" if method == "hemicube" else "")
    if o.get("parallelisation", "receivers") != "receivers":
        label += f", {o['parallelisation']}"
    return label + f", R={o['R']} V={o['V']}"


def run_cell(cell, folder):
    """The cell's result and mesh under `folder`, run now unless both are there."""
    stem = Path(cell.file).stem
    result, mesh = folder / f"{stem}.json", folder / f"{stem}.ply"
    if result.exists() and mesh.exists():
        return result, mesh
    partial_result, partial_mesh = folder / f"{stem}.partial.json", folder / f"{stem}.partial.ply"
    command = cell.command(str(partial_result)) + ["--mesh", str(partial_mesh), "--quiet"]
    run = subprocess.run(command, env=paths.simulate_environment(), capture_output=True, text=True)
    if run.returncode != 0:
        raise RuntimeError(f"{cell.label} ({cell.file}): ./simulate exit {run.returncode}: "
                           f"{run.stderr.strip()}")
    os.replace(partial_mesh, mesh)   # the mesh first: a result alone is not taken as done
    os.replace(partial_result, result)
    return result, mesh


class SceneTruths:
    """Everything a scene's cells are measured against (docs/accuracy.md, "The error taken
    apart"): its materials, the reference (per element, when committed), Cycles' answers (per
    patch), and the exact structures (patches, and every element its own patch)."""

    def __init__(self, scene, scene_sha256):
        import numpy as np
        folder = ROOT / "analysis"
        self.scene = scene
        self.emission, self.reflectance = error_parts.scene_materials(ROOT / "scenes" / f"{scene}.json")
        self.files = {}

        def load(key, path):
            if not path.exists():
                return None
            data = error_parts.read_json(path, key)
            if data.get("scene_sha256") != scene_sha256:
                raise SystemExit(f"claims: {shown(path)} is of another {scene} (its scene_sha256 "
                                 "differs): regenerate it (docs/accuracy.md)")
            self.files[key] = data
            return data

        self.structure_data = load("structure", folder / "reference" / "structure" / f"{scene}-patches.json")
        if self.structure_data is None:
            raise SystemExit(f"claims: no exact structure for {scene}: run "
                             f"experiments/claims/references --structures {scene}")
        self.structure = error_parts.reference_solution(self.structure_data)
        own = load("structure_elements", folder / "reference" / "structure" / f"{scene}-elements.json")
        self.own_data = own
        self.own = error_parts.reference_solution(own) if own else None
        reference = load("reference", folder / "reference" / f"{scene}.json")
        self.reference = error_parts.reference_solution(reference) if reference else None
        self.cycles = load("cycles", folder / "cycles" / f"{scene}.json")
        e = self.emission
        # (b): against the exact structure, widened by its own error (error_parts.own_error).
        own_element, own_patch = error_parts.self_agreement(self.structure_data, e)
        self.b_element = error_parts.element_truth(self.structure, e,
                                                   widen=error_parts.own_error(own_element))
        self.b_patch = error_parts.patch_truth(self.structure.patch_y, self.structure.patch_area, e,
                                               widen=error_parts.own_error(own_patch))
        self.structure_self = (own_element, own_patch)
        # (a) per patch: Cycles, its standard error drawn in every bootstrap draw.
        self.a_patch = None
        self.leaving = None   # the share of the emitted power that leaves the scene (Cycles')
        if self.cycles:
            self.leaving = error_parts.leaving_share(self.cycles, self.emission, self.reflectance)
            rows = np.array(self.cycles["patches"], dtype=float)
            self.a_patch = error_parts.patch_truth(rows[:, 8], rows[:, 1], e, noise=rows[:, 9])
        # (a) per element: the reference, widened by its self-agreement and its patch RMS
        # against Cycles.
        self.a_element = None
        self.reference_patch_error = None
        if self.reference is not None:
            widen = error_parts.own_error(reference["self_agreement"]["element_rms"])
            if self.a_patch is not None:
                self.reference_patch_error = error_parts.interval(self.reference.patch_y, self.a_patch)
                widen += self.reference_patch_error[0]
            self.a_element = error_parts.element_truth(self.reference, e, widen=widen)

    def parts(self, solution, delivery=None, shooter_of=None):
        """(a), (b) and (d) of one solution: {name: (rms, low, high) or None, "balance": {...}}."""
        out = {"b_element": error_parts.interval(solution.y, self.b_element),
               "b_patch": error_parts.interval(solution.patch_y, self.b_patch),
               "a_element": error_parts.interval(solution.y, self.a_element) if self.a_element else None,
               "a_patch": error_parts.interval(solution.patch_y, self.a_patch) if self.a_patch else None}
        out["balance"] = error_parts.balance(
            solution, self.emission, self.reflectance,
            self.structure_data["delivery"] if delivery is None else delivery, shooter_of)
        return out


def measure(cells, results, jobs):
    folder = results / "claims" / "cells"
    folder.mkdir(parents=True, exist_ok=True)
    truths, solutions = {}, {}
    rows = []
    with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
        runs = list(pool.map(lambda c: run_cell(c, folder), cells))
    for cell, (result_path, mesh_path) in zip(cells, runs):
        if cell.scene not in truths:
            truths[cell.scene] = SceneTruths(cell.scene, cell.scene_sha256)
        truth = truths[cell.scene]
        result = json.loads(result_path.read_text())
        solution = error_parts.mesh_solution(mesh_path, truth.structure)
        solutions[cell.id] = solution
        name, value = knob(cell)
        row = {"scene": cell.scene, "series": series_of(cell), "label": series_label(cell),
               "R": cell.R, "V": cell.V, "id": cell.id,
               "form_factors": cell.options.get("form_factors", "ray-traced"),
               "placement": cell.options.get("hemicube_placement", "centre"),
               "parallelisation": cell.options.get("parallelisation", "receivers"),
               "knob": name, "value": value, "status": result["status"],
               "converged": result["converged"], "iterations": result["iterations"],
               "simulated_seconds": result["simulated_seconds"],
               "host_seconds": result["host_seconds"], "cell": cell.file}
        row.update(truth.parts(solution))
        rows.append(row)
    return rows, truths, solutions


def claim_one_decisions(rows, truths, solutions):
    """Every converged hemicube cell against the paper's method at its largest M on the same
    scene (receivers, V = 0): the ratio of their form-factor errors (b) with its paired
    interval, per element and per patch (analysis/ncube/claim_one.py decides)."""
    out = []
    for scene in sorted({r["scene"] for r in rows}):
        mine = [r for r in rows if r["scene"] == scene and r["V"] == 0 and r["status"] == "ok"
                and r["converged"]]
        rays = [r for r in mine if r["form_factors"] == "ray-traced" and r["parallelisation"] == "receivers"]
        hemicube = [r for r in mine if r["form_factors"] == "hemicube"]
        if not rays or not hemicube:
            continue
        best = max(rays, key=lambda r: r["value"])
        truth = truths[scene]
        for measure, key, of in (("element", "b_element", lambda s: s.y),
                                 ("patch", "b_patch", lambda s: s.patch_y)):
            baseline = truth.b_element if measure == "element" else truth.b_patch
            for h in sorted(hemicube, key=lambda r: (r["placement"], r["value"])):
                ratio, low, high = error_parts.ratio_interval(
                    of(solutions[h["id"]]), of(solutions[best["id"]]), baseline)
                out.append({"scene": scene, "measure": measure, "placement": h["placement"],
                            "resolution": h["value"], "samples": best["value"],
                            "rays": best[key], "hemicube": h[key],
                            "ratio": ratio, "low": low, "high": high})
    return out


def run_picture(cell, folder):
    """The cell's picture under `folder` (--image), run now unless it is there."""
    stem = Path(cell.file).stem
    image = folder / f"{stem}.png"
    if image.exists():
        return image
    partial = folder / f"{stem}.partial.png"
    command = cell.command(str(folder / f"{stem}.json")) + ["--image", str(partial), "--quiet"]
    run = subprocess.run(command, env=paths.simulate_environment(), capture_output=True, text=True)
    if run.returncode != 0:
        raise RuntimeError(f"{cell.label} ({cell.file}): ./simulate exit {run.returncode}: "
                           f"{run.stderr.strip()}")
    os.replace(partial, image)
    return image


def picture_label(cell):
    o = cell.options
    if o.get("form_factors", "ray-traced") == "hemicube":
        method = f"hemicube N={o['hemicube_resolution']} {o['hemicube_placement']}"
    else:
        method = f"ray-traced M={o['samples']}"
    stop = "converged" if o.get("iterations", -1) < 0 else f"{o['iterations']} iterations"
    return f"{cell.scene}: {method}, R={o['R']} V={o['V']}, {stop}"


def pictures(cells, results, jobs, path):
    """The cells' pictures side by side, one row per scene, in the sweep's order."""
    from ncube import plotting   # matplotlib (1 s a start) where a figure is drawn, not before
    import matplotlib.image
    import matplotlib.pyplot as plt
    folder = results / "claims" / "pictures"
    folder.mkdir(parents=True, exist_ok=True)
    with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
        images = list(pool.map(lambda c: run_picture(c, folder), cells))
    scenes = list(dict.fromkeys(c.scene for c in cells))
    columns = max(sum(1 for c in cells if c.scene == s) for s in scenes)
    fig, axes = plt.subplots(len(scenes), columns, figsize=(6 * columns, 4.6 * len(scenes)),
                             squeeze=False, layout="constrained")
    for row, scene in enumerate(scenes):
        mine = [(c, i) for c, i in zip(cells, images) if c.scene == scene]
        for column in range(columns):
            ax = axes[row][column]
            ax.axis("off")
            if column < len(mine):
                ax.imshow(matplotlib.image.imread(mine[column][1]))
                ax.set_title(picture_label(mine[column][0]), fontsize=10)
    plotting.save(fig, path)
    return [picture_label(c) for c in cells]


def schemes_section(results, jobs, figure):
    """The second claim's section (analysis/claims_schemes.py, another part of the study),
    when that module is there; its cells run `jobs` at once as the first claim's do; its
    speedup curves written to `figure`."""
    try:
        import claims_schemes
    except ImportError:
        return None
    return claims_schemes.section(results, jobs, figure=figure)


def series_colour(row):
    """One colour per kind of series on every scene's plots."""
    if row["form_factors"] == "hemicube":
        return "C0" if row["placement"] == "centre" else "C1"
    return "C3" if row["V"] > 0 else "C2"


def plot(rows, path):
    from ncube import plotting   # matplotlib (1 s a start) where a figure is drawn, not before
    import matplotlib.pyplot as plt
    scenes = sorted({r["scene"] for r in rows})
    measures = (("b_element", "(b) form-factor error, element RMS"),
                ("b_patch", "(b) form-factor error, patch RMS"),
                ("a_patch", "(a) total error against Cycles, patch RMS"))
    fig, axes = plt.subplots(len(measures), len(scenes), figsize=(5.5 * len(scenes), 11),
                             squeeze=False, layout="constrained")
    for column, scene in enumerate(scenes):
        mine = [r for r in rows if r["scene"] == scene]
        for row_index, (measure, title) in enumerate(measures):
            ax = axes[row_index][column]
            for series in sorted({r["series"] for r in mine}):
                points = sorted((r for r in mine if r["series"] == series and r[measure]),
                                key=lambda r: r["value"])
                if not points:
                    continue
                xs = [r["simulated_seconds"] for r in points]
                ys = [r[measure][0] for r in points]
                errors = [[r[measure][0] - r[measure][1] for r in points],
                          [r[measure][2] - r[measure][0] for r in points]]
                ax.errorbar(xs, ys, yerr=errors, marker="o", capsize=3, label=points[0]["label"],
                            color=series_colour(points[0]))
                for r in points:
                    short = "M" if r["knob"] == "samples" else "N"
                    ax.annotate(f"{short}={r['value']}", (r["simulated_seconds"], r[measure][0]),
                                textcoords="offset points", xytext=(4, 4), fontsize=7)
            ax.set_xscale("log")
            ax.set_yscale("log")
            ax.set_xlabel("simulated seconds to convergence")
            ax.set_ylabel(title)
            ax.set_title(f"{scene}: {title}", fontsize=10)
            ax.grid(True, which="both", alpha=0.3)
            ax.legend(fontsize=7)
    plotting.save(fig, path)


def shown(path):
    """A path as the page names it: from the repository's root when inside it."""
    path = Path(path)
    return path.relative_to(ROOT) if path.is_relative_to(ROOT) else path


def cell_figure(part):
    return "—" if part is None else claim_one.figure(*part, percent=True)


def share(value):
    return f"{100 * value:.2f} %"


def left_out(truth):
    """How many elements a truth leaves out of the element RMS (error_parts: darker than the
    floor)."""
    return f"{int(truth.left_out.sum())} of {len(truth.y)}"


def truths_section(truths):
    out = ["## What the errors are measured against", "",
           "| scene | reference (per element): K, self-agreement element RMS, its patch RMS against "
           "Cycles | exact structure (patches): K, self-agreement element / patch RMS | every "
           "element its own patch: K | Cycles: samples a pixel, seeds | elements left out "
           "(darker than the floor): exact structure, reference |",
           "|---|---|---|---|---|---|"]
    for scene, t in sorted(truths.items()):
        ref = t.files.get("reference")
        ref_text = "none (not committed: docs/accuracy.md)" if ref is None else (
            f"refine {ref['refine']}, K = {ref['samples']}, {100 * ref['self_agreement']['element_rms']:.2f} %, "
            + (claim_one.figure(*t.reference_patch_error, percent=True) if t.reference_patch_error else "—"))
        s = t.structure_data
        own = t.files.get("structure_elements")
        cycles = t.files.get("cycles")
        out.append(f"| {scene} | {ref_text} | K = {s['samples']}, {100 * t.structure_self[0]:.2f} % / "
                   f"{100 * t.structure_self[1]:.3f} % | "
                   + (f"K = {own['samples']}" if own else "not computed") + " | "
                   + (f"{cycles.get('samples_per_pixel', cycles.get('samples_per_texel'))}, {cycles['seeds']}"
                      if cycles else "none") + " | "
                   + left_out(t.b_element) + ", "
                   + (left_out(t.a_element) if t.a_element else "—") + " |")
    return out + [""] + truths_cost_section(truths)


def seconds(value):
    return f"{value:,.0f}" if value >= 10 else f"{value:.1f}"


def truths_cost_section(truths):
    """Each committed truth's regeneration command and its seconds, as its own file records
    them (the reference's manifest, the structures' and Cycles' host_seconds)."""
    out = ["### What the truths cost to regenerate", "",
           "Each committed truth is made by its own command, not by this page; the seconds are "
           "those its file (or the reference's manifest) records, wall seconds on this shared "
           "2-core machine under whatever load it had then (docs/accuracy.md gives the loads).", "",
           "| scene | truth | command | host s | peak memory |", "|---|---|---|---:|---:|"]
    folder = ROOT / "analysis"
    for scene, t in sorted(truths.items()):
        manifest = folder / "reference" / "manifest" / f"{scene}.json"
        if manifest.exists():
            m = error_parts.read_json(manifest, "the reference's manifest")
            out.append(f"| {scene} | the reference (`analysis/reference/{scene}.json`) | "
                       f"`experiments/claims/references {scene}` (`{m['command']}`) | "
                       f"{seconds(m['wall_seconds'])} | "
                       + ("not recorded" if m.get("peak_memory_bytes") is None
                          else f"{m['peak_memory_bytes'] / 1e9:.2f} GB") + " |")
        structures = [t.files["structure"]] + ([t.files["structure_elements"]]
                                               if t.files.get("structure_elements") else [])
        for placement in ("centre", "elements"):
            path = folder / "reference" / "structure" / f"{scene}-hemicube-{placement}.json"
            if path.exists():
                structures.append(error_parts.read_json(path, "the hemicube's exact structure"))
        out.append(f"| {scene} | the exact structures ({len(structures)} files, "
                   f"`analysis/reference/structure/{scene}-*.json`) | "
                   f"`experiments/claims/references --structures {scene}` | "
                   f"{seconds(sum(d['host_seconds'] for d in structures))} | — |")
        cycles = t.files.get("cycles")
        if cycles:
            how = (f"camera rays, {cycles.get('samples_per_pixel')} samples a pixel"
                   if cycles.get("estimator") == "camera" else
                   f"bake, {cycles.get('samples_per_texel')} samples a texel (the biased "
                   "estimator: docs/accuracy.md)")
            command = ("experiments/claims/cycles-answers " + scene) if cycles.get("estimator") == "camera" \
                else (f"analysis/cycles/cycles_answers.py {scene} --out analysis/cycles/{scene}.json "
                      f"--estimator bake --samples {cycles.get('samples_per_texel')} "
                      f"--texels {cycles.get('texels_a_side')} --seeds {cycles['seeds']}")
            out.append(f"| {scene} | Cycles (`analysis/cycles/{scene}.json`: {how}, "
                       f"{cycles['seeds']} seeds) | `{command}` | {seconds(cycles['host_seconds'])} | — |")
    return out + [""]


def loss_cells(balance_, leaving):
    """The structure's loss as two cells: what leaves the scene, the structure's own loss."""
    out, own = error_parts.split_loss(balance_, None if leaving is None else leaving[0])
    if out is None:
        return f"— | {share(balance_['structure_lost_share'])}"
    return f"{share(out)} | {share(own)}"


def parts_section(rows, truths=None):
    out = ["## The error taken apart, every cell", "",
           "(a) total error: per element against the reference, per patch against Cycles; "
           "(b) form-factor error: against the exact structure; each an area-weighted RMS of "
           "symmetric relative luminance differences (Y - T) / ((Y + T) / 2) (an element or "
           f"patch whose truth is darker than {100 * error_parts.FLOOR:g} % of the mean left "
           "out; the one measure of docs/accuracy.md) with its 95 % interval. (d) the power "
           "balance: the share of the emitted power the patches absorb; of what the exact "
           "structure's centre form factors would not deliver of what this solution's patches "
           "send, the share that leaves the scene (as Cycles has it: what its patches do not "
           "absorb, the open front of the Cornell box; taken as the same for every answer of "
           "a scene) and the structure's own loss, the rest of it; and the rest of what is "
           "missing (the method's form factors' shortfall beyond the exact ones', and the "
           "unshot power left at the stop).", ""]
    for scene in sorted({r["scene"] for r in rows}):
        out += [f"### {scene}", "",
                "| method | knob | iterations | simulated s | (a) element | (a) patch | "
                "(b) element | (b) patch | absorbed | leaves the scene | structure's own loss | "
                "rest |",
                "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
        leaving = truths[scene].leaving if truths and scene in truths else None
        for r in sorted((r for r in rows if r["scene"] == scene),
                        key=lambda r: (r["label"], r["value"])):
            converged = "" if r["converged"] else " (not converged)"
            b = r["balance"]
            out.append(f"| {r['label']} | {r['knob']}={r['value']} | {r['iterations']}{converged} | "
                       f"{r['simulated_seconds']:.2f} | {cell_figure(r['a_element'])} | "
                       f"{cell_figure(r['a_patch'])} | {cell_figure(r['b_element'])} | "
                       f"{cell_figure(r['b_patch'])} | {share(b['absorbed_share'])} | "
                       f"{loss_cells(b, leaving)} | {share(b['rest_share'])} |")
        out.append("")
    return out


def structure_section(truths):
    import numpy as np
    out = ["## The structure's own error (c) and the balance of the answers (d)", "",
           "The exact structure (the same mesh and scheme as `./simulate`, exact form factors) "
           "and the same with every element its own patch, against the truth as in (a); "
           "Cycles' own balance beside them (its standard error from its 8 seeds, the 95 % "
           "interval ±1.96 se).", "",
           "| scene | answer | (c) element | (c) patch | absorbed | leaves the scene | "
           "structure's own loss | rest |",
           "|---|---|---:|---:|---:|---:|---:|---:|"]
    for scene, t in sorted(truths.items()):
        answers = [("exact structure (patches)", t.structure, None, None)]
        if t.own is not None:
            answers.append(("every element its own patch", t.own, t.own_data["delivery"],
                            np.arange(len(t.own.y))))
        if t.reference is not None:
            answers.append(("the reference", t.reference, None, None))
        for name, solution, delivery, shooter_of in answers:
            p = t.parts(solution, delivery, shooter_of)
            b = p["balance"]
            a_element = "(itself)" if name == "the reference" else cell_figure(p["a_element"])
            loss = ("— | — | —" if name == "the reference" else
                    f"{loss_cells(b, t.leaving)} | {share(b['rest_share'])}")
            out.append(f"| {scene} | {name} | {a_element} | {cell_figure(p['a_patch'])} | "
                       f"{share(b['absorbed_share'])} | {loss} |")
        # The floor of every measure: no light transport at all (every element its emission).
        dark = error_parts.Solution(t.structure.patch, t.structure.area, t.emission[t.structure.patch])
        p = t.parts(dark)
        out.append(f"| {scene} | no light transport (B = E) | {cell_figure(p['a_element'])} | "
                   f"{cell_figure(p['a_patch'])} | — | — | — | — |")
        if t.cycles:
            c = error_parts.cycles_balance(t.cycles, t.emission, t.reflectance)
            low, high = (c["absorbed_share"] - 1.96 * c["absorbed_share_se"],
                         c["absorbed_share"] + 1.96 * c["absorbed_share_se"])
            out.append(f"| {scene} | Cycles | — | — | "
                       f"{claim_one.figure(c['absorbed_share'], low, high, percent=True)} | "
                       f"{claim_one.figure(*t.leaving, percent=True)} | — | — |")
    return out + ["",
                  "For the exact structure the structure's loss (what leaves the scene and its own "
                  "loss together) is the whole deficit (its rest is 0 to rounding: absorbed + loss "
                  "= emitted is an identity of the balance, a check of the computation). What "
                  "leaves the scene is Cycles' (1 - its absorbed share, 95 % interval), the same "
                  "for every answer of a scene: in a closed room it is 0 but for Cycles' own "
                  "error; the structure's own loss is the structure's loss less it. The loss of "
                  "the reference is not computed (it has its own form factors): its deficit is "
                  "what leaves the scene as it sees it.", ""]


def markdown(rows, truths, decisions, sweep_files, picture_labels=(), schemes=None, own_section=""):
    out = ["# The paper's claims, measured", "",
           "Written by `analysis/claims.py` from the sweeps "
           + ", ".join(f"`{shown(f)}`" for f in sweep_files)
           + "; how to run it: `docs/reproduce.md`; the truths, the error parts, the intervals "
           "and the threshold: `docs/accuracy.md`. Every figure is an area-weighted RMS of "
           "symmetric relative luminance differences (the one error measure, "
           "`analysis/ncube/error_measure.py`: a solution without light transport scores about "
           "2) with its 95 % interval: a paired bootstrap over the scene's patches, widened by "
           "the truth's own error (`analysis/ncube/error_parts.py`), which answers how much the "
           "figure would move on another scene made of patches like these; the runs themselves "
           "are deterministic, so no interval is over repeated runs. Time: the "
           "simulated seconds of the whole run to convergence (largest unshot power below 1e-4 "
           "of the emitted power). The paper's method runs as the paper's program "
           "(`--parallelisation receivers`); the hemicube in its natural parallel form "
           "(`--parallelisation shooters`: each node shoots its own patch, with one hemicube at "
           "the shooter's centre, or one at each of the shooter's element centres): its "
           "simulated times are of that form. **The times are not like for like**: the rays "
           "are timed under the paper's program (receivers share a shot's elements), the "
           "hemicube under shooters (a node computes its shot alone, several shots at once); "
           "a time ratio between the two mixes the form factors' cost with the "
           "parallelisation's.", ""]
    out += truths_section(truths)
    out += ["## The first claim: ray tracing against the hemicube", "",
            "*Ray-traced form factors are much more accurate than the hemicube method* "
            "(section 6). **It is decided in the next section**, \"Each method against its own "
            "structure\", on the form-factor error (b) of each method against the exact "
            "solution of **its own** structure, and what a user sees on the total error (a) per "
            "patch against Cycles (the choice and why: `docs/accuracy.md`, \"Each method "
            "against its own structure\"). **Threshold** (the project's convention, fixed in "
            "`docs/accuracy.md` before the runs; the paper does not say how much \"much\" is): "
            f"\"much\" is a ratio of at least {claim_one.THRESHOLD:g} with its paired 95 % "
            "interval's low end at least as high; its interval below it, it does not hold; "
            "straddling, undecided. The decisions are **exploratory**: many are taken from the "
            "same data and none is corrected for multiple comparisons (docs/accuracy.md).", "",
            "### (b) against the receiver-centred structure (does not decide)", "",
            "The table below holds every method against the receiver-centred exact structure "
            "(receivers at element centres, a patch shooting its elements' mean): the rays' own "
            "structure, **not the hemicube's**. The hemicube reads a receiver off from an eye "
            "on the shooter and turns that point factor around by reciprocity, so against this "
            "structure its (b) counts where its eyes stand (one point standing for a whole "
            "shooter) as a form-factor error. Kept to show how much that placement weighs: "
            "compare the next section's (b) of the same cells against their own structures.", ""]
    out += claim_one.decision_rows(decisions)
    out += ["", "Against the receiver-centred structure (not deciding): "
            + claim_one.claim_sentence(decisions), ""]
    if own_section:
        out += [own_section.rstrip(), ""]
    out += ["## What the first claim rests on, and its threats", "",
            "The exact structures (`build/reference_solution --structure patches`, K = 1024 "
            "visibility points a shooter; `--structure hemicube-centre` and `hemicube-elements`, "
            "K = 64 rays an (eye, element) pair; `analysis/reference/structure/`), their "
            "self-agreement; Cycles' answers for (a) per patch; the converged runs below; the "
            "bootstrap over patches.", "",
            "**Threats to validity**:", "",
            "* The intervals are over the scene's patches (would another scene of the same kind "
            "give the same ratio?), not over repeated runs: both methods are deterministic. With "
            "17 patches (the Cornell box) the intervals are wide; a patch that dominates the "
            "error (a small face near a large shooter) moves the ratio most.",
            "* (b) is measured against exact structures computed with finite samples (half "
            "each one's self-agreement, K/4 against K, widens its intervals: an estimate of its "
            "error, not a bound); the structures and the methods share the scene's geometry, "
            "not code.",
            "* The hemicube here blocks with back faces and evaluates the shooter's hemicube "
            "at its centre or at each element's centre (docs/model.md); other choices (the "
            "other back-face choice, the Cornell box's light below the ceiling) are measured in "
            "`analysis/claims_hemicube.py` (its section of this page).",
            "* The hemicube's factors are not clamped: a receiver close in front of an eye gets "
            "a factor above 1 by reciprocity (\"Reciprocity in the open\" above). Its own "
            "structure has the same accident, so (b) against it does not count it; (a) against "
            "Cycles does.",
            "* The paper's method is measured at its largest M only (M = 64 where run); its "
            "error at smaller M is in the tables below, not in the verdict.",
            "* The total error (a) per element rests on the reference, whose own error is "
            "estimated (half its self-agreement plus its patch error against Cycles), not bounded; "
            "per patch it rests on Cycles' answers (the estimator of each in the truths' table "
            "above; docs/accuracy.md, \"Two estimators\").",
            "* The paper's method runs under the paper's program (receivers), the hemicube under "
            "shooters: both to the same convergence rule (largest unshot power below 1e-4 of the "
            "emitted), which leaves each a little unshot power, not the same.",
            "* Scenes: " + ", ".join(f"{scene} ({len(t.structure.patch_y)} patches, "
                                      f"{len(t.structure.y)} elements)" for scene, t in sorted(truths.items()))
            + "; the total error per element only where a reference is committed ("
            + ", ".join(scene for scene, t in sorted(truths.items()) if t.reference is not None)
            + "); scene2 and larger are not measured (docs/accuracy.md).", ""]
    out += parts_section(rows, truths)
    out += structure_section(truths)
    out += ["## Error against simulated time to convergence", "",
            "![error against time](figures/claims_accuracy.png)", ""]
    if picture_labels:
        out += ["## The pictures", "",
                "Left to right: " + "; ".join(picture_labels) + ".", "",
                "![pictures](figures/claims_pictures.png)", ""]
    # The second claim's section brings its own heading (analysis/claims_schemes.py).
    out += [schemes.rstrip(), ""] if schemes else [
        "## The second claim: receivers against shooters", "",
        "2. *No need to distribute radiosity values after the form factors* (section 6): "
        "not measured here (`analysis/claims_schemes.py` not there, or `--no-schemes`).", ""]
    return "\n".join(out)


@page.refusing_outputs("claims.py")
def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--results", type=Path, default=ROOT / "results")
    parser.add_argument("--jobs", type=runner.bounded(1, 256), default=2, help="cells run at once (1 to 256)")
    parser.add_argument("--sweeps", nargs="*", type=Path,
                        default=sorted((ROOT / "experiments" / "claims").glob("accuracy*.yaml")))
    parser.add_argument("--pictures", nargs="*", type=Path,
                        default=[ROOT / "experiments" / "claims" / "pictures.yaml"],
                        help="sweep files of the cells to picture side by side (none: no pictures)")
    parser.add_argument("--pictures-figure", type=Path,
                        default=ROOT / "analysis" / "figures" / "claims_pictures.png")
    parser.add_argument("--no-schemes", action="store_true",
                        help="leave out the second claim's section (analysis/claims_schemes.py)")
    parser.add_argument("--no-hemicube", action="store_true",   # the hemicube's section's one line here
                        help="leave out the hemicube's section (analysis/claims_hemicube.py)")
    parser.add_argument("--out", type=Path, default=ROOT / "analysis" / "claims.md")
    parser.add_argument("--figure", type=Path,
                        default=ROOT / "analysis" / "figures" / "claims_accuracy.png")
    parser.add_argument("--cost-figure", type=Path,
                        default=ROOT / "analysis" / "figures" / "claims_cost.png",
                        help="the hemicube's section's error against cost")
    parser.add_argument("--schemes-figure", type=Path,
                        default=ROOT / "analysis" / "figures" / "claims_schemes_speedup.png",
                        help="the second claim's section's speedup curves")
    args = parser.parse_args()
    if not args.sweeps:   # nothing to measure: the page would be empty
        page.refuse("claims.py", "--sweeps names no sweep file (the claims' cells are measured "
                                 "from at least one)")
    page.will_run("claims.py", f"the cells of {', '.join(page.shown(f) for f in args.sweeps)} "
                  f"without a result in {page.shown(args.results)}/claims/ itself", announce=False)
    try:
        sweeps = sweep.load_all(args.sweeps)
        picture_cells = [c for s in sweep.load_all(args.pictures) for c in s.cells] if args.pictures else []
    except sweep.SweepError as e:
        print(f"claims: {e}", file=sys.stderr)
        return 2
    cells, seen = [], set()
    for s in sweeps:
        for cell in s.cells:
            if cell.id not in seen:
                seen.add(cell.id)
                cells.append(cell)
    for scene in sorted({c.scene for c in cells}):   # before any run: one line, nothing run
        if not (ROOT / "analysis" / "reference" / "structure" / f"{scene}-patches.json").exists():
            raise SystemExit(f"claims: no exact structure for {scene}: run "
                             f"experiments/claims/references --structures {scene}")
    page.will_run("claims.py", f"the cells of {', '.join(page.shown(f) for f in args.sweeps)} "
                  f"without a result in {page.shown(args.results)}/claims/ itself")
    try:
        rows, truths, solutions = measure(cells, args.results.resolve(), args.jobs)
        labels = (pictures(picture_cells, args.results.resolve(), args.jobs, args.pictures_figure)
                  if picture_cells else [])
    except (RuntimeError, ValueError, accuracy.AccuracyError) as e:
        print(f"claims: {e}", file=sys.stderr)
        return 4
    plot(rows, args.figure)
    schemes = None if args.no_schemes else schemes_section(args.results.resolve(), args.jobs,
                                                          args.schemes_figure)
    # --- the hemicube's section (analysis/claims_hemicube.py): included whole
    import claims_hemicube
    try:
        own, hemicube = ("", "") if args.no_hemicube else claims_hemicube.sections(
            args.results.resolve(), args.jobs, cost_figure_path=args.cost_figure)
    except (claims_hemicube.CellFailed, accuracy.AccuracyError, sweep.SweepError, RuntimeError,
            ValueError) as e:
        print(f"claims: {e}", file=sys.stderr)
        return 4
    # --- end of the hemicube's section
    decisions = claim_one_decisions(rows, truths, solutions)
    body = markdown(rows, truths, decisions, [s.file for s in sweeps], labels, schemes, own) + "\n" + \
        (hemicube.rstrip() + "\n" if hemicube else "")
    page.write(args.out, op.with_opening(body, opening(op.tables(body)), "analysis/claims.py"))
    written = [args.out, args.figure] + ([args.pictures_figure] if labels else []) + \
        ([] if args.no_schemes else [args.schemes_figure]) + \
        ([] if args.no_hemicube else [args.cost_figure])
    print(f"claims: {len(rows)} cells; written: " + ", ".join(str(p) for p in written))
    return 0


def opening(found):
    """The page's opening, from its own tables: claim 1's verdicts on the form-factor error (b)
    of each method against its own structure, and the ratios they rest on; the same on the
    total error per patch against Cycles, which no structure enters; at equal simulated time;
    the structure's own error, shared by every method; claim 2's ratios, the opponent over the
    paper's program at each node count both ran."""
    def pct(cell):
        return op.number(cell.split("[")[0])

    def span(values, unit="x"):
        if not values:
            return "not measured"
        low, high = min(values), max(values)
        return f"{low:.2f}{unit}" if f"{low:.2f}" == f"{high:.2f}" else \
            f"{low:.2f}{unit} to {high:.2f}{unit}"

    def interval(cell):
        """(ratio, low, high) of a "1.35 [0.95, 4.44]" cell."""
        ratio, low, high = re.match(r"\s*([0-9.]+) \[([0-9.]+), ([0-9.]+|∞)\]", cell).groups()
        return float(ratio), float(low), float("inf") if high == "∞" else float(high)

    def counted(rows):
        verdicts = [r["verdict"] for r in rows]
        better = sum(1 for r in rows if interval(r["ratio [95 %]"])[2] < 1)
        return (f"holds in {verdicts.count('holds')} of {len(rows)}, is undecided in "
                f"{verdicts.count('undecided')}, does not hold in {verdicts.count('does not hold')}"
                + (f" (the hemicube the more accurate, its interval below 1, in {better})" if better else ""))

    def ratios(rows, placement):
        return [interval(r["ratio [95 %]"])[0] for r in rows if r["hemicube"].startswith(placement)]

    sentences = []
    decided = next((rows for label, rows in found if label == "The decisions" and rows
                    and "verdict" in rows[0]), [])
    own = [r for r in decided if r["measure"].startswith("(b) own structure")]
    if own:
        sentences.append(op.Sentence(
            "Claim 1, ray tracing much more accurate than the hemicube, judged on each method's "
            "form-factor error (b) against the exact solution of its own structure (per element "
            f"and per patch, every hemicube setting against the paper's method at its largest M): "
            f"it {counted(own)}; the hemicube's (b) is {span(ratios(own, 'centre'))} the paper's "
            f"method's at the shooter's centre and {span(ratios(own, 'elements'))} from each "
            "shooter element",
            "each ratio has its paired 95 % bootstrap interval over patches, each error widened "
            "by its own truth's error, in the table of the decisions; 'much' (the ratio and its "
            "interval's low end at least 2) is the project's convention; the decisions are not "
            "corrected for multiple comparisons, so they are exploratory"))
    seen = [r for r in decided if r["measure"].startswith("(a) patch")]
    if seen:
        sentences.append(op.Sentence(
            "What a user sees, the total error per patch against Cycles, which no structure "
            f"enters: the hemicube at the shooter's centre is {span(ratios(seen, 'centre'))} the "
            f"paper's method's, from each shooter element {span(ratios(seen, 'elements'))}; "
            f"\"much more accurate\" {counted(seen)}",
            "paired 95 % bootstrap intervals over patches, widened by Cycles' standard errors, "
            "in the table of the decisions; exploratory as above"))
    equal = next((rows for label, rows in found if label == "At equal cost" and rows
                  and "verdict" in rows[0]), [])
    equal = [r for r in equal if r["verdict"] != "—"]
    if equal:
        sentences.append(op.Sentence(
            "At equal simulated time (for each of the rays' cells, the hemicube's best setting "
            "within its time, on the three measures), \"much more accurate\" " + counted(equal),
            "paired 95 % intervals in the table at equal simulated time; the times are not like "
            "for like (the rays under the paper's program, the hemicube under shooters), so "
            "this ranks the settings on this machine model, it does not isolate the form "
            "factors' cost"))
    structure = next((rows for label, rows in found if label.startswith("The structure's own error")), [])
    exact = [(r["scene"], r["(c) patch"]) for r in structure if r["answer"] == "exact structure (patches)"]
    if exact:
        sentences.append(op.Sentence(
            "The structure all methods share (receivers at element centres, a patch shooting its "
            "elements' mean) has an error of its own of "
            + span([pct(c) for _, c in exact], " %") + " per patch against Cycles ("
            + "; ".join(f"{s} {c}" for s, c in exact) + "), the larger part of what a user sees",
            "95 % intervals in brackets, over patches, widened by Cycles' standard errors"))
    to_conv, to_error, nodes = [], [], 0
    for label, rows in found:
        if not label.endswith("to convergence and to a fixed error") or not rows or "nodes" not in rows[0]:
            continue
        for n in sorted({r["nodes"] for r in rows}, key=op.number):
            at = [r for r in rows if r["nodes"] == n]
            def best(prefix, column):
                values = [op.number(r[column].split(" ")[0]) for r in at
                          if r["scheme"].startswith(prefix) and op.number(r[column].split(" ")[0]) is not None]
                return min(values, default=None)
            ours, theirs = best("receivers", "s to convergence"), best("circulation", "s to convergence")
            if ours and theirs:
                nodes += 1
                to_conv.append(theirs / ours)
                e_ours, e_theirs = best("receivers", "s to the error (iteration)"), \
                    best("circulation", "s to the error (iteration)")
                if e_ours and e_theirs:
                    to_error.append(e_theirs / e_ours)
    if to_conv:
        sentences.append(op.Sentence(
            f"Claim 2, no need to distribute radiosity values: at {nodes} node counts of the "
            f"Cornell box and scene0, circulation (one shooter a node; a scheme built from "
            f"Çapın, Aykanat & Özgüç's abstracts) takes {span(to_conv)} the paper's program's "
            f"simulated time to convergence and {span(to_error)} its time to the fixed error "
            "(a third of the error of a solution without light transport, measured after every "
            "iteration)",
            "deterministic runs, no sampling interval; a ratio within 1 % of 1 is a tie; the "
            "opponent's shares, replicated geometry and ring are assumed, and every scheme uses "
            "the same ray-traced form factors, so the gaps come from the order of shots and who "
            "computes a shot, not from the wire (docs/model.md)"))
    # A page written in part (--no-schemes, a sweep without the hemicube) says what it lacks.
    missing = [("Claim 1 is not decided on this page: 0 comparisons with the hemicube against "
                "its own structure", own),
               ("The total error per patch is not compared: 0 comparisons with both methods", seen),
               ("The structure's own error is not on this page: 0 scenes", exact),
               ("Claim 2 is not measured on this page: 0 node counts with both schemes", to_conv)]
    for text, present in missing:
        if len(sentences) < 3 and not present:
            sentences.append(op.Sentence(text, "not run for this page"))
    return sentences


if __name__ == "__main__":
    sys.exit(main())
