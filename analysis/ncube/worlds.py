"""Plausible worlds: the paper's reproduction with every unknown of analysis/unknowns.json drawn
(analysis/unknowns.py writes the page, docs/reproduce.md says how to run it).

A world is one draw of the unknowns: the four scenes regenerated with their drawn free choices
at the paper's exact patch and element counts (scenes/generator/variant.py), the drawn samples,
block size and element record size. World 0 is the default world (every unknown at its default:
the committed scenes, byte for byte). For every world the two calibrated parameters are
refitted on the cells of analysis/calibration.json (the fit is part of the model), then the
paper's 40 cells run (experiments/table1..5.json with the world's scenes and cost model) and one
memory probe for finding F5 (scene3 at R=4, V=15, set-up only).

**The fit.** analysis/calibrate.py's procedure (Newton steps with a finite-difference Jacobian
on the simulated seconds per iteration of the calibration cells), warm-started from the
committed values: the Jacobian once, from the committed costs and each raised by 25 % (the
times are affine in the two costs as long as the busiest node stays the same), one solve, then
up to three verification rounds, each correcting with the same Jacobian, until every cell is
within 0.1 % of the paper. When no pair of positive costs solves both cells (as under a random
patch order, analysis/patch-order.md), both costs are scaled by one factor (their calibrated
ratio) fitted on the first cell, as analysis/patch_order.py does. On the default world the
procedure returns the committed values (analysis/unknowns.md says by how much).

**Every run is a cell of a sweep** (experiments/sweep): the fit's rounds and the tables are
sweep files written under <study>/worlds/wNN/ and run into <study>/results/, on the local cores
or on Slurm. A cell's identity is its configuration and the contents of its scene and cost
model, so a stopped study run again keeps every finished cell: the sweep files of each round
are rewritten identically from the results already there, and only missing cells run. A
verification cell is the very cell the tables run (same scene, options and cost model), so it
runs once."""
import json
import math
import random
import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from . import results as results_io
from . import sweep as sweeps
from .paths import ANALYSIS, EXPERIMENTS, PLATFORMS, ROOT, SCENES

sys.path.insert(0, str(SCENES))
from generator.choices import SceneChoices  # noqa: E402
from generator.variant import scene_text  # noqa: E402

SCENE_NAMES = ["scene0", "scene1", "scene2", "scene3"]
TABLES = ["table1", "table2", "table3", "table4", "table5"]
UNKNOWNS_FILE = ANALYSIS / "unknowns.json"
PROBE_FACTOR = 1.25         # each cost raised by 25 % for the Jacobian
TOLERANCE = 1e-3            # a fitted cell within 0.1 % of the paper
VERIFY_ROUNDS = 3
MAX_REDRAWS = 200           # draws of one scene's geometry refused by the generator's checks
SCENE_KEYS = ["room_scale_x", "room_scale_y", "room_scale_z", "furniture_width",
              "furniture_height", "piece_element_size", "turn_panels"]


class WorldError(Exception):
    """A world that cannot be drawn or fitted; the message says which and why."""


def load_unknowns(path=UNKNOWNS_FILE):
    return json.loads(Path(path).read_text())


def draw_value(rng, unknown):
    kind = unknown["distribution"]
    if kind == "choice":
        return rng.choice(unknown["values"])
    low, high = unknown["range"]
    if kind == "uniform":
        return round(rng.uniform(low, high), 3)
    if kind == "log-uniform":
        return round(math.exp(rng.uniform(math.log(low), math.log(high))), 3)
    if kind == "uniform-int":
        return rng.randint(low, high)
    if kind == "log-uniform-int":
        return int(round(math.exp(rng.uniform(math.log(low), math.log(high)))))
    raise WorldError(f"{UNKNOWNS_FILE}: unknown {unknown['name']}: distribution {kind!r}")


def applies(unknown, scene):
    return scene in unknown.get("scenes", SCENE_NAMES)


def scene_choices(world, scene):
    v = world["scenes"][scene]
    return SceneChoices(room_scale=(v["room_scale_x"], v["room_scale_y"], v["room_scale_z"]),
                        furniture_width=v["furniture_width"],
                        furniture_height=v["furniture_height"],
                        piece_element_size=v["piece_element_size"],
                        turn_panels=v["turn_panels"], order=world["values"]["patch_order"],
                        order_seed=v["order_seed"])


