#!/usr/bin/python3
"""Do the calibration and the findings survive another order of the patches? Writes
analysis/patch-order.md and analysis/patch-order.json.

usage: analysis/patch_order.py [--seeds 1 2 3] [--results DIR] [--cores N]

Which patches a visibility processor holds follows the order of the scene file (section 3: an
even 1/V share; docs/model.md), and so does the imbalance between the visibility processors
that the second fitted parameter is identified through. The paper's patch order is unknown;
scenes/generate.py writes rooms first, then furniture. For every seed this script

1. writes the four scenes with their patches in a seeded random order (same patches, same
   elements, same name) under DIR/seed<k>/scenes/;
2. refits the two calibrated parameters on the cells of analysis/calibration.json with those
   scenes (the simulated times are affine in the two costs to within the busiest node's
   switch, so a 2x2 solve and up to three Newton corrections); when no pair of positive costs
   matches both cells, it says so and falls back to one factor on both fitted costs (their
   ratio as calibrated), fitted on the first calibration cell;
3. runs the paper's sweeps (experiments/table1..5.json) with those scenes and that cost model
   through experiments/sweep into DIR/seed<k>/results/;
4. reads them like analysis/report.py does: median and 90th-percentile |error| and the verdict
   on each finding F1-F6 (ncube.findings, the report's one definition).

Seed 0 stands for the committed order and cost model (the results of experiments/reproduce in
results/, run if missing). The output depends only on the seeds and the inputs.
"""

from ncube.interpreter import use_project_python  # noqa: E402

use_project_python()   # Debian's /usr/bin/python3 (README.md, "Use")

import argparse
import json
import random
import re
import subprocess
import sys
from pathlib import Path


# numpy (0.1 s of CPU a start) is imported by the functions that use it: --help and refusals need none.

from ncube import simulate as simulator  # noqa: E402
from ncube import sweep as sweeps  # noqa: E402
from ncube.paper.cells import load_inputs, unique_cells  # noqa: E402
from ncube.paper.sections import error_statistics  # noqa: E402
from ncube import findings as fnd  # noqa: E402
from ncube import opening as op  # noqa: E402
from ncube import page  # noqa: E402
from ncube.paths import ANALYSIS, EXPERIMENTS, PLATFORMS, ROOT, SCENES  # noqa: E402

SCENE_NAMES = ["scene0", "scene1", "scene2", "scene3"]
TABLES = ["table1", "table2", "table3", "table4", "table5"]
FINDINGS = [fnd.finding_f1, fnd.finding_f2, fnd.finding_f3, fnd.finding_f4, fnd.finding_f5,
            fnd.finding_f6]


def shuffled_scene(source, target, seed):
    """The scene with its patches in a seeded random order, one patch per line."""
    scene = json.loads(Path(source).read_text())
    random.Random(seed).shuffle(scene["patches"])
    head = [f"{json.dumps(k)}: {json.dumps(v)}" for k, v in scene.items() if k != "patches"]
    patches = ",\n  ".join(json.dumps(p) for p in scene["patches"])
    Path(target).write_text("{" + ",\n ".join(head) + ',\n "patches": [\n  ' + patches +
                            "\n ]\n}\n")


def write_cost_model(values, path):
    document = json.loads((PLATFORMS / "cost_model.json").read_text())
    for name, value in values.items():
        document["parameters"][name]["value"] = float(value)
    Path(path).write_text(json.dumps(document, indent=1) + "\n")


def calibration_cells():
    calibration = json.loads((ANALYSIS / "calibration.json").read_text())
    paper = json.loads((ANALYSIS / "paper_tables.json").read_text())
    cells = []
    for c in calibration["cells"]:
        table = next(t for t in paper["tables"] if t["table"] == c["table"])
        row = next(r for r in table["rows"] if (r["R"], r["V"]) == (c["R"], c["V"]))
        spec = next(s for s in sweeps.load(EXPERIMENTS / f"table{c['table']}.json").cells
                    if (s.scene, s.R, s.V) == (c["scene"], c["R"], c["V"]))
        cells.append((c, float(row[c["scene"]]), spec))
    return calibration["parameters"], cells


