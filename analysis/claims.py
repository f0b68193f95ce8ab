#!/usr/bin/python3
"""The paper's claims, measured (issue 31 item 5): error against simulated time to convergence.

Reads the sweep files experiments/claims/accuracy*.yaml with the sweep tool's own loader (the
same validation, defaults and cell identity as experiments/sweep), runs every cell's ./simulate
command itself with --mesh added (a sweep cell has no mesh output: docs/accuracy.md, "The
study"), keeps each cell's result and mesh under RESULTS/claims/ named after the cell's
identity (a finished cell is not run again; a changed option or input is another cell), and
compares each mesh with its scene's reference (analysis/reference/<scene>.json, made by
experiments/claims/references) by analysis/ncube/accuracy.py. Writes analysis/claims.md and
analysis/figures/claims_accuracy.png.

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
import subprocess
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from ncube import accuracy, output_file, page, paths, plotting, sweep  # noqa: E402

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


def measure(cells, results, jobs):
    folder = results / "claims" / "cells"
    folder.mkdir(parents=True, exist_ok=True)
    references = {}
    rows = []
    with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
        runs = list(pool.map(lambda c: run_cell(c, folder), cells))
    for cell, (result_path, mesh_path) in zip(cells, runs):
        reference_path = ROOT / "analysis" / "reference" / f"{cell.scene}.json"
        if cell.scene not in references:
            if not reference_path.exists():
                raise SystemExit(f"claims: no reference for {cell.scene}: run "
                                 f"experiments/claims/references {cell.scene}")
            references[cell.scene] = accuracy.read_reference(reference_path)
        reference = references[cell.scene]
        if reference["scene_sha256"] != cell.scene_sha256:
            raise SystemExit(f"claims: {reference_path} is of another {cell.scene} (its "
                             "scene_sha256 differs): run experiments/claims/references again")
        result = json.loads(result_path.read_text())
        error = accuracy.compare(accuracy.solution_from_ply(mesh_path), reference,
                                 str(mesh_path), str(reference_path))
        name, value = knob(cell)
        rows.append({"scene": cell.scene, "series": series_of(cell), "label": series_label(cell),
                     "R": cell.R, "V": cell.V,
                     "form_factors": cell.options.get("form_factors", "ray-traced"),
                     "placement": cell.options.get("hemicube_placement", "centre"),
                     "parallelisation": cell.options.get("parallelisation", "receivers"),
                     "knob": name, "value": value, "status": result["status"],
                     "converged": result["converged"], "iterations": result["iterations"],
                     "simulated_seconds": result["simulated_seconds"],
                     "element_rms": error["element_rms"], "patch_rms": error["patch_rms"],
                     "patch_max": error["patch_max"], "worst_patch": error["worst_patch"],
                     "cell": cell.file})
    return rows, references


MUCH = 2.0   # "much more accurate": the hemicube's error at least this many times the rays'
MEASURES = (("element_rms", "element RMS"), ("patch_rms", "patch RMS"))
PLACEMENTS = {"centre": "shooter's centre", "elements": "centre of each shooter element"}


def v0_pair(rows, scene):
    """The scene's V = 0 cells of both methods on one configuration: the rays at their
    largest M, and the hemicube's cells, by (placement, N)."""
    mine = [r for r in rows if r["scene"] == scene and r["V"] == 0 and r["status"] == "ok"
            and r["parallelisation"] == "receivers"]
    rays = [r for r in mine if r["form_factors"] == "ray-traced"]
    hemicube = [r for r in mine if r["form_factors"] == "hemicube"]
    if not rays or not hemicube:
        return None, []
    best = max(rays, key=lambda r: r["value"])
    return best, [r for r in hemicube if r["R"] == best["R"]]


def claim_one_comparisons(rows):
    """[(scene, measure label, rays' row, hemicube's row, ratio)] for every hemicube cell
    beside the paper's method on the same V = 0 configuration."""
    out = []
    for scene in sorted({r["scene"] for r in rows}):
        rays, hemicube = v0_pair(rows, scene)
        for key, label in MEASURES:
            for h in sorted(hemicube, key=lambda r: (r["placement"], r["value"])):
                ratio = h[key] / rays[key] if rays[key] > 0 else float("inf")
                out.append((scene, label, rays, h, ratio))
    return out