def draw_world(index, study_seed, unknowns=None):
    """World `index` of the study seeded `study_seed`: {"index", "values" (the unknowns drawn
    once), "scenes" (each scene's drawn geometry, its order seed and how many draws the
    generator's checks refused), "texts" (the scene files)}. World 0: every default."""
    unknowns = unknowns or load_unknowns()
    drawn = unknowns["drawn"]
    rng = random.Random(f"unknowns:{study_seed}:{index}")
    default = index == 0
    world = {"index": index, "study_seed": study_seed, "values": {}, "scenes": {}, "texts": {}}
    for u in drawn:
        if not u["per_scene"]:
            world["values"][u["name"]] = u["default"] if default else draw_value(rng, u)
    for scene in SCENE_NAMES:
        refused = 0
        while True:
            values = {u["name"]: (u["default"] if default or not applies(u, scene)
                                  else draw_value(rng, u))
                      for u in drawn if u["per_scene"]}
            values["order_seed"] = 0 if default else rng.randrange(2 ** 31)
            world["scenes"][scene] = values
            text, problems = scene_text(scene, scene_choices(world, scene))
            if not problems:
                break
            refused += 1
            if default or refused >= MAX_REDRAWS:
                raise WorldError(f"world {index}: {scene}: {refused} draws refused by the "
                                 f"generator's checks, the last: {problems[0]}")
        values["refused_draws"] = refused
        world["texts"][scene] = text
    return world


def flat_values(world):
    """{unknown name or "sceneK.name": drawn value}: every drawn value of the world."""
    flat = dict(world["values"])
    for scene, values in world["scenes"].items():
        for key in SCENE_KEYS:
            flat[f"{scene}.{key}"] = values[key]
    return flat


# ---------------------------------------------------------------------------------------------
# Files of a world.

def write_if_changed(path, text):
    """Writes `text` unless the file holds it already (a resumed study rewrites nothing)."""
    path = Path(path)
    if path.exists() and path.read_text() == text:
        return path
    path.parent.mkdir(parents=True, exist_ok=True)
    tmp = path.with_name(path.name + ".tmp")
    tmp.write_text(text)
    tmp.replace(path)
    return path


def world_folder(study, index):
    return Path(study) / "worlds" / f"w{index:02d}"


def write_world(world, study):
    folder = world_folder(study, world["index"])
    for scene, text in world["texts"].items():
        write_if_changed(folder / "scenes" / f"{scene}.json", text)
    record = {k: v for k, v in world.items() if k != "texts"}
    write_if_changed(folder / "world.json", json.dumps(record, indent=1, sort_keys=True) + "\n")
    return folder


def calibration():
    """(parameter names, cells with their paper value, committed values)."""
    import calibrate   # analysis/calibrate.py: its paper_value and cost-model house style
    document = json.loads((ANALYSIS / "calibration.json").read_text())
    tables = json.loads((ANALYSIS / "paper_tables.json").read_text())
    committed = json.loads((PLATFORMS / "cost_model.json").read_text())["parameters"]
    names = document["parameters"]
    cells = [dict(c, paper=calibrate.paper_value(tables, c)) for c in document["cells"]]
    return names, cells, [float(committed[n]["value"]) for n in names]


def rounded(x):
    return [float(f"{v:.6g}") for v in x]   # as analysis/calibrate.py records a fit


def write_cost_model(world, study, names, x):
    """The world's cost model with the costs x: platforms/cost_model.json with the world's
    element record size and the two costs, in the house style; named by its content."""
    import calibrate
    document = json.loads((PLATFORMS / "cost_model.json").read_text())
    document["parameters"]["element_bytes"]["value"] = world["values"]["element_bytes"]
    for name, value in zip(names, x):
        document["parameters"][name]["value"] = value
    folder = world_folder(study, world["index"]) / "cost_models"
    folder.mkdir(parents=True, exist_ok=True)
    tmp = folder / "trial.json.tmp"
    calibrate.write_cost_model(document, tmp)
    text = tmp.read_text()
    tmp.unlink()
    tag = "-".join(f"{v:.6g}" for v in x)
    return write_if_changed(folder / f"costs-{tag}.json", text)


def table_sweep(world, study, table, cost_model):
    """The paper's sweep experiments/<table>.json with the world's scenes, samples, block size
    and cost model."""
    folder = world_folder(study, world["index"])
    document = json.loads((EXPERIMENTS / f"{table}.json").read_text())
    document["name"] = f"w{world['index']:02d}-{table}"
    document["options"] = dict(document.get("options", {}), samples=world["values"]["samples"],
                               block_size=world["values"]["block_size"],
                               cost_model=str(cost_model))
    for cell in document["cells"]:
        cell["scene"] = str(folder / "scenes" / f"{cell['scene']}.json")
    return document


