#!/usr/bin/python3
"""The hemicube's choices in the open: its back faces (block or pass) and the
Cornell box's light just below the ceiling, measured.

Reads experiments/claims/hemicube.yaml with the sweep tool's own loader (its validation,
defaults and cell identity), runs every cell's ./simulate command itself with --mesh (one host
thread, `jobs` cells at once) and keeps each result and mesh under RESULTS/claims/hemicube/
named after the cell's identity: a finished cell is not run again, a changed option or input is
another cell. Beside the sweep's cells it runs, for every Cornell-box cell, two --iterations
checkpoints: just before and at the ceiling's first shot, whose meshes give what that shot
passes on (below). Each cell is compared with

  * its scene's reference (analysis/reference/<scene>.json) by analysis/ncube/accuracy.py:
    element RMS, patch RMS and the largest patch error;
  * Cycles' per-patch answers (analysis/cycles/<scene>.json): the area-weighted RMS of the
    patches' relative luminance differences (as analysis/cycles/compare.py), with a 95 %
    interval from Cycles' standard errors (delta method: d_p = Y_p / Yc_p - 1 has the standard
    error (1 + d_p) se_p / Yc_p; the RMS's, sum_p (w_p d_p sigma_p)^2 under its root over
    W RMS).

What the ceiling's first shot passes on: with the meshes before (B0) and after (B1) the
shot, the ceiling's unshot radiosity at its first shot is its elements' area-weighted mean of
B0 (it emits nothing and has not shot), and each other element e received
A_e (B1_e - B0_e) / rho_e; their sum over A_ceiling times that mean is the share of the
shot's power that reaches a patch (the rest leaves the box through its open side, or meets
nothing: the hemicube's cells that no receiver takes). Computed per colour; the three agree
(the form factors do not depend on the colour), and the green is shown.

Every simulated figure is deterministic (the hemicube has no random numbers, the rays' parts
are a fixed grid): the same command gives the same mesh. Its uncertainty is that of what it is
held against, which the section states: the reference's self-agreement and its difference from
Cycles, and Cycles' standard errors.

section(results_root, jobs) returns the markdown section analysis/claims.py puts in
analysis/claims.md; run alone it prints it:

  /usr/bin/python3 analysis/claims_hemicube.py [--results results] [--jobs 2]"""

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
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from ncube import accuracy, claim_one, input_file, own_structure, page, paths, runner, sweep  # noqa: E402

ROOT = paths.ROOT
SWEEP = ROOT / "experiments" / "claims" / "hemicube.yaml"
CLAIMS_SWEEPS = "accuracy*.yaml"      # the claims' own cells (analysis/claims.py)
CEILING_SCENE = "cornell-box"
Z95 = 1.959964                        # two-sided 95 % of the normal distribution
CYCLES_BYTES = 64 << 20
COLOURS = "rgb"
GREEN = 1


class CellFailed(RuntimeError):
    pass


def variant(cell, **options):
    """The cell with some options changed: another cell, of another identity."""
    return dataclasses.replace(cell, options=dict(cell.options, **options))


def run_cell(cell, folder):
    """The cell's result and mesh under `folder`, run now unless both are there."""
    stem = Path(cell.file).stem
    result, mesh = folder / f"{stem}.json", folder / f"{stem}.ply"
    if result.exists() and mesh.exists():
        return result, mesh
    partial_result, partial_mesh = folder / f"{stem}.partial.json", folder / f"{stem}.partial.ply"
    command = cell.command(str(partial_result)) + ["--mesh", str(partial_mesh)]   # --quiet --threads 1
    run = subprocess.run(command, env=paths.simulate_environment(), capture_output=True, text=True)
    if run.returncode != 0:
        raise CellFailed(f"{cell.label} ({cell.file}): ./simulate exit {run.returncode}: "
                         f"{run.stderr.strip()}")
    os.replace(partial_mesh, mesh)   # the mesh first: a result alone is not taken as done
    os.replace(partial_result, result)
    return result, mesh


def method_of(cell):
    """(method, placement or the rays' M, back faces, the hemicube's N)."""
    o = cell.options
    if o["form_factors"] == "hemicube":
        return ("hemicube", o["hemicube_placement"], o["hemicube_back_faces"], o["hemicube_resolution"])
    return ("ray-traced", f"M={o['samples']}", "", 0)


def method_label(method):
    name, placement, back_faces, resolution = method
    if name == "hemicube":
        return f"hemicube N={resolution} ({placement}, back faces {back_faces})"
    return f"rays ({placement})"


def hemicube_row(rows, scene, placement, back_faces):
    return next((r for r in rows if r["scene"] == scene and r["method"][:3] == ("hemicube", placement, back_faces)), None)


def luminance(rgb):
    return accuracy.luminance(rgb)


def cycles_answers(scene, scene_sha256):
    path = ROOT / "analysis" / "cycles" / f"{scene}.json"
    try:
        cycles = json.loads(input_file.read_input_text(path, "Cycles answers", CYCLES_BYTES))
    except (input_file.InputFileError, ValueError) as e:
        raise CellFailed(f"{path}: {e}") from None
    if cycles.get("scene_sha256") != scene_sha256:
        raise CellFailed(f"{path} is of another {scene} (its scene_sha256 differs): run "
                         "experiments/claims/cycles-answers again")
    return path, cycles


