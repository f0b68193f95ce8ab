#!/usr/bin/python3
"""The reproduction with intervals over what the paper does not tell (analysis/unknowns.md).

Writes analysis/unknowns.md, analysis/unknowns-worlds.json and
analysis/figures/unknowns_intervals.png.

usage: analysis/unknowns.py [--run] [--worlds N] [--seed S] [--results DIR] [--cores N]
                            [--slurm] [--summary FILE] [--out-dir DIR]

--run draws the worlds (analysis/unknowns.json; the sampler and the fit: analysis/ncube/worlds.py),
runs every world's fit and tables through experiments/sweep into DIR (default
results/unknowns; resumable: run the same command again after a stop), then writes the page.
Without --run it reads what DIR holds and refuses, with one line and exit 2, writing nothing,
when a world's results are missing. --summary FILE writes the page from a saved
unknowns-worlds.json instead (no results needed; the test's canned worlds). The worlds and the
study seed default to experiments/unknowns/study.json. World 0 is the default world (the
committed scenes and model); the intervals are over the drawn worlds 1..N.
"""
import argparse
import json
import sys
import time
from pathlib import Path

from ncube.interpreter import use_project_python  # noqa: E402

use_project_python()   # Debian's /usr/bin/python3 (README.md, "Use")

# numpy (0.1 s of CPU a start) is imported by the functions that use it: a refusal needs none.
from ncube import opening as op  # noqa: E402
from ncube import input_file  # noqa: E402
from ncube import page as page_rule  # noqa: E402
from ncube.paths import ANALYSIS, EXPERIMENTS, ROOT  # noqa: E402

STUDY = EXPERIMENTS / "unknowns" / "study.json"
INTERVAL = (5, 95)          # the 90 % interval: 5th to 95th percentile over the drawn worlds
FIT_TOLERANCE = 1e-3        # a world's calibration cells match the paper to 0.1 % (the fit's
                            # own tolerance, ncube.worlds.TOLERANCE): an interval is read as
                            # that much wider, so that a fitted cell counts as inside
FINDINGS = ["F1", "F2", "F3", "F4", "F5", "F6"]


class Refusal(Exception):
    pass


# ---------------------------------------------------------------------------------------------
# Running the study.

def run_study(count, seed, study, sweep_args):
    from ncube import worlds as w
    unknowns = w.load_unknowns()
    results_dir = study / "results"
    drawn = [w.draw_world(i, seed, unknowns) for i in range(count + 1)]
    for world in drawn:
        w.write_world(world, study)
    print(f"unknowns: {count} worlds drawn and the default world, scenes written under "
          f"{study}/worlds", flush=True)
    for round_number in range(1 + w.VERIFY_ROUNDS + 1):
        states = [w.fit_world(world, study, results_dir) for world in drawn]
        pending = [s.sweep_file for s in states if not s.done]
        if not pending:
            break
        print(f"unknowns: fit round for {len(pending)} world(s)", flush=True)
        w.run_sweeps([w.combined_sweep(pending, f"fit-round{round_number}",
                                       study / "sweeps" / f"fit-round{round_number}.json")],
                     results_dir, sweep_args)
    files = []
    for world, state in zip(drawn, states):
        name = f"w{world['index']:02d}-tables"
        files.append(w.combined_sweep(w.tables_sweeps(world, study, state.cost_model), name,
                                      study / "sweeps" / f"{name}.json"))
    print(f"unknowns: the tables of {len(drawn)} worlds", flush=True)
    w.run_sweeps(files, results_dir, sweep_args)


def collect(count, seed, study):
    """Every world's outcome; a Refusal naming the first world without its results."""
    from ncube import worlds as w
    unknowns = w.load_unknowns()
    results_dir = study / "results"
    outcomes = []
    for i in range(count + 1):
        folder = w.world_folder(study, i)
        if not (folder / "world.json").exists() or not results_dir.is_dir():
            raise Refusal(f"{folder}: world {i} not drawn yet")
        world = w.draw_world(i, seed, unknowns)
        state = w.fit_world(world, study, results_dir)
        if not state.done:
            raise Refusal(f"{study}: world {i}'s fit has not run ({state.sweep_file})")
        outcome = w.world_outcome(world, study, results_dir, state)
        if outcome is None:
            raise Refusal(f"{study}: world {i}'s tables have not run")
        outcomes.append(outcome)
    names, _, committed = w.calibration()
    return {"study_seed": seed, "worlds": outcomes, "cells": w.paper_cells(),
            "committed": dict(zip(names, committed))}