def fit(names, cells, scenes_dir, workdir):
    """(values, how): the fitted costs for the scenes of `scenes_dir`."""
    import numpy as np
    base = json.loads((PLATFORMS / "cost_model.json").read_text())["parameters"]
    x0 = np.array([float(base[n]["value"]) for n in names])
    target = np.array([paper for _, paper, _ in cells])
    model = Path(workdir) / "trial_cost_model.json"

    def times(x):
        write_cost_model(dict(zip(names, x)), model)
        return np.array([simulator.run(scenes_dir / f"{c['scene']}.json", spec.options,
                                       spec.platform_file, model, spec.cfg,
                                       accept_out_of_memory=False,
                                       threads=0)["seconds_per_iteration"]
                         for c, _, spec in cells])

    y0 = times(x0)
    jacobian = np.empty((len(cells), len(names)))
    for j in range(len(names)):
        probe = x0.copy()
        probe[j] *= 1.25
        jacobian[:, j] = (times(probe) - y0) / (probe[j] - x0[j])
    x = x0 + np.linalg.solve(jacobian, target - y0)
    if np.all(x > 0):
        for _ in range(3):
            y = times(x)
            if np.all(np.abs(y - target) <= 1e-3 * target):
                return dict(zip(names, x)), "two parameters"
            x = x + np.linalg.solve(jacobian, target - y)
            if not np.all(x > 0):
                break
        else:
            return dict(zip(names, x)), "two parameters (residual above 0.1 %)"
    # No positive pair: one factor on both costs, fitted on the first cell (affine in the
    # factor: two runs and a correction).
    first = 0
    scale = 1.0
    for _ in range(3):
        y = times(x0 * scale)[first]
        y_probe = times(x0 * scale * 1.1)[first]
        slope = (y_probe - y) / (0.1 * scale)
        scale += (target[first] - y) / slope
        if abs(times(x0 * scale)[first] - target[first]) <= 1e-3 * target[first]:
            break
    return dict(zip(names, x0 * scale)), "one factor (no positive two-parameter fit)"


def run_tables(scenes_dir, cost_model, out_dir, cores):
    """The paper sweeps with these scenes and this cost model, into out_dir/results."""
    folder = out_dir / "sweeps"
    folder.mkdir(parents=True, exist_ok=True)
    files = []
    for name in TABLES:
        sweep = json.loads((EXPERIMENTS / f"{name}.json").read_text())
        sweep["options"] = dict(sweep.get("options", {}), cost_model=str(cost_model))
        for cell in sweep.get("cells", []):
            cell["scene"] = str(scenes_dir / f"{Path(cell['scene']).stem}.json")
        if "grid" in sweep and "scene" in sweep["grid"]:
            sweep["grid"]["scene"] = [str(scenes_dir / f"{Path(s).stem}.json")
                                      for s in sweep["grid"]["scene"]]
        (folder / f"{name}.json").write_text(json.dumps(sweep, indent=1) + "\n")
        files.append(str(folder / f"{name}.json"))
    subprocess.run([str(ROOT / "experiments" / "sweep"), *files, "--results",
                    str(out_dir / "results"), "--cores", str(cores)], check=True,
                   stdout=subprocess.DEVNULL)
    return out_dir / "results"


def judge(results_dir):
    inputs = load_inputs(results_dir)
    stats = error_statistics(unique_cells(inputs.cells))
    verdicts = {}
    for judge_one in FINDINGS:
        finding = judge_one(inputs.cells)
        verdicts[finding.name] = finding.status
    return stats, verdicts


def opening(found):
    """The page's opening, from its own table: the error, the verdicts and the fitted costs
    under the random orders against the generator's."""
    rows = found[0][1]
    generator, shuffled = rows[0], rows[1:]
    error = "median |error|"
    findings = [k for k in generator if re.fullmatch(r"F\d", k)]
    costs = [k for k in generator if k.startswith("`")]
    robust = [f for f in findings if all(r[f] == generator[f] for r in shuffled)]
    moving = [f for f in findings if f not in robust]
    spread = f"the spread over {len(shuffled)} seeded random orders, each refitted; no wider interval"
    medians = [op.number(r[error]) for r in shuffled]
    moved = max(abs(op.number(r[c]) / op.number(generator[c]) - 1) * 100
                for r in shuffled for c in costs)
    sentences = [
        op.Sentence(f"Over {len(shuffled)} random patch orders the median |error| is "
                    f"{min(medians):.1f} to {max(medians):.1f} % against "
                    f"{generator[error]} with the order of scenes/generate.py", spread),
        op.Sentence("The verdicts that stay under every order: " + (", ".join(robust) or "none") +
                    "; that depend on it: " + (", ".join(
                        f"{f} ({generator[f]} with the generator's order, "
                        f"{sum(r[f] == generator[f] for r in shuffled)} of {len(shuffled)} random "
                        "orders agree)" for f in moving) or "none"), spread),
        op.Sentence(f"The fitted costs move by at most {moved:.1f} %: " + "; ".join(
            f"{c} {min(op.number(r[c]) for r in shuffled):.2f} to "
            f"{max(op.number(r[c]) for r in shuffled):.2f} (committed {generator[c]})"
            for c in costs), spread)]
    return sentences