def against_cycles(patch_luminance, cycles):
    """Area-weighted RMS of (Y_p - Yc_p) / Yc_p over the patches Cycles sees lit, with its
    95 % half-width from Cycles' standard errors (delta method), and per patch (d, sigma)."""
    weighted = total = 0.0
    per_patch = {}
    for row in cycles["patches"]:
        patch, area, y_cycles, se = row[0], row[1], row[8], row[9]
        if y_cycles <= 0.0:
            continue
        d = patch_luminance[patch] / y_cycles - 1.0
        sigma = (1.0 + d) * se / y_cycles
        per_patch[patch] = (d, sigma)
        weighted += area * d * d
        total += area
    rms = math.sqrt(weighted / total)
    spread = math.sqrt(sum((row[1] * per_patch[row[0]][0] * per_patch[row[0]][1]) ** 2
                           for row in cycles["patches"] if row[0] in per_patch))
    half = Z95 * spread / (total * rms) if rms > 0 else 0.0
    return rms, half, per_patch


def element_solution(mesh):
    return accuracy.solution_from_ply(mesh)


def passed_on(before, after, reference, scene, patch):
    """The share of `patch`'s first shot's power that reaches the other patches, per colour,
    from the meshes before and after the shot (the module's docstring)."""
    areas = [e[1] for e in reference["elements"]]
    reflectance = [p["reflectance"] for p in scene["patches"]]
    shooter_area = sum(a for (p, _), a in zip(before, areas) if p == patch)
    unshot = [sum(a * rgb[c] for (p, rgb), a in zip(before, areas) if p == patch) / shooter_area
              for c in range(3)]
    shares = []
    for c in range(3):
        received = sum(a * (b1[c] - b0[c]) / reflectance[p][c]
                       for (p, b0), (_, b1), a in zip(before, after, areas)
                       if p != patch and reflectance[p][c] > 0)
        shares.append(received / (shooter_area * unshot[c]) if unshot[c] > 0 else float("nan"))
    return shares


FORM_FACTOR_ROWS = 16384   # points a pass: the temporaries stay small (each point's figure is the same)


def point_form_factors(points, normal, polygon):
    """F(x -> polygon) for every point x (rows of `points`) with the unit `normal`, by
    Lambert's contour integral, the polygon wholly in front of every point. Taken
    FORM_FACTOR_ROWS points at a time: a grid of 800 x 800 points at once spends more time
    faulting in its temporaries than computing."""
    import numpy as np
    if len(points) > FORM_FACTOR_ROWS:
        return np.concatenate([point_form_factors(points[i:i + FORM_FACTOR_ROWS], normal, polygon)
                               for i in range(0, len(points), FORM_FACTOR_ROWS)])
    total = np.zeros(len(points))
    for a, b in zip(polygon, polygon[1:] + polygon[:1]):
        ra, rb = np.asarray(a) - points, np.asarray(b) - points
        cross = np.cross(ra, rb)
        norm = np.linalg.norm(cross, axis=1)
        cosine = np.einsum("ij,ij->i", ra, rb) / (np.linalg.norm(ra, axis=1) * np.linalg.norm(rb, axis=1))
        angle = np.arccos(np.clip(cosine, -1.0, 1.0))
        total += angle * (cross @ np.asarray(normal)) / norm
    return np.abs(total) / (2 * math.pi)


def opening(scene):
    """The box's open side: the scene's vertices in its nearest plane z = min z, in order."""
    vertices = [tuple(v) for p in scene["patches"] for v in p["vertices"]]
    z = min(v[2] for v in vertices)
    corners = sorted(set(v for v in vertices if v[2] == z))
    cx, cy = sum(v[0] for v in corners) / len(corners), sum(v[1] for v in corners) / len(corners)
    return sorted(corners, key=lambda v: math.atan2(v[1] - cy, v[0] - cx))


def exact_share(scene, ceiling, light, cells):
    """A lower bound on what the ceiling passes on, free of the hemicube's and the rays'
    errors: the mean over the ceiling (midpoint rule, cells x cells points) of 1 - F(x -> the
    open side) - F(x -> the light), every other direction meeting a patch's front. Where the
    light hides part of the open side (from points just above it) that part is subtracted
    twice, so the share is at least this."""
    import numpy as np
    v = np.asarray(scene["patches"][ceiling]["vertices"], dtype=float)
    normal = np.cross(v[1] - v[0], v[2] - v[0])
    normal /= np.linalg.norm(normal)
    s, t = np.meshgrid((np.arange(cells) + 0.5) / cells, (np.arange(cells) + 0.5) / cells)
    s, t = s.ravel()[:, None], t.ravel()[:, None]
    # The ceiling is a quad: bilinear points, weighted by the local area element.
    points = ((1 - s) * (1 - t) * v[0] + s * (1 - t) * v[1] + s * t * v[2] + (1 - s) * t * v[3])
    du = (1 - t) * (v[1] - v[0]) + t * (v[2] - v[3])
    dv = (1 - s) * (v[3] - v[0]) + s * (v[2] - v[1])
    weight = np.linalg.norm(np.cross(du, dv), axis=1)
    lost = (point_form_factors(points, normal, opening(scene))
            + point_form_factors(points, normal, [tuple(x) for x in scene["patches"][light]["vertices"]]))
    return float(1.0 - (weight * lost).sum() / weight.sum())