def claim_one_sentence(rows):
    """One sentence: the first claim holds, holds only where, or does not hold. "Much more
    accurate": the hemicube's error at least MUCH times the rays' (the paper's method at its
    largest M), per element and per patch, on every scene with both methods' V = 0 cells."""
    comparisons = claim_one_comparisons(rows)
    if not comparisons:
        return ("not measured: the sweeps have no scene with both methods' converged V = 0 "
                "cells on one configuration.")
    holding = [c for c in comparisons if c[4] >= MUCH]
    def figures(scene, label):
        mine = [c for c in comparisons if c[0] == scene and c[1] == label]
        rays = mine[0][2]
        era = [c for c in mine if c[3]["placement"] == "centre" and c[3]["value"] == 100]
        key = "element_rms" if label == "element RMS" else "patch_rms"
        best = min(mine, key=lambda c: c[3][key])
        text = f"{scene} {label}: rays (M={rays['value']}) {100 * rays[key]:.1f} %"
        if era:
            text += f", hemicube N=100 centre {100 * era[0][3][key]:.1f} %"
        text += (f", best hemicube ({best[3]['placement']} N={best[3]['value']}) "
                 f"{100 * best[3][key]:.1f} %")
        return text
    pairs = sorted({(c[0], c[1]) for c in comparisons})
    stated = "; ".join(figures(scene, label) for scene, label in pairs)
    figure = " (figure: `figures/claims_accuracy.png`; " + stated + ")"
    if len(holding) == len(comparisons):
        return (f"**holds**: every hemicube cell's error is at least {MUCH:g} times the "
                f"paper's method's, per element and per patch, on every scene" + figure + ".")
    if not holding:
        return (f"**does not hold**: no hemicube cell's error reaches {MUCH:g} times the "
                f"paper's method's, per element or per patch, on any scene" + figure + ".")
    where = []
    for placement in ("centre", "elements"):
        mine = [c for c in comparisons if c[3]["placement"] == placement]
        held = [c for c in mine if c[4] >= MUCH]
        ratios = f"hemicube / rays {min(c[4] for c in mine):.2f} to {max(c[4] for c in mine):.2f}" if mine else ""
        resolutions = ", ".join(str(n) for n in sorted({c[3]["value"] for c in mine}))
        if not mine:
            continue
        if len(held) == len(mine):
            where.append(f"against the hemicube at the {PLACEMENTS[placement]} at every N measured "
                         f"({resolutions}), on every scene, per element and per patch ({ratios})")
            continue
        if not held:
            where.append(f"not against the hemicube at the {PLACEMENTS[placement]} ({ratios})")
            continue
        parts = []
        for scene, label in pairs:
            ns = [c[3]["value"] for c in held if c[0] == scene and c[1] == label]
            if ns:
                parts.append(f"{scene} {label} at N in " + "{" + ", ".join(str(n) for n in sorted(ns)) + "}")
        where.append(f"against the hemicube at the {PLACEMENTS[placement]} on "
                     + ", ".join(parts) + f" ({ratios})")
    return (f"**holds only** " + "; ".join(where) + figure + ".")


def claim_one_table(rows):
    """The markdown table behind the sentence: every hemicube cell against the rays."""
    out = ["| scene | measure | paper's method (M) | hemicube (placement, N) | "
           "hemicube / rays |", "|---|---|---:|---:|---:|"]
    for scene, label, rays, h, ratio in claim_one_comparisons(rows):
        key = "element_rms" if label == "element RMS" else "patch_rms"
        out.append(f"| {scene} R={rays['R']} V=0 | {label} | {rays[key]:.3f} (M={rays['value']}) | "
                   f"{h[key]:.3f} ({h['placement']}, N={h['value']}) | {ratio:.2f} |")
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


def schemes_section(results):
    """The second claim's section (analysis/claims_schemes.py, another part of the study),
    when that module is there."""
    try:
        import claims_schemes
    except ImportError:
        return None
    return claims_schemes.section(results)


def plot(rows, path):
    import matplotlib.pyplot as plt
    scenes = sorted({r["scene"] for r in rows})
    fig, axes = plt.subplots(3, len(scenes), figsize=(5.5 * len(scenes), 11), squeeze=False,
                             layout="constrained")
    for column, scene in enumerate(scenes):
        mine = [r for r in rows if r["scene"] == scene]
        for row_index, (measure, title) in enumerate(
                (("element_rms", "element RMS relative error"),
                 ("patch_rms", "patch RMS relative error"),
                 ("patch_max", "largest patch error"))):
            ax = axes[row_index][column]
            for series in sorted({r["series"] for r in mine}):
                points = sorted((r for r in mine if r["series"] == series),
                                key=lambda r: r["value"])
                xs = [r["simulated_seconds"] for r in points]
                ys = [r[measure] for r in points]
                ax.plot(xs, ys, marker="o", label=points[0]["label"])
                for r in points:
                    short = "M" if r["knob"] == "samples" else "N"
                    ax.annotate(f"{short}={r['value']}", (r["simulated_seconds"], r[measure]),
                                textcoords="offset points", xytext=(4, 4), fontsize=8)
            ax.set_xscale("log")
            ax.set_yscale("log")
            ax.set_xlabel("simulated seconds to convergence")
            ax.set_ylabel(title)
            ax.set_title(f"{scene}: {title}")
            ax.grid(True, which="both", alpha=0.3)
            ax.legend(fontsize=8)
    plotting.save(fig, path)


def shown(path):
    """A path as the page names it: from the repository's root when inside it."""
    path = Path(path)
    return path.relative_to(ROOT) if path.is_relative_to(ROOT) else path