# ---------------------------------------------------------------------------------------------
# Statistics (pure functions of the summary: tests/unknowns_test.sh checks them on canned
# worlds).

def interval(values):
    import numpy as np
    values = np.array([v for v in values if v is not None], dtype=float)
    if values.size == 0:
        return None
    low, high = np.percentile(values, INTERVAL)
    return {"n": int(values.size), "median": float(np.median(values)), "low": float(low),
            "high": float(high)}


def contains(span, value, shift=0.0, factor=1.0):
    low = (span["low"] + shift) * factor * (1 - FIT_TOLERANCE)
    high = (span["high"] + shift) * factor * (1 + FIT_TOLERANCE)
    return low <= value <= high


def cell_table(summary, worlds):
    rows = []
    for key, table, scene, R, V, paper, calibration in summary["cells"]:
        values = [w["cells"].get(key) for w in worlds]
        span = interval(values)
        inside = span is not None and contains(span, paper)
        rows.append({"key": key, "table": table, "scene": scene, "R": R, "V": V,
                     "paper": paper, "calibration": calibration, "interval": span,
                     "inside": inside,
                     "missing": sum(v is None for v in values),
                     "statuses": sorted({w["status"][key] for w in worlds
                                         if w["cells"].get(key) is None})})
    return rows


def finding_counts(worlds):
    return {f: sum(w["findings"][f] == "reproduced" for w in worlds) for f in FINDINGS}


def error_distribution(worlds, which):
    import numpy as np
    values = np.array([w["stats"][which] for w in worlds], dtype=float)
    return {"min": float(values.min()), "p5": float(np.percentile(values, 5)),
            "median": float(np.median(values)), "p95": float(np.percentile(values, 95)),
            "max": float(values.max())}


def design_columns(worlds, names):
    """The regressors of one group of unknowns: numbers as they are (a block size on a log
    scale), a choice one-hot (its first value the baseline); constant columns dropped."""
    import numpy as np
    columns = []
    for name in names:
        values = [w["values"][name] for w in worlds]
        if all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in values):
            column = np.log(values) if name == "block_size" else np.array(values, dtype=float)
            columns.append(column)
        else:
            levels = sorted({json.dumps(v) for v in values})
            for level in levels[1:]:
                columns.append(np.array([json.dumps(v) == level for v in values], dtype=float))
    return [c for c in columns if np.ptp(c) > 0]


def r_squared(y, columns):
    """Share of the variance of y that a least-squares fit on the columns explains."""
    import numpy as np
    if not columns or np.var(y) == 0:
        return 0.0
    design = np.column_stack([np.ones_like(y)] + columns)
    coefficients, *_ = np.linalg.lstsq(design, y, rcond=None)
    residual = y - design @ coefficients
    return float(max(0.0, 1 - residual.var() / y.var()))


def groups_for(scene):
    """The groups of unknowns of the sensitivity table for a cell of `scene`."""
    own = lambda keys: [f"{scene}.{k}" for k in keys]  # noqa: E731
    groups = [("room size", own(["room_scale_x", "room_scale_y", "room_scale_z"])),
              ("furniture size", own(["furniture_width", "furniture_height"])),
              ("element split", own(["piece_element_size"])),
              ("panels turned", own(["turn_panels"]) if scene != "scene0" else []),
              ("patch order", ["patch_order"]),
              ("samples", ["samples"]),
              ("block size", ["block_size"]),
              ("element record", ["element_bytes"])]
    if scene != "scene2":   # the calibration scene's geometry reaches every cell via the fit
        groups.append(("scene2 geometry (the fit's)",
                       [f"scene2.{k}" for k in ["room_scale_x", "room_scale_y", "room_scale_z",
                                                "furniture_width", "furniture_height",
                                                "piece_element_size"]]))
    else:
        groups.append(("scene2 geometry (the fit's)", []))
    return groups


GROUP_NAMES = [g for g, _ in groups_for("scene1")]


def sensitivity(summary, worlds):
    """{cell key: {group: share}}: the R^2 of the cell's log value over the worlds on each
    group's drawn values alone; also the chance level of each group (its column count over
    the worlds less one). Worlds without the cell's value are left out of its row."""
    import numpy as np
    table = {}
    for key, table_number, scene, *_ in summary["cells"]:
        have = [w for w in worlds if w["cells"].get(key) is not None]
        if len(have) < 4:
            continue
        y = np.log([w["cells"][key] for w in have])
        table[key] = {group: r_squared(y, design_columns(have, names))
                      for group, names in groups_for(scene)}
    return table