def ceiling_patch(scene):
    """The Cornell box's ceiling: the patch that emits nothing, faces down and lies highest
    (the light hangs 0.1 below it)."""
    best = None
    for k, p in enumerate(scene["patches"]):
        if any(p.get("emission", [0, 0, 0])):
            continue
        ys = [v[1] for v in p["vertices"]]
        if max(ys) - min(ys) > 1e-9:
            continue
        if best is None or ys[0] > best[1]:
            best = (k, ys[0])
    return best[0]


def light_patch(scene):
    return next(k for k, p in enumerate(scene["patches"]) if any(p.get("emission", [0, 0, 0])))


def claims_back_faces():
    """The back-face choice of every hemicube cell of the claims' own sweeps."""
    choices = {}
    files = sorted((ROOT / "experiments" / "claims").glob(CLAIMS_SWEEPS))
    for f in files:
        for cell in sweep.load(f).cells:
            if cell.options["form_factors"] == "hemicube":
                choices.setdefault(cell.options["hemicube_back_faces"], 0)
                choices[cell.options["hemicube_back_faces"]] += 1
    return files, choices


def measure(results_root, jobs=2, sweep_file=SWEEP):
    """Every row of the section, running what is not yet in results_root/claims/hemicube/."""
    folder = Path(results_root).resolve() / "claims" / "hemicube"
    folder.mkdir(parents=True, exist_ok=True)
    cells = sweep.load(sweep_file).cells
    scenes, references, cycles = {}, {}, {}
    for cell in cells:
        if cell.scene in references:
            continue
        reference_path = ROOT / "analysis" / "reference" / f"{cell.scene}.json"
        reference = accuracy.read_reference(reference_path)
        if reference["scene_sha256"] != cell.scene_sha256:
            raise CellFailed(f"{reference_path} is of another {cell.scene} (its scene_sha256 "
                             "differs): run experiments/claims/references again")
        references[cell.scene] = (reference_path, reference)
        cycles[cell.scene] = cycles_answers(cell.scene, cell.scene_sha256)
        scenes[cell.scene] = json.loads(Path(cell.scene_file).read_text())
    rows = []
    with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
        runs = list(pool.map(lambda c: run_cell(c, folder), cells))
        checkpoints = []
        for cell, (result_path, mesh) in zip(cells, runs):
            result = json.loads(result_path.read_text())
            reference_path, reference = references[cell.scene]
            error = accuracy.compare(element_solution(mesh), reference, str(mesh), str(reference_path))
            patch_y = [luminance(rgb) for rgb in result["patch_radiosity"]]
            rms, half, per_patch = against_cycles(patch_y, cycles[cell.scene][1])
            row = {"scene": cell.scene, "method": method_of(cell), "R": cell.R, "V": cell.V,
                   "convergence": cell.options["convergence"],
                   "iterations": result["iterations"],
                   "converged": result["converged"], "status": result["status"],
                   "simulated_seconds": result["simulated_seconds"],
                   "element_rms": error["element_rms"], "patch_rms": error["patch_rms"],
                   "patch_max": error["patch_max"], "worst_patch": error["worst_patch"],
                   "per_patch_reference": error["per_patch"], "patch_luminance": patch_y,
                   "cycles_rms": rms, "cycles_half": half, "per_patch_cycles": per_patch,
                   "cell": cell.file}
            rows.append(row)
            if cell.scene == CEILING_SCENE:
                ceiling = ceiling_patch(scenes[cell.scene])
                shot = result["shooters"].index(ceiling) + 1   # its first shot's iteration
                pair = [variant(cell, iterations=shot - 1), variant(cell, iterations=shot)]
                checkpoints.append((row, ceiling, [pool.submit(run_cell, c, folder) for c in pair]))
        for row, ceiling, futures in checkpoints:
            scene = scenes[row["scene"]]
            (_, before), (_, after) = (f.result() for f in futures)
            row["ceiling"] = ceiling
            row["passed_on"] = passed_on(element_solution(before), element_solution(after),
                                         references[row["scene"]][1], scene, ceiling)
            if max(row["passed_on"]) - min(row["passed_on"]) > 1e-9:
                raise CellFailed(f"{row['cell']}: the ceiling's shot passes on {row['passed_on']} "
                                 "of its power per colour: the form factors should not depend on "
                                 "the colour")
    return rows, references, cycles, scenes


QUADRATURE_CELLS = (200, 400, 800)   # the lower bound's grids: the finest shown, their spread its error


def ceiling_bound(scene):
    """(lower bound, its quadrature spread) of what the ceiling passes on (exact_share)."""
    ceiling, light = ceiling_patch(scene), light_patch(scene)
    values = [exact_share(scene, ceiling, light, n) for n in QUADRATURE_CELLS]
    return values[-1], max(values) - min(values)


# --- the markdown, every sentence made from the numbers -------------------------------------

PLACED = {"centre": "at the shooter's centre", "elements": "at each shooter element's centre"}


def percent(x, digits=1):
    return f"{100 * x:.{digits}f} %"


def signed(x, digits=1):
    return f"{100 * x:+.{digits}f} %"


def interval(value, half, digits=1):
    return f"{signed(value, digits)} [{signed(value - half, digits)}, {signed(value + half, digits)}]"


def change(before, after):
    """A verb for before -> after, with no claim beyond the numbers."""
    if after == before:
        return "leaves"
    return "lowers" if after < before else "raises"