def markdown(rows, references, sweep_files, picture_labels=(), schemes=None):
    out = ["# The paper's claims, measured", "",
           "Written by `analysis/claims.py` (issue 31 item 5) from the sweeps "
           + ", ".join(f"`{shown(f)}`" for f in sweep_files)
           + "; how to run it: `docs/reproduce.md`; the reference and the error measure: "
           "`docs/accuracy.md`.", "",
           "Error: the area-weighted RMS of the elements' relative luminance errors against the "
           "reference (element RMS), the same over patches (patch RMS), and the largest patch "
           "error. Time: the simulated seconds of the whole run to convergence (largest unshot "
           "power below 1e-4 of the emitted power).", "", "## The references", "",
           "| scene | elements | K | self-agreement K/4 vs K: element RMS | patch RMS | "
           "largest patch | host seconds |", "|---|---:|---:|---:|---:|---:|---:|"]
    for scene, ref in sorted(references.items()):
        s = ref["self_agreement"]
        out.append(f"| {scene} | {ref['element_count']} | {ref['samples']} | "
                   f"{s['element_rms']:.2e} | {s['patch_rms']:.2e} | {s['patch_max']:.2e} | "
                   f"{ref['host_seconds']:.0f} |")
    out += ["", "## Error against simulated time to convergence", "",
            "![error against time](figures/claims_accuracy.png)", ""]
    for scene in sorted({r["scene"] for r in rows}):
        out += [f"### {scene}", "",
                "| method | knob | iterations | simulated s | element RMS | patch RMS | "
                "largest patch error (patch) |", "|---|---:|---:|---:|---:|---:|---:|"]
        for r in sorted((r for r in rows if r["scene"] == scene),
                        key=lambda r: (r["label"], r["value"])):
            converged = "" if r["converged"] else " (not converged)"
            out.append(f"| {r['label']} | {r['knob']}={r['value']} | {r['iterations']}{converged} | "
                       f"{r['simulated_seconds']:.2f} | {r['element_rms']:.3f} | "
                       f"{r['patch_rms']:.3f} | {r['patch_max']:.3f} ({r['worst_patch']}) |")
        out.append("")
    if picture_labels:
        out += ["## The pictures", "",
                "Left to right: " + "; ".join(picture_labels) + ". The hemicube's artifacts "
                "(aliasing of small or distant elements in its cells, a shooter judged from "
                "one point) against the rays' smooth shading.", "",
                "![pictures](figures/claims_pictures.png)", ""]
    out += ["## The first claim: ray tracing against the hemicube", "",
            "*Ray-traced form factors are much more accurate than the hemicube* (section 6), "
            f"judged on the configurations both methods run (V = 0; `much': the hemicube's "
            f"error at least {MUCH:g} times the paper's method's at its largest M):", ""]
    out += claim_one_table(rows) + ["", "1. " + claim_one_sentence(rows), ""]
    # The second claim's section brings its own heading (analysis/claims_schemes.py).
    out += [schemes.rstrip(), ""] if schemes else [
        "## The second claim: receivers against shooters", "",
        "2. *No need to distribute radiosity values after the form factors* (section 6): "
        "not measured here (`analysis/claims_schemes.py` not there, or `--no-schemes`).", ""]
    return "\n".join(out)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--results", type=Path, default=ROOT / "results")
    parser.add_argument("--jobs", type=int, default=2, help="cells run at once")
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
    args = parser.parse_args()
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
        if not (ROOT / "analysis" / "reference" / f"{scene}.json").exists():
            raise SystemExit(f"claims: no reference for {scene}: run "
                             f"experiments/claims/references {scene}")
    page.will_run("claims.py", f"the cells of {', '.join(page.shown(f) for f in args.sweeps)} "
                  f"without a result in {page.shown(args.results)}/claims/ itself")
    try:
        rows, references = measure(cells, args.results.resolve(), args.jobs)
        labels = (pictures(picture_cells, args.results.resolve(), args.jobs, args.pictures_figure)
                  if picture_cells else [])
    except (RuntimeError, accuracy.AccuracyError) as e:
        print(f"claims: {e}", file=sys.stderr)
        return 4
    plot(rows, args.figure)
    schemes = None if args.no_schemes else schemes_section(args.results.resolve())
    # --- the hemicube's section (analysis/claims_hemicube.py, issue 38 item 6): included whole
    import claims_hemicube
    try:
        hemicube = "" if args.no_hemicube else claims_hemicube.section(args.results.resolve(), args.jobs)
    except (claims_hemicube.CellFailed, accuracy.AccuracyError, sweep.SweepError) as e:
        print(f"claims: {e}", file=sys.stderr)
        return 4
    # --- end of the hemicube's section
    output_file.write(args.out, markdown(rows, references, [s.file for s in sweeps], labels,
                                         schemes) + "\n" + (hemicube.rstrip() + "\n" if hemicube else ""))
    written = [args.out, args.figure] + ([args.pictures_figure] if labels else [])
    print(f"claims: {len(rows)} cells; written: " + ", ".join(str(p) for p in written))
    return 0


if __name__ == "__main__":
    sys.exit(main())