def chance_levels(worlds, scene="scene1"):
    return {group: len(design_columns(worlds, names)) / max(1, len(worlds) - 1)
            for group, names in groups_for(scene)}


def width(span):
    return (span["high"] - span["low"]) / span["median"]


def scale_comparison(summary, worlds, first):
    """How the intervals change from the first `first` worlds to all of them."""
    import numpy as np
    small = {r["key"]: r for r in cell_table(summary, worlds[:first])}
    large = {r["key"]: r for r in cell_table(summary, worlds)}
    ratios = [width(large[k]["interval"]) / width(small[k]["interval"])
              for k in large if large[k]["interval"] and small[k]["interval"]
              and width(small[k]["interval"]) > 0]
    changed = [k for k in large if large[k]["inside"] != small[k]["inside"]]
    return {"first": first, "all": len(worlds), "median_width_ratio": float(np.median(ratios)),
            "inside_small": sum(r["inside"] for r in small.values()),
            "inside_large": sum(r["inside"] for r in large.values()), "changed": changed}


# ---------------------------------------------------------------------------------------------
# What lies outside: each miss with its direction, size, and what would close it, sized from
# the cells of its own table.

def outside(rows):
    misses = []
    for row in rows:
        span = row["interval"]
        if row["inside"] or span is None:
            continue
        above = row["paper"] > span["high"]
        edge = span["high"] if above else span["low"]
        misses.append(dict(row, above=above, miss_seconds=row["paper"] - edge,
                           miss_share=row["paper"] / edge - 1,
                           gap_median=row["paper"] - span["median"]))
    return misses


def group_fits(rows, table, scene, exclude_one_node=False):
    """The two simplest mechanisms for the cells of one table and scene, each sized to fit
    them as a whole: an additive cost d (seconds per iteration; per run in Table 5: the median
    of paper - median world) and a factor f on the simulated time (a cost per unit of work
    that differs from what the fit on scene2 gives: the median of paper / median world); for
    each, the cells it leaves outside their interval shifted or scaled by it."""
    import numpy as np
    picked = [r for r in rows if r["table"] == table and r["scene"] == scene and r["interval"]
              and not (exclude_one_node and r["R"] * (r["V"] + 1) == 1)]
    if not picked:
        return None
    d = float(np.median([r["paper"] - r["interval"]["median"] for r in picked]))
    f = float(np.median([r["paper"] / r["interval"]["median"] for r in picked]))
    return {"cells": len(picked), "d": d, "f": f,
            "d_outside": [r["key"] for r in picked if not contains(r["interval"], r["paper"], shift=d)],
            "f_outside": [r["key"] for r in picked if not contains(r["interval"], r["paper"], factor=f)]}