def overlap(a, a_half, b, b_half):
    return abs(a - b) <= a_half + b_half


def back_faces_sentences(rows):
    out = []
    for scene in sorted({r["scene"] for r in rows}):
        for placement in ("centre", "elements"):
            block = hemicube_row(rows, scene, placement, "block")
            passing = hemicube_row(rows, scene, placement, "pass")
            if not block or not passing:
                continue
            resolved = ("the two intervals do not overlap" if not overlap(
                block["cycles_rms"], block["cycles_half"], passing["cycles_rms"],
                passing["cycles_half"]) else "the two intervals overlap")
            out.append(
                f"{scene}, the hemicube {PLACED[placement]}: pass {change(block['element_rms'], passing['element_rms'])} "
                f"the element RMS against the reference from {block['element_rms']:.3f} to "
                f"{passing['element_rms']:.3f}, {change(block['patch_rms'], passing['patch_rms'])} its "
                f"patch RMS from {block['patch_rms']:.3f} to {passing['patch_rms']:.3f}, and "
                f"{change(block['cycles_rms'], passing['cycles_rms'])} the patch RMS against Cycles "
                f"from {block['cycles_rms']:.3f} ± {block['cycles_half']:.3f} to "
                f"{passing['cycles_rms']:.3f} ± {passing['cycles_half']:.3f} ({resolved}).")
    return out


def ceiling_sentences(rows, reference_y, cycles_y, cycles_half):
    mine = [r for r in rows if "passed_on" in r]
    if not mine:
        return []
    rays = next((r for r in mine if r["method"][0] == "ray-traced"), None)
    out = []
    for placement in ("centre", "elements"):
        block = hemicube_row(mine, CEILING_SCENE, placement, "block")
        passing = hemicube_row(mine, CEILING_SCENE, placement, "pass")
        if not block or not passing:
            continue
        c = block["ceiling"]
        text = (f"The hemicube {PLACED[placement]}: the ceiling's first shot passes on "
                f"{percent(block['passed_on'][GREEN])} of its power with back faces blocking and "
                f"{percent(passing['passed_on'][GREEN])} with them passing")
        if rays:
            text += f" (the rays, {rays['method'][1]}: {percent(rays['passed_on'][GREEN])})"
        text += (f"; the ceiling's converged luminance is {block['patch_luminance'][c]:.4g} "
                 f"({signed(block['patch_luminance'][c] / reference_y - 1)} against the reference, "
                 f"{interval(*cycles_difference(block['patch_luminance'][c], cycles_y, cycles_half))} "
                 f"against Cycles) with block and {passing['patch_luminance'][c]:.4g} "
                 f"({signed(passing['patch_luminance'][c] / reference_y - 1)}, "
                 f"{interval(*cycles_difference(passing['patch_luminance'][c], cycles_y, cycles_half))}) "
                 "with pass.")
        out.append(text)
    return out


def cycles_difference(y, y_cycles, cycles_half):
    """(d, its 95 % half-width) of y against Cycles' y_cycles +- cycles_half (95 %)."""
    d = y / y_cycles - 1.0
    return d, (1.0 + d) * cycles_half / y_cycles