@page.refusing_outputs("patch_order.py")
def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seeds", type=int, nargs="+", default=[1, 2, 3, 4])
    parser.add_argument("--results", type=Path, default=ROOT / "results" / "patch-order")
    parser.add_argument("--cores", type=int, default=2)
    args = parser.parse_args()
    page.will_run("patch_order.py", f"a refit and the paper's sweeps for each of the seeds "
                  f"{', '.join(map(str, args.seeds))} into {page.shown(args.results)}/ itself")
    names, cells = calibration_cells()
    fitted_now = {n: float(json.loads((PLATFORMS / "cost_model.json").read_text())
                           ["parameters"][n]["value"]) for n in names}

    rows = []
    committed = ROOT / "results"
    if not (committed / "plan.json").exists():
        subprocess.run([str(ROOT / "experiments" / "reproduce"), "--only",
                        ",".join(TABLES), "--cores", str(args.cores)], check=True)
    stats, verdicts = judge(committed)
    rows.append({"seed": 0, "order": "scenes/generate.py", "fit": "committed",
                 "parameters": fitted_now, "stats": stats, "findings": verdicts})
    for seed in args.seeds:
        out_dir = args.results.resolve() / f"seed{seed}"
        scenes_dir = out_dir / "scenes"
        scenes_dir.mkdir(parents=True, exist_ok=True)
        for name in SCENE_NAMES:
            shuffled_scene(SCENES / f"{name}.json", scenes_dir / f"{name}.json", seed)
        values, how = fit(names, cells, scenes_dir, out_dir)
        cost_model = out_dir / "cost_model.json"
        write_cost_model(values, cost_model)
        stats, verdicts = judge(run_tables(scenes_dir, cost_model, out_dir, args.cores))
        rows.append({"seed": seed, "order": f"random (seed {seed})", "fit": how,
                     "parameters": values, "stats": stats, "findings": verdicts})
        print(f"seed {seed}: {how}, " + ", ".join(f"{n}={v:.4g}" for n, v in values.items()) +
              f", median {100 * stats['median']:.1f} %, " +
              " ".join(f"{k}:{v}" for k, v in verdicts.items()), flush=True)

    finding_names = list(rows[0]["findings"])
    lines = ["# Patch order: do the calibration and the findings survive it?", "",
             "Written by `analysis/patch_order.py` (its docstring says how). Seed 0 is the "
             "order of `scenes/generate.py` with the committed cost model; the others are "
             "seeded random orders of the same patches, each with its own refit of the two "
             "calibrated parameters on the cells of `analysis/calibration.json`.", "",
             "| order | fit | " + " | ".join(f"`{n}`" for n in names) +
             " | median |error| | 90th pct | " + " | ".join(finding_names) + " |",
             "|---|---|" + "--:|" * len(names) + "--:|--:|" + "---|" * len(finding_names)]
    for row in rows:
        lines.append(f"| {row['order']} | {row['fit']} | " +
                     " | ".join(f"{row['parameters'][n]:.2f}" for n in names) +
                     f" | {100 * row['stats']['median']:.1f} % | "
                     f"{100 * row['stats']['p90']:.1f} % | " +
                     " | ".join(row["findings"][f] for f in finding_names) + " |")
    shuffled = [r for r in rows if r["seed"] != 0]
    medians = [100 * r["stats"]["median"] for r in shuffled]
    robust = [f for f in finding_names
              if all(r["findings"][f] == rows[0]["findings"][f] for r in shuffled)]
    lines += ["", f"Over the {len(shuffled)} random orders: median |error| "
              f"{min(medians):.1f} to {max(medians):.1f} % (generator order "
              f"{100 * rows[0]['stats']['median']:.1f} %). Verdicts the same under every "
              f"order: {', '.join(robust) or 'none'}; verdicts that depend on the order: "
              f"{', '.join(f for f in finding_names if f not in robust) or 'none'}."]
    for name in names:
        values = [r["parameters"][name] for r in shuffled]
        lines.append(f"`{name}`: {min(values):.2f} to {max(values):.2f} over the random "
                     f"orders (committed {fitted_now[name]:.2f}).")
    body = "\n".join(lines) + "\n"
    page.write(ANALYSIS / "patch-order.md",
               op.with_opening(body, opening(op.tables(body)), "analysis/patch_order.py"))
    page.write(ANALYSIS / "patch-order.json", json.dumps(rows, indent=1, sort_keys=True) + "\n")
    print("wrote analysis/patch-order.md")
    return 0


if __name__ == "__main__":
    sys.exit(main())
