#!/usr/bin/python3
"""The study over the paper's unknowns (analysis/unknowns.py, analysis/ncube/worlds.py):

1. the sampler: a drawn world's scenes have the paper's patch and element counts exactly; the
   default world's scenes are the committed files byte for byte; a world is the same draw every
   time from the same seed and index, another from another seed;
2. the page's statistics on canned worlds whose figures are worked out by hand here;
3. without results the page refuses with one line and exit 2 and writes nothing.

usage: tests/unknowns_test.py REPO_ROOT"""
import json
import math
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(sys.argv[1] if len(sys.argv) > 1 else Path(__file__).resolve().parent.parent)
sys.path.insert(0, str(ROOT / "analysis"))

from ncube import worlds  # noqa: E402
import unknowns  # noqa: E402

PAPER_COUNTS = {"scene0": (52, 1162), "scene1": (288, 4648), "scene2": (832, 18952),
                "scene3": (3328, 74368)}   # the paper's section 5, typed in from it
failures = []


def check(condition, what):
    if not condition:
        failures.append(what)
        print("FAIL: " + what)


# 1. The sampler.
default = worlds.draw_world(0, 41)
for scene, text in default["texts"].items():
    check(text == (ROOT / "scenes" / f"{scene}.json").read_text(),
          f"default world: {scene} differs from scenes/{scene}.json")
first = worlds.draw_world(1, 41)
again = worlds.draw_world(1, 41)
other = worlds.draw_world(1, 42)
check(first == again, "world 1 of seed 41 drawn twice differs")
check(first["texts"] != other["texts"], "world 1 of seeds 41 and 42 are the same scenes")
check(first["values"] != default["values"] or
      worlds.flat_values(first) != worlds.flat_values(default), "world 1 is the default world")
for scene, text in first["texts"].items():
    data = json.loads(text)
    counts = (len(data["patches"]), sum(p["elements"][0] * p["elements"][1]
                                        for p in data["patches"]))
    check(counts == PAPER_COUNTS[scene], f"world 1: {scene} has {counts}, the paper "
          f"{PAPER_COUNTS[scene]}")
    check(text != default["texts"][scene], f"world 1: {scene} is the default scene")
# Every drawn value lies in its range (or among its values).
unknown_list = worlds.load_unknowns()["drawn"]
flat = worlds.flat_values(first)
for u in unknown_list:
    keys = [u["name"]] if not u["per_scene"] else \
        [f"{s}.{u['name']}" for s in worlds.SCENE_NAMES if worlds.applies(u, s)]
    for key in keys:
        v = flat[key]
        ok = v in u["values"] if "values" in u else u["range"][0] <= v <= u["range"][1]
        check(ok, f"world 1: {key} = {v} outside its range in analysis/unknowns.json")

# A world's runs: its tables are the paper sweeps' 41 distinct cells and the memory probe, and
# the one sweep that runs them holds the very cells (identities) the per-table files name.
from ncube import sweep as sweeps  # noqa: E402
with tempfile.TemporaryDirectory() as folder:
    study = Path(folder)
    worlds.write_world(first, study)
    names, _, committed = worlds.calibration()
    model = worlds.write_cost_model(first, study, names, committed)
    files = worlds.tables_sweeps(first, study, model)
    combined = worlds.combined_sweep(files, "w01-tables", study / "w01-tables.json")
    per_table = {c.file for f in files for c in sweeps.load(f).cells}
    run_as_one = [c.file for c in sweeps.load(combined).cells]
    check(len(per_table) == 42 and set(run_as_one) == per_table and
          len(run_as_one) == len(set(run_as_one)),
          f"world 1's tables: {len(per_table)} distinct cells, {len(run_as_one)} run as one")
    document = json.loads(Path(model).read_text())["parameters"]
    check(document["element_bytes"]["value"] == first["values"]["element_bytes"],
          "world 1's cost model lacks its element record size")

# 2. The statistics on canned worlds. Three cells; four drawn worlds and the default world.
cells = [["T1 scene1 R=4 V=0", 1, "scene1", 4, 0, 4.0, False],
         ["T1 scene1 R=8 V=0", 1, "scene1", 8, 0, 2.0, False],
         ["T5 scene0 R=8 V=7", 5, "scene0", 8, 7, 10.0, False]]