def markdown(rows, references, cycles, scenes, claims_files, claims_choices, sweep_file=SWEEP):
    machines = ", ".join(f"R = {R}, V = {V}" for R, V in sorted({(r["R"], r["V"]) for r in rows}))
    stops = ", ".join(f"{f:g}" for f in sorted({r["convergence"] for r in rows}))
    out = ["## The hemicube's choices: back faces, and the light below the ceiling", "",
           f"Written by `analysis/claims_hemicube.py` from `{shown(sweep_file)}` (docs/model.md, "
           f"\"The hemicube\"): the cells at {machines}, run until the largest unshot power is "
           f"below {stops} of the emitted power. A polygon the hemicube's eye "
           "sees from behind receives nothing; with `--hemicube-back-faces block` (the default) "
           "it takes cells and hides what lies beyond it, with `pass` it is culled.", ""]
    counts = ", ".join(f"{n} with `{choice}`" for choice, n in sorted(claims_choices.items()))
    out += [f"The claims' hemicube cells ({', '.join(f'`{shown(f)}`' for f in claims_files)}): "
            f"{counts or 'none'}.", ""]
    out += ["**What the figures rest on.** Every simulated figure is deterministic: the hemicube "
            "has no random numbers and the rays' parts are a fixed grid, so a rerun gives the "
            "same mesh. Its uncertainty is that of what it is held against:"]
    for scene in sorted(references):
        path, ref = references[scene]
        s = ref["self_agreement"]
        cycles_path, answers = cycles[scene]
        ref_rms, ref_half, _ = against_cycles(ref["patch_luminance"], answers)
        out.append(f"* {scene}: the reference `{shown(path)}` ({ref['element_count']} elements, "
                   f"K = {ref['samples']}): its self-agreement (K/4 against K) element RMS "
                   f"{s['element_rms']:.2e}, patch RMS {s['patch_rms']:.2e}; its patch RMS "
                   f"against Cycles (`{shown(cycles_path)}`, "
                   f"{answers.get('samples_per_pixel', answers.get('samples_per_texel'))} "
                   f"samples a pixel x {answers['seeds']} seeds) {ref_rms:.3f} ± {ref_half:.3f} "
                   "(95 %, from Cycles' standard errors).")
    out += ["", "### Back faces: block against pass", "",
            "| scene | method | iterations | element RMS vs reference | patch RMS vs reference "
            "| largest patch error (patch) | patch RMS vs Cycles (95 %) |",
            "|---|---|---:|---:|---:|---:|---:|"]
    for r in sorted(rows, key=lambda r: (r["scene"], r["method"])):
        converged = "" if r["converged"] else " (not converged)"
        out.append(f"| {r['scene']} | {method_label(r['method'])} | {r['iterations']}{converged} | "
                   f"{r['element_rms']:.3f} | {r['patch_rms']:.3f} | "
                   f"{r['patch_max']:.3f} ({r['worst_patch']}) | "
                   f"{r['cycles_rms']:.3f} ± {r['cycles_half']:.3f} |")
    out += [""] + [f"* {s}" for s in back_faces_sentences(rows)] + [""]
    ceiling_rows = [r for r in rows if "passed_on" in r]
    if ceiling_rows:
        scene = ceiling_rows[0]["scene"]
        c = ceiling_rows[0]["ceiling"]
        light = light_patch(scenes[scene])
        gap = (min(v[1] for v in scenes[scene]["patches"][c]["vertices"])
               - max(v[1] for v in scenes[scene]["patches"][light]["vertices"]))
        reference_y = references[scene][1]["patch_luminance"][c]
        row = next(p for p in cycles[scene][1]["patches"] if p[0] == c)
        cycles_y, cycles_half = row[8], Z95 * row[9]
        bound, spread = ceiling_bound(scenes[scene])
        out += [f"### The light below the ceiling ({scene}, patch {c})", "",
                f"The light (patch {light}) hangs {gap:.3g} below the ceiling (patch {c}), its "
                f"back to it. The ceiling's luminance: reference {reference_y:.4g}, Cycles "
                f"{cycles_y:.4g} ± {cycles_half:.2g} (95 %). What the ceiling's first shot "
                "passes on: the share of its power the other patches receive (from the meshes "
                "just before and at that shot; the module's docstring). Without the methods' "
                f"errors it is at least {percent(bound, 2)} ± {percent(spread, 2)} (1 − F(ceiling → "
                "open side) − F(ceiling → light), Lambert's contour integral at "
                f"{QUADRATURE_CELLS[-1]} x {QUADRATURE_CELLS[-1]} points of the ceiling; ± the "
                "spread over " + ", ".join(f"{n} x {n}" for n in QUADRATURE_CELLS) + " points; "
                "at least: where the light hides part of the open side it is subtracted twice).", "",
                "| method | first shot passes on | ceiling luminance | vs reference | "
                "vs Cycles (95 %) |", "|---|---:|---:|---:|---:|"]
        for r in sorted(ceiling_rows, key=lambda r: r["method"]):
            y = r["patch_luminance"][c]
            out.append(f"| {method_label(r['method'])} | {percent(r['passed_on'][GREEN])} | "
                       f"{y:.4g} | {signed(y / reference_y - 1)} | "
                       f"{interval(*cycles_difference(y, cycles_y, cycles_half))} |")
        out += [""] + [f"* {s}" for s in ceiling_sentences(rows, reference_y, cycles_y, cycles_half)]
        out.append("")
    return "\n".join(out)


def shown(path):
    path = Path(path)
    return path.relative_to(ROOT) if path.is_relative_to(ROOT) else path


# --- each method against its own structure, error against cost, reciprocity -----------------

COST_FIGURE = ROOT / "analysis" / "figures" / "claims_cost.png"
COSTS = (("simulated_seconds", "simulated s"), ("host_seconds", "host s"))
MEASURE_NAMES = {"b_own_element": "(b) own structure, element",
                 "b_own_patch": "(b) own structure, patch",
                 "a_patch": "(a) patch vs Cycles"}


def claims_sweeps():
    return sorted((ROOT / "experiments" / "claims").glob(CLAIMS_SWEEPS))


def like_for_like(results_root, jobs=2, sweep_files=None):
    """The claims' cells (claims.py's measure: their (a) and (b) with intervals), each with its
    (b) against its own structure and its result file's reciprocity count; the decisions on
    each measure; the scenes' hemicube structures and files."""
    import claims
    files = sweep_files or claims_sweeps()
    cells, seen = [], set()
    for s in sweep.load_all(files):
        for cell in s.cells:
            if cell.id not in seen:
                seen.add(cell.id)
                cells.append(cell)
    rows, truths, solutions = claims.measure(cells, Path(results_root).resolve(), jobs)
    own, scenes = {}, {}
    for cell in cells:
        if cell.scene not in own:
            own[cell.scene] = own_structure.OwnTruths(ROOT, cell.scene, cell.scene_sha256,
                                                      truths[cell.scene].emission)
            scenes[cell.scene] = json.loads(Path(cell.scene_file).read_text())
    own_structure.own_errors(rows, solutions, own, truths)
    folder = Path(results_root).resolve() / "claims" / "cells"
    for r in rows:
        result = json.loads((folder / f"{Path(r['cell']).stem}.json").read_text())
        r["above_one"] = own_structure.above_one(result)
    decisions = own_structure.decide(rows, solutions, own, truths)
    equal = {key: own_structure.at_equal_cost(rows, solutions, own, truths, key)
             for key in ("b_own_element", "b_own_patch", "a_patch")}
    return {"rows": rows, "own": own, "scenes": scenes, "decisions": decisions,
            "equal_cost": equal, "files": files}