def per_doubling(rows, table, scene, R):
    """The paper's time at R/2 over that at R (V=0), when both are in the table."""
    here = next((r for r in rows if (r["table"], r["scene"], r["R"], r["V"]) == (table, scene, R, 0)), None)
    half = next((r for r in rows if (r["table"], r["scene"], r["R"], r["V"]) == (table, scene, R // 2, 0)), None)
    if here is None or half is None:
        return None
    return half["paper"] / here["paper"], half["interval"]["median"] / here["interval"]["median"]


def mechanism(miss, rows):
    """A sentence naming what could close the miss, sized from the cells of its table."""
    table, scene = miss["table"], miss["scene"]
    if table == 5:
        fit = group_fits(rows, 5, scene, exclude_one_node=True)
        if miss["R"] == 1:
            return (f"the one-node time has no message at all, so only the work: a cost per "
                    f"test on {scene} {100 * (miss['paper'] / miss['interval']['median'] - 1):+.0f} % "
                    f"from what the fit on scene2 gives (scene0 is no calibration cell); the "
                    "model's two costs are the same for every scene")
        return (f"a cost per run (loading the scene onto the nodes through the host, collecting "
                f"the result), which Tables 1-4's seconds per iteration would not show: "
                f"{fit['d']:.0f} s a run sized on the {fit['cells']} parallel cells of Table 5 "
                f"({fit['d'] / 138:.1f} s over each of the paper's 138 iterations), leaving "
                f"{len(fit['d_outside'])} of them outside")
    if miss["V"] == 1 and miss["above"]:
        return (f"{miss['gap_median']:.1f} s an iteration that only the exchange with one "
                "visibility processor brings (the paper's V=1 is slower than its V=0; the "
                "model's messages cost under 0.1 s a run, docs/reproduce.md): a cost per block "
                "exchanged in the authors' program of thousands of times the modeled nCube2 "
                "message, or a wait the paper does not describe")
    text = (f"a cost the model lacks (above) or has too much of (below) on {scene}'s Table "
            f"{table} cells: the table below sizes the two simplest on them")
    doubling = per_doubling(rows, table, scene, miss["R"]) if miss["V"] == 0 else None
    if not miss["above"] and doubling and doubling[0] > 2.05:
        text = (f"the paper's time falls {doubling[0]:.1f}x from R={miss['R'] // 2} to "
                f"R={miss['R']} (the median world {doubling[1]:.1f}x): faster than the "
                "processors grow, which a fixed amount of work shared among more processors "
                "cannot do, nor any unknown of analysis/unknowns.json; a cost that shrinks "
                "faster than 1/R would (per-node work that gets cheaper as a node holds fewer "
                "elements)")
    return text


# ---------------------------------------------------------------------------------------------
# The page.

def pct(x, digits=1):
    return f"{100 * x:.{digits}f} %"


def secs(x):
    if x is None:
        return "—"
    if abs(x) >= 100:
        return f"{x:.0f}"
    if abs(x) >= 10:
        return f"{x:.1f}"
    return f"{x:.2f}"


def page(summary, figure_name, small_run_note=None):
    default, worlds = summary["worlds"][0], summary["worlds"][1:]
    n = len(worlds)
    rows = cell_table(summary, worlds)
    counts = finding_counts(worlds)
    inside = sum(r["inside"] for r in rows)
    lines = ["# The reproduction with intervals over what the paper does not tell", ""]
    if small_run_note:
        lines += [f"**{small_run_note}**", ""]
    lines += [
        "Written by `analysis/unknowns.py` from the study's results (how to run it: "
        "`docs/reproduce.md`). Every choice the paper leaves open is listed once in "
        "`analysis/unknowns.json` with its range and why; a *world* draws each drawn unknown "
        "from its range (`analysis/ncube/worlds.py`, study seed "
        f"{summary['study_seed']}): the four scenes regenerated with the paper's patch and "
        "element counts exactly and the drawn room, furniture, element split, panels and patch "
        "order, the drawn samples, block size and element record; then the two calibrated "
        "costs are refitted on the two calibration cells of `analysis/calibration.json` and "
        "the 40 cells run. The default world (every unknown at its default: the committed "
        "scenes and model) is shown beside the drawn worlds and is not one of them.", "",
        f"**{n} drawn worlds. The paper's value lies inside the simulation's 90 % interval "
        f"(5th to 95th percentile over the worlds) in {inside} of the {len(rows)} cells**; "
        f"{len(rows) - inside} lie outside (section 5).", ""]
    # 0. The unknowns.
    listed = input_file.read_json(ANALYSIS / "unknowns.json", "list of unknowns", STUDY_BYTES)
    lines += ["## The unknowns", "",
              "Drawn (`analysis/unknowns.json` gives each one's reason in full):", "",
              "| unknown | per scene | drawn from | default | basis |", "|---|---|---|---|---|"]
    for u in listed["drawn"]:
        span = (" or ".join(json.dumps(v) for v in u["values"]) if "values" in u else
                f"{u['distribution']} {u['range'][0]} to {u['range'][1]}")
        lines.append(f"| `{u['name']}` | {'yes' if u['per_scene'] else 'no'} | {span} | "
                     f"{json.dumps(u['default'])} | {u['basis']} |")
    lines += ["", "Held fixed: " + "; ".join(f"{u['name']} ({u['basis']})"
                                             for u in listed["fixed"]) + ".", ""]
    # 1. The cells.
    lines += [f"## 1. The {len(rows)} cells", "",
              f"Median and 90 % interval over the {n} worlds; *default* is the default world. "
              "A cell marked (fit) is a calibration cell: every world is fitted to it.", "",
              "| table | scene | R | V | paper | default | median | 90 % interval | paper inside |",
              "|--:|---|--:|--:|--:|--:|--:|---|---|"]
    for r in rows:
        span = r["interval"]
        cells_text = (f"{secs(span['median'])} | {secs(span['low'])} – {secs(span['high'])}"
                      if span else "— | —")
        note = " (fit)" if r["calibration"] else ""
        if r["missing"]:
            note += f" ({r['missing']} world(s) {', '.join(r['statuses'])})"
        lines.append(f"| {r['table']} | {r['scene']} | {r['R']} | {r['V']} | {secs(r['paper'])} "
                     f"| {secs(default['cells'].get(r['key']))} | {cells_text} | "
                     f"{'yes' if r['inside'] else '**no**'}{note} |")
    # 2. Findings.
    lines += ["", "## 2. The findings", "",
              "In how many worlds each finding holds, judged by the report's own definitions "
              "(`analysis/ncube/findings.py`).", "",
              "| finding | worlds where it holds | default world |", "|---|--:|---|"]
    for f in FINDINGS:
        lines.append(f"| {f} | {counts[f]} of {n} ({pct(counts[f] / n, 0)}) | "
                     f"{default['findings'][f]} |")
    # 3. Errors.
    lines += ["", "## 3. The error over worlds", "",
              "Median and 90th percentile of |simulated − paper| / paper over the 40 cells, "
              "one value a world; their distribution over the worlds.", "",
              "| | min | 5 % | median | 95 % | max | default world |", "|---|--:|--:|--:|--:|--:|--:|"]
    for which, label in (("median", "median |error|"), ("p90", "90th percentile")):
        d = error_distribution(worlds, which)
        lines.append(f"| {label} | " + " | ".join(pct(d[k]) for k in
                                                    ("min", "p5", "median", "p95", "max")) +
                     f" | {pct(default['stats'][which])} |")
    fits = [w["fit"]["how"].startswith("two") for w in worlds]
    names = ["flops_per_ray_patch_test", "flops_per_plane_crossing"]
    lines += ["", f"The fit: two parameters in {sum(fits)} worlds, one factor on both costs "
              f"in {n - sum(fits)} (no positive pair fits both cells; analysis/patch-order.md). "
              "Fitted costs over the worlds: " +
              "; ".join(f"`{name}` {min(w['fit']['values'][j] for w in worlds):.2f} to "
                        f"{max(w['fit']['values'][j] for w in worlds):.2f}"
                        for j, name in enumerate(names)) +
              ". On the default world the procedure gives " +
              ", ".join(f"{v:.6g}" for v in default["fit"]["values"]) +
              f" ({default['fit']['how']}, {default['fit']['rounds']} verification round(s); "
              "committed: " + ", ".join(f"{summary['committed'][name]:.6g}" for name in names
                                        if name in summary.get("committed", {}))
              + ")."]
    # 4. Sensitivity.
    table = sensitivity(summary, worlds)
    chance = chance_levels(worlds)
    lines += ["", "## 4. Which unknowns move which cells", "",
              "Share of each cell's spread over the worlds (variance of its log time) that "
              "each group of unknowns explains alone: the R² of a least-squares fit of the "
              "cell's log time on that group's drawn values (a choice one-hot, the block size "
              "on a log scale), one group at a time. The groups are drawn independently, so "
              "the shares need not add up to one (interactions, noise). With "
              f"{n} worlds a group of k values explains about k/{n - 1} by chance alone: "
              + ", ".join(f"{g} {pct(c, 0)}" for g, c in chance.items()) +
              "; shares near those are noise. *scene2 geometry* is the calibration scene's: "
              "it reaches other scenes' cells through the refitted costs.", "",
              "| cell | " + " | ".join(GROUP_NAMES) + " |",
              "|---|" + "--:|" * len(GROUP_NAMES)]
    for r in rows:
        shares = table.get(r["key"])
        if shares is None:
            continue
        best = max(shares.values())
        lines.append(f"| {r['key']} | " + " | ".join(
            (f"**{pct(shares[g], 0)}**" if shares[g] == best else pct(shares[g], 0))
            for g in GROUP_NAMES) + " |")
    # 5. Outside.
    misses = outside(rows)
    lines += ["", "## 5. What lies outside", "",
              "Each cell whose paper value falls outside its interval, with the direction and "
              "size of the miss (from the nearer end of the interval) and what could close it, "
              "sized from the cells of its own table. Nothing here is added to the model.", ""]
    if not misses:
        lines.append("Every paper value lies inside its interval.")
    for m in misses:
        direction = "above" if m["above"] else "below"
        lines.append(f"* **{m['key']}**: paper {secs(m['paper'])} s, {direction} the interval "
                     f"by {secs(abs(m['miss_seconds']))} s "
                     f"({pct(abs(m['miss_share']), 1 if abs(m['miss_share']) < 0.1 else 0)}; "
                     f"median world {secs(m['interval']['median'])} s). Could close it: "
                     f"{mechanism(m, rows)}.")
    groups = sorted({(m["table"], m["scene"]) for m in misses})
    if groups:
        lines += ["", "The two simplest mechanisms sized on all cells of a table and scene that "
                  "has a miss: one additive cost (per iteration; per run in Table 5, its "
                  "parallel cells) equal to the median of paper − median world, and one factor "
                  "on the time (a cost per unit of work other than the fit on scene2 gives) "
                  "equal to the median of paper / median world; for each, how many of those "
                  "cells stay outside their interval moved by it.", "",
                  "| table | scene | cells | misses | additive cost | still outside | factor | "
                  "still outside |", "|--:|---|--:|--:|--:|--:|--:|--:|"]
        for table_number, scene in groups:
            fit = group_fits(rows, table_number, scene, exclude_one_node=table_number == 5)
            count = sum((m["table"], m["scene"]) == (table_number, scene) for m in misses)
            unit = "s a run" if table_number == 5 else "s"
            lines.append(f"| {table_number} | {scene} | {fit['cells']} | {count} | "
                         f"{fit['d']:+.1f} {unit} | {len(fit['d_outside'])} | {fit['f']:.2f} | "
                         f"{len(fit['f_outside'])} |")
    # 6. Scale.
    if n >= 32:
        first = 16
    else:
        first = max(2, n // 2)
    scale = scale_comparison(summary, worlds, first)
    lines += ["", "## 6. How many worlds", "",
              f"With the first {scale['first']} worlds against all {scale['all']}: the "
              f"intervals' median width changes by a factor {scale['median_width_ratio']:.2f}; "
              f"the paper's value is inside in {scale['inside_small']} cells with "
              f"{scale['first']} worlds and {scale['inside_large']} with {scale['all']}" +
              (f" (changed: {', '.join(scale['changed'])})." if scale["changed"] else
               "; no cell changes its verdict.")]
    lines += ["", "## 7. The worlds", "",
              "| world | samples | block | element bytes | patch order | fit | median | 90th pct | "
              + " | ".join(FINDINGS) + " |", "|--:|--:|--:|--:|---|---|--:|--:|" + "---|" * 6]
    for w in [default] + worlds:
        v = w["values"]
        lines.append(f"| {w['index']}{' (default)' if w is default else ''} | {v['samples']} | "
                     f"{v['block_size']} | {v['element_bytes']} | {v['patch_order']} | "
                     + ", ".join(f"{x:.2f}" for x in w["fit"]["values"])
                     + (" (one factor)" if not w["fit"]["how"].startswith("two") else "")
                     + f" | {pct(w['stats']['median'])} | {pct(w['stats']['p90'])} | "
                     + " | ".join("yes" if w["findings"][f] == "reproduced" else "no"
                                  for f in FINDINGS) + " |")
    refused = sum(sum(w["refused_draws"].values()) for w in worlds)
    lines += ["", f"Draws of a scene's geometry refused by the generator's checks (overlap, "
              f"sliver, partition) and drawn again: {refused} over the {n} worlds; so the "
              "accepted draws are the ranges of `analysis/unknowns.json` cut to scenes the "
              "generator accepts.", "",
              f"![every cell's interval against the paper's value](figures/{figure_name})", ""]
    body = "\n".join(lines)
    return op.with_opening(body, opening(op.tables(body)), "analysis/unknowns.py")


def opening(found):
    """The page's opening, from its own tables: the cells inside their intervals, the error
    over the worlds, the findings that survive the unknowns and those that do not, where the
    misses lie."""
    cells = op.table(found, "1. The", "paper inside")
    inside = sum(r["paper inside"].startswith("yes") for r in cells)
    error = op.table(found, "3. The error over worlds")[0]
    findings = op.table(found, "2. The findings")
    n = int(findings[0]["worlds where it holds"].split(" of ")[1].split()[0])
    share = {r["finding"]: op.number(r["worlds where it holds"]) / n for r in findings}
    robust = [f for f, x in share.items() if x >= 0.9]
    fragile = [f for f, x in share.items() if x < 0.9]
    sentences = [
        op.Sentence(f"The paper's value lies inside the simulation's 90 % interval in {inside} of "
                    f"the {len(cells)} cells; {len(cells) - inside} lie outside",
                    f"each interval the 5th to 95th percentile over {n} drawn worlds; with 16 "
                    "worlds instead the verdicts compare in section 6"),
        op.Sentence(f"The median |error| over the {len(cells)} cells is {error['default world']} "
                    f"in the default world and {error['median']} in the median world",
                    f"between {error['5 %']} and {error['95 %']} over the worlds (5th to 95th "
                    f"percentile; {error['min']} to {error['max']} in all)"),
        op.Sentence("Reproduced in at least 90 % of the worlds: " +
                    (", ".join(f"{f} ({share[f] * n:.0f} of {n})" for f in robust) or "none") +
                    "; less often: " +
                    (", ".join(f"{f} ({share[f] * n:.0f} of {n})" for f in fragile) or "none"),
                    f"counts over {n} worlds, each judged by the report's definitions; the "
                    "default world's verdicts are in section 2")]
    try:
        groups = op.table(found, "5. What lies outside", "misses")
    except KeyError:
        return sentences
    worst = max(groups, key=lambda r: op.number(r["misses"]))
    sentences.append(op.Sentence(
        f"The misses lie in {len(groups)} table and scene group(s), most in Table "
        f"{worst['table']} {worst['scene']} ({worst['misses']} of its {worst['cells']} cells); "
        f"one factor of {worst['factor']} on that group's time would leave "
        f"{worst['still outside 2']} outside",
        "sized from the group's median world, nothing added to the model (section 5)"))
    return sentences


def figure(summary, path):
    from matplotlib import ticker
    from ncube.plotting import plt, save
    worlds = summary["worlds"][1:]
    rows = cell_table(summary, worlds)
    fig, ax = plt.subplots(figsize=(8, 11))
    for y, r in enumerate(rows):
        span = r["interval"]
        if span is None:
            continue
        ratio = lambda v: v / r["paper"]  # noqa: E731
        colour = "tab:blue" if r["inside"] else "tab:red"
        ax.plot([ratio(span["low"]), ratio(span["high"])], [y, y], color=colour, lw=4,
                solid_capstyle="butt")
        ax.plot(ratio(span["median"]), y, "k|", ms=10)
        default = summary["worlds"][0]["cells"].get(r["key"])
        if default is not None:
            ax.plot(ratio(default), y, "kx", ms=5)
    ax.axvline(1.0, color="k", lw=1)
    ax.set_xscale("log")
    ax.xaxis.set_major_locator(ticker.FixedLocator([0.25, 0.5, 0.8, 1, 1.25, 2, 4]))
    ax.xaxis.set_major_formatter(ticker.FormatStrFormatter("%g"))
    ax.xaxis.set_minor_formatter(ticker.NullFormatter())
    ax.set_yticks(range(len(rows)))
    ax.set_yticklabels([r["key"] + (" (fit)" if r["calibration"] else "") for r in rows],
                       fontsize=7)
    ax.invert_yaxis()
    ax.set_xlabel("simulated / paper (the paper's value at 1)")
    ax.set_title(f"90 % intervals over {len(worlds)} worlds (blue: paper inside, red: outside;"
                 "\n| median world, x default world)", fontsize=9)
    ax.grid(True, axis="x", which="both", alpha=0.3)
    save(fig, path)


SUMMARY_BYTES = 64 << 20   # a summary of thousands of worlds is a few MB


def check_summary(path, summary):
    """A saved summary's shape and numbers: every world's cells finite numbers above 0
    (simulated seconds, speedups and ratios: their logarithms are taken) or null (not run),
    else an InputFileError naming file, world and cell."""
    if not isinstance(summary, dict) or not isinstance(summary.get("worlds"), list) \
            or not isinstance(summary.get("cells"), list):
        raise input_file.InputFileError(f"{path}: summary: not an object with \"cells\" and "
                                        "\"worlds\" lists")
    for index, world in enumerate(summary["worlds"]):
        cells = world.get("cells") if isinstance(world, dict) else None
        if not isinstance(cells, dict) or not isinstance(world.get("status"), dict):
            raise input_file.InputFileError(f"{path}: world {index}: no \"cells\" and "
                                            "\"status\" objects")
        for key, value in cells.items():
            if value is None:
                continue
            if isinstance(value, bool) or not isinstance(value, (int, float)) or value != value \
                    or value in (float("inf"), float("-inf")) or value <= 0:
                raise input_file.InputFileError(
                    f"{path}: world {index}: cell {key}: {value!r} is not a finite number above 0")


STUDY_BYTES = 1 << 20   # a few lines: how many worlds, the seed


def read_study(path=STUDY):
    """The study file through the input gate (ncube.input_file): {"worlds": n >= 1, "seed":
    s >= 0}, whole numbers, else an InputFileError naming the file and the item."""
    study = input_file.read_json(path, "study file", STUDY_BYTES)
    if not isinstance(study, dict):
        raise input_file.InputFileError(f"{path}: study file: not an object with \"worlds\" "
                                        "and \"seed\"")
    for item, low in (("worlds", 1), ("seed", 0)):
        value = study.get(item)
        if isinstance(value, bool) or not isinstance(value, int) or not low <= value <= 100000:
            raise input_file.InputFileError(f"{path}: study file: {item}: {value!r} is not a "
                                            f"whole number from {low} to 100000")
    return study


@page_rule.refusing_outputs("unknowns.py")
def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    try:
        study_defaults = read_study()
    except input_file.InputFileError as e:
        print(f"unknowns: {e}; nothing written", file=sys.stderr)
        return 2
    parser.add_argument("--run", action="store_true", help="run the study first (resumable)")
    parser.add_argument("--worlds", type=int, default=study_defaults["worlds"])
    parser.add_argument("--seed", type=int, default=study_defaults["seed"])
    parser.add_argument("--results", type=Path, default=ROOT / "results" / "unknowns")
    parser.add_argument("--cores", type=int, default=2)
    parser.add_argument("--slurm", action="store_true", help="run the cells as Slurm jobs")
    parser.add_argument("--summary", type=Path, help="write the page from this saved summary")
    parser.add_argument("--out-dir", type=Path, default=None,
                        help="where unknowns.md, unknowns-worlds.json and figures/ go (default "
                             "analysis/, the committed page: only for a whole study; --summary "
                             "needs it named)")
    parser.add_argument("--label", default=None,
                        help="a line at the top of the page (default: none for the study, a "
                             "warning for fewer worlds than experiments/unknowns/study.json's)")
    args = parser.parse_args()
    started = time.time()
    study = args.results.resolve()
    if args.summary and args.out_dir is None:
        print("unknowns: --summary writes only where --out-dir says (the committed page in "
              "analysis/ is written by a whole study); nothing written", file=sys.stderr)
        return 2
    out = ANALYSIS if args.out_dir is None else args.out_dir
    if out.exists() and not out.is_dir():
        print(f"unknowns: --out-dir {out}: not a folder; nothing written", file=sys.stderr)
        return 5
    try:
        if args.summary:
            summary = input_file.read_json(args.summary, "summary", SUMMARY_BYTES)
            check_summary(args.summary, summary)
        else:
            if args.run:
                sweep_args = ["--slurm"] if args.slurm else ["--cores", str(args.cores)]
                from ncube.worlds import WorldError
                try:
                    run_study(args.worlds, args.seed, study, sweep_args)
                except WorldError as e:
                    print(f"unknowns: {e}", file=sys.stderr)
                    return 4
            summary = collect(args.worlds, args.seed, study)
    except Refusal as e:
        print(f"unknowns: {e}: run analysis/unknowns.py --run first; nothing written",
              file=sys.stderr)
        return 2
    except input_file.InputFileError as e:
        print(f"unknowns: {e}; nothing written", file=sys.stderr)
        return 2
    if len(summary["worlds"]) < 3:
        print("unknowns: fewer than 2 drawn worlds: no interval; nothing written",
              file=sys.stderr)
        return 2
    drawn_count = len(summary["worlds"]) - 1
    label = args.label
    if label is None and drawn_count < study_defaults["worlds"]:
        label = (f"A small run of {drawn_count} drawn worlds, not the study "
                 f"({study_defaults['worlds']} worlds, {STUDY.relative_to(ROOT)}): "
                 "its intervals are not the study's.")
    figure_name = "unknowns_intervals.png"
    if out.resolve() == ANALYSIS.resolve() and (args.summary or drawn_count < study_defaults["worlds"]):
        print(f"unknowns: {drawn_count} drawn worlds{' from a saved summary' if args.summary else ''}"
              f" would replace the committed page (analysis/unknowns.md, the study of "
              f"{study_defaults['worlds']} worlds): give --out-dir; nothing written", file=sys.stderr)
        return 2
    try:
        (out / "figures").mkdir(parents=True, exist_ok=True)
    except OSError as e:
        print(f"unknowns: --out-dir {out}: cannot make its figures/ folder: {e.strerror or e}; "
              "nothing written", file=sys.stderr)
        return 5
    try:
        text = page(summary, figure_name, label)
    except input_file.InputFileError as e:
        print(f"unknowns: {e}; nothing written", file=sys.stderr)
        return 2
    if not args.summary:
        page_rule.write(out / "unknowns-worlds.json",
                          json.dumps(summary, indent=1, sort_keys=True) + "\n")
    figure(summary, out / "figures" / figure_name)
    page_rule.write(out / "unknowns.md", text)
    print(f"unknowns: {len(summary['worlds']) - 1} worlds; written: {out / 'unknowns.md'}, "
          f"{out / 'figures' / figure_name}; {time.time() - started:.0f} s wall time")
    return 0


if __name__ == "__main__":
    sys.exit(main())