def canned_world(index, a, b, c, element_bytes, findings):
    values = {"patch_order": "generator", "samples": 64, "block_size": 100,
              "element_bytes": element_bytes}
    for scene in worlds.SCENE_NAMES:
        for k, key in enumerate(worlds.SCENE_KEYS):
            values[f"{scene}.{key}"] = False if key == "turn_panels" else \
                1.0 + 0.01 * ((index * 7 + k * 3) % 5)
    return {"index": index, "values": values, "refused_draws": {s: 0 for s in PAPER_COUNTS},
            "fit": {"values": [17.0, 27.0], "how": "two parameters", "rounds": 1,
                    "residuals": [0, 0]},
            "cells": {cells[0][0]: a, cells[1][0]: b, cells[2][0]: c},
            "status": {cells[0][0]: "ok", cells[1][0]: "ok", cells[2][0]: "ok"},
            "stats": {"median": 0.1 * index, "p90": 0.2 * index},
            "findings": dict(zip(unknowns.FINDINGS, findings))}


R, N = "reproduced", "not reproduced"
# Cell 1: 1, 2, 3, 4 -> median 2.5, 5th percentile 1 + 0.05 x 3 = 1.15, 95th 3.85: the
# paper's 4.0 is above by 0.15. Cell 2: 1.5 .. 3 -> inside. Cell 3's log value is exactly
# linear in the element record (e^(b / 100)): that group explains all of its spread.
summary = {"study_seed": 0, "cells": cells, "worlds": [
    canned_world(0, 4.0, 2.0, 10.0, 184, [R] * 6),
    canned_world(1, 1.0, 1.5, math.exp(1.80), 180, [R, N, R, R, R, N]),
    canned_world(2, 2.0, 2.5, math.exp(2.00), 200, [R, N, R, N, R, N]),
    canned_world(3, 3.0, 3.0, math.exp(2.10), 210, [R, N, R, R, R, N]),
    canned_world(4, 4.0, 2.0, math.exp(2.20), 220, [N, N, R, R, R, N])]}
drawn = summary["worlds"][1:]
rows = {r["key"]: r for r in unknowns.cell_table(summary, drawn)}
span = rows[cells[0][0]]["interval"]
check(abs(span["median"] - 2.5) < 1e-12 and abs(span["low"] - 1.15) < 1e-12 and
      abs(span["high"] - 3.85) < 1e-12, f"cell 1's interval {span}, want 2.5 in 1.15 - 3.85")
check(not rows[cells[0][0]]["inside"] and rows[cells[1][0]]["inside"],
      "inside: cell 1 should be outside, cell 2 inside")
check(not rows[cells[2][0]]["inside"], "cell 3 (paper 10 against e^1.8..e^2.2) should be outside")
counts = unknowns.finding_counts(drawn)
check(counts == {"F1": 3, "F2": 0, "F3": 4, "F4": 3, "F5": 4, "F6": 0},
      f"finding counts {counts}")
errors = unknowns.error_distribution(drawn, "median")
check(abs(errors["median"] - 0.25) < 1e-12 and errors["min"] == 0.1 and
      abs(errors["max"] - 0.4) < 1e-12, f"error distribution {errors}")
shares = unknowns.sensitivity(summary, drawn)[cells[2][0]]
check(abs(shares["element record"] - 1.0) < 1e-9, f"cell 3: element record explains "
      f"{shares['element record']}, want 1")
check(shares["samples"] == 0.0 and shares["patch order"] == 0.0,
      "constant unknowns explain nothing")
misses = {m["key"]: m for m in unknowns.outside(list(rows.values()))}
check(set(misses) == {cells[0][0], cells[2][0]}, f"outside: {sorted(misses)}")
check(misses[cells[0][0]]["above"] and abs(misses[cells[0][0]]["miss_seconds"] - 0.15) < 1e-12,
      "cell 1's miss: 0.15 s above")
text = unknowns.page(summary, "x.png", "canned")
check("inside the simulation's 90 % interval (5th to 95th percentile over the worlds) in 1 of "
      "the 3 cells" in text, "the page's count of cells inside")
check("| F1 | 3 of 4 (75 %) | reproduced |" in text, "the page's F1 line")

# 3. The refusal.
with tempfile.TemporaryDirectory() as folder:
    out = Path(folder) / "out"
    out.mkdir()
    completed = subprocess.run(["/usr/bin/python3", str(ROOT / "analysis" / "unknowns.py"),
                                "--results", str(Path(folder) / "none"), "--worlds", "2",
                                "--out-dir", str(out)], capture_output=True, text=True)
    check(completed.returncode == 2, f"refusal: exit {completed.returncode}, want 2")
    check(len(completed.stderr.strip().splitlines()) == 1, "refusal: not one line: " +
          completed.stderr)
    check(not any(out.iterdir()) and not (Path(folder) / "none").exists(),
          "refusal: something was written")

if failures:
    sys.exit(1)
print("PASS: the sampler (counts, default world byte for byte, seeded) and the page's "
      "statistics on canned worlds")