def method_name(r):
    if r["form_factors"] == "hemicube":
        return f"hemicube ({r['placement']}) N={r['value']}"
    return f"rays M={r['value']}"


def error_figure(part):
    return "—" if part is None else claim_one.figure(*part, percent=True)


def decision_counts(decisions, key):
    mine = [d for d in decisions if d["measure"] == key]
    return {v: sum(1 for d in mine if d["verdict"] == v) for v in ("holds", "undecided", "does not hold")}, len(mine)


def verdict_sentence(decisions, key, placement=None):
    """How many decisions on measure `key` (and placement) hold, are undecided, do not hold,
    with the ratios' range."""
    mine = [d for d in decisions if d["measure"] == key and (placement is None or d["placement"] == placement)]
    if not mine:
        return None
    counts = {v: sum(1 for d in mine if d["verdict"] == v) for v in ("holds", "undecided", "does not hold")}
    ratios = [d["ratio"] for d in mine]
    where = f"the hemicube {PLACED[placement]}" if placement else "the hemicube"
    return (f"on {MEASURE_NAMES[key]}, {where} against the paper's method at its largest M: "
            f"\"much more accurate\" holds in {counts['holds']} of {len(mine)} comparisons, is "
            f"undecided in {counts['undecided']}, does not hold in {counts['does not hold']} "
            f"(ratios {min(ratios):.2f} to {max(ratios):.2f})")


def equal_cost_sentence(entries, key):
    judged = [e for e in entries if e["hemicube"] is not None]
    if not judged:
        return None
    counts = {v: sum(1 for e in judged if e["verdict"] == v) for v in ("holds", "undecided", "does not hold")}
    ratios = [e["ratio"] for e in judged]
    return (f"at equal simulated time on {MEASURE_NAMES[key]} (the hemicube's best setting "
            f"within each of the rays' cells' time): \"much more accurate\" holds in "
            f"{counts['holds']} of {len(judged)}, is undecided in {counts['undecided']}, does not "
            f"hold in {counts['does not hold']} (ratios {min(ratios):.2f} to {max(ratios):.2f})")


def reciprocity_rows(data):
    """Per scene and placement: the runs' counts (receivers a shot whose factor came out above
    1) and the exact structure's (element, shooter) pairs above 1, its largest factor."""
    out = []
    for scene in sorted(data["own"]):
        own = data["own"][scene]
        for placement in own_structure.PLACEMENTS:
            runs = sorted((r for r in data["rows"] if r["scene"] == scene
                           and r["form_factors"] == "hemicube" and r["placement"] == placement),
                          key=lambda r: r["value"])
            structure = own.data.get(placement)
            if not runs and structure is None:
                continue
            pairs = None if structure is None else structure.get("above_one", [])
            out.append({"scene": scene, "placement": placement,
                        "runs": [(r["value"], r["above_one"], r["iterations"]) for r in runs],
                        "pairs": None if pairs is None else len(pairs),
                        "largest": max((p[2] for p in pairs), default=None) if pairs else None,
                        "elements": len(structure["elements"]) if structure else None})
    return out


def accident_sentences(data, largest=3):
    out = []
    for scene in sorted(data["own"]):
        structure = data["own"][scene].data.get("centre")
        if structure is None:
            continue
        groups = own_structure.proximity(data["scenes"][scene], structure, "centre")
        if not groups:
            out.append(f"{scene}: no element's exact factor by reciprocity from a shooter's "
                       "centre exceeds 1.")
            continue
        named = "; ".join(
            f"patch {g['shooter']}'s centre {g['distance']:.4g} in front of patch "
            f"{g['receiver']} ({g['elements']} element{'s' if g['elements'] > 1 else ''} above 1, "
            f"up to {g['largest']:.3g})" for g in groups[:largest])
        more = f"; {len(groups) - largest} more pairs of patches" if len(groups) > largest else ""
        out.append(f"{scene}: {named}{more}.")
    return out