def calibration_sweep(world, study, round_name, cost_models, cells):
    """The calibration cells under each cost model of a round, as one sweep."""
    picked = []
    for c in cells:
        table = table_sweep(world, study, f"table{c['table']}", cost_models[0])
        options = {k: v for k, v in table["options"].items() if k != "cost_model"}
        for model in cost_models:
            picked.append(dict(options, scene=str(world_folder(study, world["index"]) / "scenes"
                                                  / f"{c['scene']}.json"),
                               R=c["R"], V=c["V"], cost_model=str(model)))
    return {"name": f"w{world['index']:02d}-{round_name}", "measure": "seconds_per_iteration",
            "description": f"world {world['index']}: calibration cells, {round_name}",
            "cells": picked}


def memory_sweep(world, study, cost_model):
    folder = world_folder(study, world["index"])
    return {"name": f"w{world['index']:02d}-memory", "measure": "seconds_per_iteration",
            "description": "finding F5's probe: scene3 at R=4, V=15 set up, not iterated",
            "options": {"samples": world["values"]["samples"],
                        "block_size": world["values"]["block_size"],
                        "cost_model": str(cost_model), "iterations": 0},
            "cells": [{"scene": str(folder / "scenes" / "scene3.json"), "R": 4, "V": 15}]}


def write_sweep(document, study, world_index):
    path = world_folder(study, world_index) / "sweeps" / f"{document['name']}.json"
    return write_if_changed(path, json.dumps(document, indent=1) + "\n")


def seconds(results_dir, sweep_file):
    """The sweep's cells' seconds per iteration in order, None when a cell has no result."""
    out = []
    for cell in sweeps.load(sweep_file).cells:
        result = results_io.read(Path(results_dir) / cell.file)
        ok = result is not None and result.get("status") == "ok" and \
            results_io.mismatch(result, cell) is None
        out.append(result["seconds_per_iteration"] if ok else None)
    return out


# ---------------------------------------------------------------------------------------------
# The fit, replayed from the results there are: each call either says which sweep must run
# next or gives the fit.

@dataclass
class FitState:
    done: bool
    sweep_file: Path = None      # the next round to run, when not done
    values: list = None
    how: str = ""
    rounds: int = 0
    residuals: list = None
    cost_model: Path = None


def fit_world(world, study, results_dir):
    names, cells, x0 = calibration()
    target = np.array([c["paper"] for c in cells])
    x0 = np.array(x0)
    points = [x0.copy()]
    for j in range(len(names)):
        probe = x0.copy()
        probe[j] *= PROBE_FACTOR
        points.append(probe)
    models = [write_cost_model(world, study, names, rounded(p)) for p in points]
    jacobian_file = write_sweep(calibration_sweep(world, study, "fit-jacobian", models, cells),
                                study, world["index"])
    times = seconds(results_dir, jacobian_file)
    if None in times:
        return FitState(False, jacobian_file)
    # times are cell-major: cell i under model k at i * len(models) + k
    y = np.array(times).reshape(len(cells), len(models))
    y0 = y[:, 0]
    jacobian = np.empty((len(cells), len(names)))
    for j in range(len(names)):
        jacobian[:, j] = (y[:, j + 1] - y0) / (points[j + 1][j] - x0[j])
    x = x0 + np.linalg.solve(jacobian, target - y0)
    one_factor = not np.all(x > 0)
    slope = float(jacobian[0] @ x0)   # d y_0 / d (factor on both costs)
    if one_factor:
        x = x0 * (1 + (target[0] - y0[0]) / slope)
    how = ("one factor on both costs, fitted on the first cell (no positive two-parameter fit)"
           if one_factor else "two parameters")
    for round_number in range(1, VERIFY_ROUNDS + 1):
        x = np.array(rounded(x))
        model = write_cost_model(world, study, names, x)
        verify_file = write_sweep(calibration_sweep(world, study, f"fit-verify{round_number}",
                                                    [model], cells), study, world["index"])
        y_now = seconds(results_dir, verify_file)
        if None in y_now:
            return FitState(False, verify_file)
        y_now = np.array(y_now)
        residual = (y_now - target) / target
        judged = residual[:1] if one_factor else residual
        if np.all(np.abs(judged) <= TOLERANCE) or round_number == VERIFY_ROUNDS:
            if not np.all(np.abs(judged) <= TOLERANCE):
                how += f"; residual above {100 * TOLERANCE:g} % after {VERIFY_ROUNDS} rounds"
            return FitState(True, values=[float(v) for v in x], how=how, rounds=round_number,
                            residuals=[float(r) for r in residual], cost_model=model)
        if one_factor:
            factor = float(x[0] / x0[0]) + (target[0] - y_now[0]) / slope
            x = x0 * factor
        else:
            x = x + np.linalg.solve(jacobian, target - y_now)
            if not np.all(x > 0):
                x = np.maximum(x, 1e-3)
    raise AssertionError("not reached")