def cost_figure(data, path):
    """Per scene: (a) per patch and (b) against its own structure per patch, against simulated
    and host seconds; the front's cells ringed."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from ncube import plotting
    scenes = sorted({r["scene"] for r in data["rows"]})
    panels = [(key, cost) for key in ("a_patch", "b_own_patch") for cost, _ in COSTS]
    fig, axes = plt.subplots(len(panels), len(scenes), figsize=(5.5 * len(scenes), 4 * len(panels)),
                             squeeze=False, layout="constrained")
    for column, scene in enumerate(scenes):
        for row_index, (key, cost) in enumerate(panels):
            ax = axes[row_index][column]
            cells = own_structure.cost_rows(data["rows"], scene, key, cost)
            for kind, colour in (("rays", "C2"), ("centre", "C0"), ("elements", "C1")):
                mine = sorted((r for r in cells if (r["form_factors"] == "ray-traced") == (kind == "rays")
                               and (kind == "rays" or r["placement"] == kind)), key=lambda r: r["value"])
                if not mine:
                    continue
                ax.plot([r[cost] for r in mine], [r[key][0] for r in mine], marker="o", color=colour,
                        label="rays" if kind == "rays" else f"hemicube ({kind})")
                for r in mine:
                    ax.annotate(("M=" if kind == "rays" else "N=") + str(r["value"]),
                                (r[cost], r[key][0]), textcoords="offset points", xytext=(4, 4), fontsize=7)
            on = sorted((r for r in cells if r["on_front"]), key=lambda r: r[cost])
            ax.plot([r[cost] for r in on], [r[key][0] for r in on], linestyle="--", color="k",
                    marker="o", markerfacecolor="none", markersize=11, label="front")
            ax.set_xscale("log")
            ax.set_yscale("log")
            ax.set_xlabel(dict(COSTS)[cost].replace(" s", " seconds"))
            ax.set_ylabel(MEASURE_NAMES[key])
            ax.set_title(f"{scene}: {MEASURE_NAMES[key]} against {dict(COSTS)[cost]}", fontsize=10)
            ax.grid(True, which="both", alpha=0.3)
            ax.legend(fontsize=7)
    plotting.save(fig, path)


def like_for_like_markdown(data, figure_name="figures/claims_cost.png"):
    decisions = data["decisions"]
    out = ["## Each method against its own structure, and against cost", "",
           "**Which measure decides what (chosen before the runs, `docs/accuracy.md`, \"Each "
           "method against its own structure\").** The first claim is about form factors: it "
           "is decided on the form-factor error (b) of each method against the exact solution "
           "of **its own** structure: the rays against the receiver-centred one (receivers at "
           "element centres), the hemicube at the shooter's centre against exact point-to-element "
           "factors from the shooter's centroid turned around by the same reciprocity "
           "(`--structure hemicube-centre`), the hemicube at the elements against the same from "
           "each shooter element's centroid (`hemicube-elements`). What a user sees is decided "
           "on the total error (a) per patch against Cycles, which no structure enters. Both "
           "with the first claim's rule (\"much\": the ratio and its paired 95 % interval's low "
           "end at least 2, the project's convention; the intervals over patches as "
           "`docs/accuracy.md` says; no control for multiple comparisons: exploratory).", ""]
    sentences = [verdict_sentence(decisions, key, placement)
                 for key in ("b_own_element", "b_own_patch", "a_patch")
                 for placement in own_structure.PLACEMENTS]
    sentences += [equal_cost_sentence(data["equal_cost"][key], key)
                  for key in ("b_own_element", "b_own_patch", "a_patch")]
    out += [f"* {s[0].upper()}{s[1:]}." for s in sentences if s]
    missing = sorted(scene for scene, own in data["own"].items()
                     if any(p not in own.data for p in own_structure.PLACEMENTS))
    if missing:
        out += [f"* No hemicube structure committed for {', '.join(missing)} (at one placement "
                "or both): those cells' (b) against their own structure is not measured (—)."]
    out += ["", "### The decisions", "",
            "| scene | measure | hemicube | paper's method | hemicube's | ratio [95 %] | verdict |",
            "|---|---|---|---:|---:|---:|---|"]
    for d in decisions:
        out.append(f"| {d['scene']} | {MEASURE_NAMES[d['measure']]} | {d['placement']} "
                   f"N={d['resolution']} | M={d['samples']}: {error_figure(d['rays'])} | "
                   f"{error_figure(d['hemicube'])} | "
                   f"{claim_one.figure(d['ratio'], d['low'], d['high'])} | {d['verdict']} |")
    out += ["", "### Error against cost", "",
            f"![error against cost]({figure_name})", "",
            "Every converged cell at V = 0 (the rays under the paper's program, the hemicube "
            "under `shooters`, as in the tables above); **front**: no other cell costs at most "
            "as much with a lower error (the cheapest setting for its error), for simulated "
            "seconds (sim) and host seconds (host) apart. Host seconds are the run's wall time "
            "on the host (its result file's `host_seconds`, one host thread a cell, two cells "
            "at once), measured on a shared machine whose load varies: they rank settings "
            "roughly, they do not time them.", ""]
    for scene in sorted({r["scene"] for r in data["rows"]}):
        out += [f"#### {scene}", "",
                "| method | simulated s | host s | (a) patch vs Cycles | front (sim, host) | "
                "(b) own structure, patch | front (sim, host) | (b) own structure, element |",
                "|---|---:|---:|---:|---|---:|---|---:|"]
        fronts = {(key, cost): {r["id"] for r in own_structure.cost_rows(data["rows"], scene, key, cost)
                                if r["on_front"]}
                  for key in ("a_patch", "b_own_patch") for cost, _ in COSTS}
        rays, hemicube = own_structure.decidable(data["rows"], scene)
        for r in sorted(rays + hemicube, key=lambda r: r["simulated_seconds"]):
            def mark(key):
                return ", ".join(name for cost, name in (("simulated_seconds", "sim"), ("host_seconds", "host"))
                                 if r["id"] in fronts[(key, cost)]) or "—"
            out.append(f"| {method_name(r)} | {r['simulated_seconds']:.2f} | {r['host_seconds']:.2f} | "
                       f"{error_figure(r['a_patch'])} | {mark('a_patch')} | "
                       f"{error_figure(r['b_own_patch'])} | {mark('b_own_patch')} | "
                       f"{error_figure(r['b_own_element'])} |")
        out.append("")
    out += ["**At equal cost**", "",
            "At equal simulated time: for each of the rays' cells, the hemicube's best error among its cells whose "
            "simulated time is at most the rays' cell's (the times not like for like: the rays "
            "under the paper's program, the hemicube under `shooters`):", "",
            "| scene | measure | rays | its error | hemicube's best within its time | its error "
            "| ratio [95 %] | verdict |", "|---|---|---|---:|---|---:|---:|---|"]
    for key in ("b_own_element", "b_own_patch", "a_patch"):
        for e in data["equal_cost"][key]:
            ray = e["rays"]
            if e["hemicube"] is None:
                out.append(f"| {e['scene']} | {MEASURE_NAMES[key]} | M={ray['value']} "
                           f"({ray['simulated_seconds']:.2f} s) | {error_figure(ray[key])} | none "
                           "| — | — | — |")
                continue
            h = e["hemicube"]
            out.append(f"| {e['scene']} | {MEASURE_NAMES[key]} | M={ray['value']} "
                       f"({ray['simulated_seconds']:.2f} s) | {error_figure(ray[key])} | "
                       f"{method_name(h)} ({h['simulated_seconds']:.2f} s) | {error_figure(h[key])} | "
                       f"{claim_one.figure(e['ratio'], e['low'], e['high'])} | {e['verdict']} |")
    out += ["", "### Reciprocity in the open", "",
            "The hemicube turns the point factor it reads from an eye on the shooter around: "
            "F(receiver → shooter) = A_eye F(eye → receiver) / A_receiver, summed over the "
            "eyes. For a small receiver close in front of an eye this exceeds 1, a factor no "
            "receiver can have (it would receive more than the whole shooter sends per unit of "
            "its area). Every hemicube run counts such receivers, shot by shot "
            "(`counts.hemicube_reciprocal_above_one`, charged nothing); the exact structure of "
            "each placement lists its (element, shooter) pairs above 1 (`above_one`). The guard "
            "`--hemicube-reciprocity clamp` takes min(1, F) (assumed: no source for it was "
            "found; the literature's remedy for near receivers is to integrate over the "
            "shooter, as the paper's receiver-centred rays do: Wallace, Elmquist & Haines "
            "1989); it is a variant option of the method, not the claims' choice (as computed).", "",
            "| scene | placement | receiver-shots above 1 a run (N: count (iterations)) | exact structure: "
            "(element, shooter) pairs above 1 | largest exact factor |",
            "|---|---|---|---:|---:|"]
    for r in reciprocity_rows(data):
        runs = "; ".join(f"N={n}: {'—' if c is None else c} ({shots})" for n, c, shots in r["runs"]) or "—"
        pairs = "not computed" if r["pairs"] is None else str(r["pairs"])
        largest = "—" if r["largest"] is None else f"{r['largest']:.3g}"
        out.append(f"| {r['scene']} | {r['placement']} | {runs} | {pairs} | {largest} |")
    out += ["", "**The scenes' proximity accidents** (from the centre structure's pairs above "
            "1, nearest first: the shooter's centroid, the distance to the receiving patch's "
            "plane in scene units):", ""]
    out += [f"* {s}" for s in accident_sentences(data)]
    return "\n".join(out) + "\n"


def sections(results_root, jobs=2, sweep_file=SWEEP, claims_sweep_files=None, cost_figure_path=COST_FIGURE):
    """The two markdown sections (claims.py puts the first right after the first claim's
    receiver-centred table, the second at the page's end): each method against its own
    structure and against cost (the claims' cells, claims_sweep_files or
    experiments/claims/accuracy*.yaml; its figure written to cost_figure_path), and the back
    faces and the light below the ceiling (runs what is missing under
    results_root/claims/hemicube/)."""
    data = like_for_like(results_root, jobs, claims_sweep_files)
    if data["rows"]:
        cost_figure(data, cost_figure_path)
    rows, references, cycles, scenes = measure(results_root, jobs, sweep_file)
    files, choices = claims_back_faces()
    return (like_for_like_markdown(data),
            markdown(rows, references, cycles, scenes, files, choices, sweep_file))


def section(results_root, jobs=2, sweep_file=SWEEP, claims_sweep_files=None, cost_figure_path=COST_FIGURE):
    """Both sections of sections(), one after the other (this script's own output)."""
    own, choices = sections(results_root, jobs, sweep_file, claims_sweep_files, cost_figure_path)
    return own + "\n" + choices


@page.refusing_outputs("claims_hemicube.py")
def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--results", type=Path, default=ROOT / "results")
    parser.add_argument("--jobs", type=runner.bounded(1, 256), default=2, help="cells run at once (1 to 256)")
    parser.add_argument("--sweep", type=Path, default=SWEEP)
    parser.add_argument("--claims-sweeps", nargs="*", type=Path, default=None,
                        help="the first claim's sweep files (default experiments/claims/accuracy*.yaml)")
    parser.add_argument("--cost-figure", type=Path, default=COST_FIGURE,
                        help="where the error-against-cost figure goes")
    args = parser.parse_args()
    page.will_run("claims_hemicube.py", f"the cells of {page.shown(args.sweep)} without a result "
                  f"in {page.shown(args.results)}/claims/hemicube/ itself")
    try:
        print(section(args.results, args.jobs, args.sweep, args.claims_sweeps, args.cost_figure))
    except sweep.SweepError as e:
        print(f"claims_hemicube: {e}", file=sys.stderr)
        return 2
    except (CellFailed, accuracy.AccuracyError, RuntimeError, ValueError) as e:
        print(f"claims_hemicube: {e}", file=sys.stderr)
        return 4
    return 0


if __name__ == "__main__":
    sys.exit(main())