def tables_sweeps(world, study, cost_model):
    files = [write_sweep(table_sweep(world, study, t, cost_model), study, world["index"])
             for t in TABLES]
    files.append(write_sweep(memory_sweep(world, study, cost_model), study, world["index"]))
    return files


def run_sweeps(files, results_dir, sweep_args):
    """experiments/sweep on these files into results_dir; a WorldError when it fails."""
    command = [str(ROOT / "experiments" / "sweep"), *map(str, files), "--results",
               str(results_dir), *sweep_args]
    completed = subprocess.run(command)
    if completed.returncode != 0:
        raise WorldError(f"experiments/sweep stopped with exit {completed.returncode} (its "
                         "message is above); run the same command again to go on")


# ---------------------------------------------------------------------------------------------
# A world's outcome, read as analysis/report.py reads the paper's cells.

def world_outcome(world, study, results_dir, fit):
    """{"cells": {cell key: simulated or None}, "status": {key: status}, "stats", "findings",
    "fit"}; None when a table cell of the world has no result yet."""
    from . import findings as fnd
    from .paper.cells import Cell, Inputs, build_cells, read_json, unique_cells
    from .paper.sections import error_statistics
    files = tables_sweeps(world, study, fit.cost_model)
    loaded = {t: sweeps.load(f) for t, f in zip(TABLES, files)}
    inputs = Inputs(paper=read_json(ANALYSIS / "paper_tables.json"), sweeps=loaded,
                    results_dir=Path(results_dir), platform_files={},
                    calibration=read_json(ANALYSIS / "calibration.json"))
    build_cells(inputs)
    if any(c.key is not None and c.result is None for c in inputs.cells):
        return None
    probe_spec = sweeps.load(files[-1]).cells[0]
    probe = results_io.read(Path(results_dir) / probe_spec.file)
    if probe is None:
        return None
    cells = list(inputs.cells) + [Cell(table=0, quantity="memory", scene="scene3", R=4, V=15,
                                       T=64, sim_R=4, sim_V=15, key=probe_spec.file,
                                       result=probe)]
    verdicts = {}
    for judge in (fnd.finding_f1, fnd.finding_f2, fnd.finding_f3, fnd.finding_f4,
                  fnd.finding_f5, fnd.finding_f6):
        finding = judge(cells)
        verdicts[finding.name] = finding.status
    compared = [c for c in unique_cells(inputs.cells) if c.paper is not None]
    return {"index": world["index"], "values": flat_values(world),
            "refused_draws": {s: v["refused_draws"] for s, v in world["scenes"].items()},
            "fit": {"values": fit.values, "how": fit.how, "rounds": fit.rounds,
                    "residuals": fit.residuals},
            "cells": {cell_key(c): c.sim for c in compared},
            "status": {cell_key(c): c.status for c in compared},
            "stats": error_statistics(compared), "findings": verdicts}


def cell_key(cell):
    return f"T{cell.table} {cell.scene} R={cell.R} V={cell.V}"


def paper_cells():
    """[(key, table, scene, R, V, paper value, calibration?)] of the 40 compared cells, in the
    report's order (Tables 3 and 4 repeat rows of Tables 1 and 2: each comparison once)."""
    from .paper.cells import Inputs, build_cells, read_json, unique_cells
    inputs = Inputs(paper=read_json(ANALYSIS / "paper_tables.json"), sweeps={},
                    results_dir=Path("/nonexistent"), platform_files={},
                    calibration=read_json(ANALYSIS / "calibration.json"))
    build_cells(inputs)
    return [(cell_key(c), c.table, c.scene, c.R, c.V, c.paper, c.calibration)
            for c in unique_cells(inputs.cells) if c.paper is not None]


def combined_sweep(files, name, path):
    """One sweep file holding the cells of several of these sweep files (each cell with its
    sweep's options written into it, each configuration once): run as one, so that the sweep
    tool writes one summary (a CSV and its plots) instead of one a file. The cells keep their
    identities, so the files read back (`seconds`, `world_outcome`) find their results."""
    cells, seen = [], set()
    for file in files:
        document = json.loads(Path(file).read_text())
        for cell in document["cells"]:
            merged = dict(document.get("options", {}), **cell)
            merged.pop("paper_row", None)     # not part of a cell's identity
            key = json.dumps(merged, sort_keys=True)
            if key not in seen:
                seen.add(key)
                cells.append(merged)
    document = {"name": name, "measure": "seconds_per_iteration",
                "description": f"the cells of {len(files)} sweep files of the study over the "
                               "unknowns (analysis/unknowns.py)", "cells": cells}
    return write_if_changed(path, json.dumps(document, indent=1) + "\n")
