#!/usr/bin/python3
"""What the hemicube costs the host in the prediction table's hemicube scenes and in the probe's
hemicube rooms, and whether projection_speed and raster_speed carry it: the section of
docs/machines/probe.md "What a hemicube costs", the hemicube's part of the study whose loop part
is docs/machines/loop_profile.py (its machinery shared from there).

    /usr/bin/python3 docs/machines/hemicube_profile.py [--processes P] [--rounds R] [--jobs J]
                                                       [--out FILE] [--from FILE] [--more]
                                                       [--real ROUNDS] [--page]

Runs (`build/machine_probe --hemicube-scenes`): the probe's six hemicube rooms, whose medians fit
projection_speed and raster_speed, and the table's three hemicube scenes as a one-node run draws
them (every element of every other patch, from four shooters; the Cornell box with a hemicube
at each of the shooter's elements, scene0 at 400 x 400 cells, scene1 at 100 x 100). For each:

* counted by valgrind's callgrind (--cache-sim=yes --branch-sim=yes, the loop study's caches;
  --toggle-collect on render_hemicube, so that only the kernel is counted): two processes of
  `build/machine_probe --hemicube-only RUN --passes 0` and `--passes 1`, whose difference is one
  pass: instructions (Ir), data references, first-level and last-level data misses,
  conditional branches and their mispredictions; with the pass's hemicube counters;
* timed natively: P processes of `build/machine_probe --hemicube-scenes R` (every run round by
  round in one process, thread CPU time, each run's median of its R rounds).

Then: a pass's instructions fitted on the counted kinds; each process's times fitted on the six
rooms alone (the model's two kinds; rows with a rate of their own; instructions at one rate;
instructions with the simulated last-level misses) and the scenes predicted from them; the
model's miss regressed on what the counts and the simulated caches give a run (rows a raster
flop, a polygon's size on a face, the share of clip tests that cut, last-level misses a cell).
With --real, the scenes' whole runs as docs/machines/prediction_table.py times them: three
under callgrind (render_hemicube's own inclusive counts against the process's, the difference
of two runs' iterations) and ROUNDS rounds natively, each against a --hemicube-scenes process
in the same round.

The measurements are kept in --out (JSON); --from makes the tables again from such a file
without running anything (--more, --real: adds to it); --page writes them into
docs/machines/probe.md between its hemicube-profile markers, and the finding's sentence between
its hemicube-opening markers.
"""

import json
import math
import os
import re
import subprocess
import sys
import tempfile
import time
from concurrent.futures import ThreadPoolExecutor

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import loop_profile as lp  # noqa: E402  (beside this script: its machinery and caches)
import prediction_records  # noqa: E402  (the records of docs/machines/probe.md's table)
import prediction_table  # noqa: E402  (the hemicube's rows and its counters by kind)

# numpy (0.1 s of CPU a start) is imported by the functions that use it: --help and refusals need none.
from ncube import input_file, output_file  # noqa: E402

PAGE = lp.PAGE
BEGIN, END = "<!-- hemicube-profile:begin -->", "<!-- hemicube-profile:end -->"
OPEN_BEGIN, OPEN_END = "<!-- hemicube-opening:begin -->", "<!-- hemicube-opening:end -->"
ROOMS = [f"room of {n} patches, {r} x {r} cells"
         for n, r in ((985, 8), (505, 20), (241, 100), (103, 100), (49, 400), (19, 200))]
SCENES = ["cornell-box, hemicube at elements", "scene0, hemicube at 400", "scene1, hemicube"]
RESOLUTION = {**{r: int(r.split(", ")[1].split(" x ")[0]) for r in ROOMS},
              SCENES[0]: 100, SCENES[1]: 400, SCENES[2]: 100}
PROJECTION, RASTER = prediction_table.PROJECTION, prediction_table.RASTER
COUNTERS = PROJECTION + RASTER
EVENTS = ["Ir", "Dr", "Dw", "D1mr", "D1mw", "DLmr", "DLmw", "Bc", "Bcm"]
KERNEL = "ncube::render_hemicube("
# A one-node run's hemicube shot (src/radiosity/form_factor_methods.cpp): its polygons' lists
# built, render_hemicube, reciprocity, the gather of its form factors.
SHOT = "shoot_hemicube("
# The whole runs: natively the prediction table's (scene, N, options); under callgrind fewer
# iterations, (scene, a, b, options), the difference of a and b iterations.
REAL = prediction_table.HEMICUBE_RUNS
REAL_COUNTED = [("cornell-box", 10, 12, REAL[0][2]), ("scene0", 30, 60, REAL[1][2]),
                ("scene1", 100, 200, REAL[2][2])]
REAL_NAME = dict(zip((s for s, _, _ in REAL), SCENES))


def callgrind(command, toggle=True):
    """One process under callgrind: its events (render_hemicube's alone with `toggle`), its
    standard output, and without `toggle` the kernel's inclusive events beside the process's."""
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "cg.out")
        done = subprocess.run(["nice", "-n", "10", "valgrind", "--tool=callgrind", "--cache-sim=yes",
                               "--branch-sim=yes", *lp.CACHES, f"--callgrind-out-file={out}",
                               *([f"--toggle-collect={KERNEL[:-1]}*"] if toggle else []), *command],
                              capture_output=True, text=True, check=True)
        text = input_file.read_input_text(out, "callgrind's output", 1 << 30)
        events = re.search(r"^events: (.*)$", text, re.M).group(1).split()
        totals = dict(zip(events, map(int, re.search(r"^totals: (.*)$", text, re.M).group(1).split())))
        kernel = None
        if not toggle:
            table = subprocess.run(["callgrind_annotate", "--inclusive=yes", "--threshold=100", out],
                                   capture_output=True, text=True, check=True).stdout
            kernel = {}
            for name in (KERNEL, SHOT):
                line = next(x for x in table.splitlines() if name in x)
                numbers = [int(t.replace(",", "")) for t in line.split() if re.fullmatch(r"[\d,]+", t)]
                kernel[name] = dict(zip(events, numbers))
    return totals, done.stdout, kernel


def kernel_counts(run):
    """One pass of `run`'s hemicubes: render_hemicube's events and the pass's counters."""
    (base, _, _), (one, stdout, _) = [callgrind([lp.PROBE, "--hemicube-only", run, "--passes", str(p)])
                                      for p in (0, 1)]
    line = next(x for x in stdout.splitlines() if x.startswith(run + " |"))
    work = {k: int(v) for k, v in re.findall(r"\| (\w+) (\d+)", line) if k in COUNTERS}
    return {"work": work, "pass": {e: one[e] - base[e] for e in EVENTS}}


def native(rounds):
    done = subprocess.run(["nice", "-n", "19", lp.PROBE, "--hemicube-scenes", str(rounds)],
                          capture_output=True, text=True, check=True)
    rows = {}
    for line in done.stdout.splitlines():
        name, rest = line.split(" | ", 1)
        values = dict(re.findall(r"(\w+) ([0-9.]+)", rest))
        rows[name] = {"passes": int(values["passes"]), "median_s": float(values["median_s"]),
                      "spread_percent": float(values["spread_percent"])}
    return rows


def stamp():
    """The time and the 1-minute load average, for the measurements' log."""
    load = input_file.read_input_text("/proc/loadavg", "the load average", 4096).split()[0]
    return time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime()) + f" (load average {load})"


def hemicube_options(extra):
    return ["--form-factors", "hemicube", *extra]


def real_counted(item):
    """A whole run's timed iterations under callgrind: the process's events and render_hemicube's
    inclusive ones, the difference of two runs."""
    scene, a, b, extra = item
    out = {}
    with tempfile.TemporaryDirectory() as work:
        for iterations in (a, b):
            result = os.path.join(work, f"{iterations}.json")
            totals, _, kernel = callgrind([lp.SIMULATE, os.path.join(lp.ROOT, "scenes", scene + ".json"),
                                           "--R", "1", "--V", "0", "--iterations", str(iterations),
                                           "--reference-visibility", "--threads", "1", "--platform",
                                           lp.PLATFORM, "--json", result, "--quiet",
                                           *hemicube_options(extra)], toggle=False)
            counts = input_file.read_json(result, "a result file", 1 << 26)["counts"]
            out[iterations] = {"counts": counts, "process": totals, "kernel": kernel}
    return {"iterations": [a, b],
            "work": {k: out[b]["counts"].get(k, 0) - out[a]["counts"].get(k, 0) for k in out[b]["counts"]},
            "process": {e: out[b]["process"][e] - out[a]["process"][e] for e in EVENTS},
            "kernel": {e: out[b]["kernel"][KERNEL][e] - out[a]["kernel"][KERNEL][e] for e in EVENTS},
            "shot": {e: out[b]["kernel"][SHOT][e] - out[a]["kernel"][SHOT][e] for e in EVENTS}}


def real_round():
    """One round: each hemicube row's runs of N and 2N iterations, then a --hemicube-scenes
    process of 3 rounds."""
    row = {"real": {}}
    with tempfile.TemporaryDirectory() as work:
        for scene, n, extra in REAL:
            row["real"][scene] = [lp.simulate_run(scene, m, work, extra=hemicube_options(extra),
                                                  counters=COUNTERS + ["hemicube_delta_form_factors"])
                                  for m in (n, 2 * n)]
    row["kernel"] = native(3)
    return row


def prediction_flops():
    return costs_and_rates()[0]


def costs_and_rates():
    costs = lp.cost_model()
    return ({c: costs[prediction_table.KIND_COUNTERS[c]] for c in COUNTERS},
            lp.platform_rates(lp.PLATFORM))


def kind_flops(work, flops):
    """(projection flops, raster flops, rows' flops, cells' flops) of a pass's counters."""
    projection = sum(flops[c] * work.get(c, 0) for c in PROJECTION)
    rows = flops["hemicube_rows_scanned"] * work.get("hemicube_rows_scanned", 0)
    cells = sum(flops[c] * work.get(c, 0) for c in RASTER) - rows
    return projection, rows + cells, rows, cells


def simulated_hemicube(work, flops, rates):
    p, r, _, _ = kind_flops(work, flops)
    return p / rates["projection_speed"] + r / rates["raster_speed"]


def features(data, runs, flops):
    """What each run's counts and simulated caches give, a pass."""
    out = {}
    for r in runs:
        w, p = data["callgrind"][r]["work"], data["callgrind"][r]["pass"]
        proj, ras, rows, cells = kind_flops(w, flops)
        n = RESOLUTION[r]
        hemicubes = w["hemicube_cells_read"] / (n * n + 4 * n * n / 2)
        out[r] = {"hemicubes": hemicubes, "polygons": w["hemicube_polygons_set_up"] / hemicubes,
                  "raster_share": ras / (proj + ras), "rows_share": rows / ras,
                  "cells_a_polygon": w["hemicube_depth_tests"] / max(w["hemicube_polygons_scanned"], 1),
                  "rows_a_polygon": w["hemicube_rows_scanned"] / max(w["hemicube_polygons_scanned"], 1),
                  "cut_share": w["hemicube_clip_cuts"] / w["hemicube_clip_tests"],
                  "flops": proj + ras, "Ir": p["Ir"] / (proj + ras),
                  "D1": (p["D1mr"] + p["D1mw"]) / w["hemicube_cells_read"],
                  "LL": (p["DLmr"] + p["DLmw"]) / w["hemicube_cells_read"],
                  "Bcm": p["Bcm"] / (proj + ras), "footprint_kib": 16 * n * n / 1024}
    return out


def seconds_a_pass(proc, r):
    return proc[r]["median_s"] / proc[r]["passes"]


# The fits of each process's times on the six rooms: name -> the columns of a run (its work by
# kind, each column charged at a rate of its own).
def fit_columns(data, flops):
    def cols(r):
        w, p = data["callgrind"][r]["work"], data["callgrind"][r]["pass"]
        proj, ras, rows, cells = kind_flops(w, flops)
        depth = flops["hemicube_depth_tests"] * w["hemicube_depth_tests"]
        return {"model": [proj, ras], "rows": [proj, rows, cells],
                "cells": [proj, rows, depth, cells - depth], "Ir": [p["Ir"]],
                "Ir+LL": [p["Ir"], p["DLmr"] + p["DLmw"]]}
    return cols


FITS = [("model", "the model's kinds (projection, raster)"),
        ("rows", "rows at a rate of their own (projection, rows, cells)"),
        ("cells", "rows, depth tests and cells read each at a rate of their own"),
        ("Ir", "instructions at one rate"),
        ("Ir+LL", "instructions and simulated last-level misses")]


def fit_on_rooms(proc, cols, name):
    """One process's times of the rooms fitted on the columns `name` (relative least squares):
    seconds a unit of each column."""
    import numpy as np
    a = np.array([np.array(cols(r)[name]) / seconds_a_pass(proc, r) for r in ROOMS])
    c, *_ = np.linalg.lstsq(a, np.ones(len(ROOMS)), rcond=None)
    return c


def rooms_to_scenes(data, runs, flops, rates):
    """Each process's times fitted on the rooms alone, each way of FITS, and what each predicts
    for every run (fitted over measured, minus 1); with the committed platform's rates'
    prediction of the same pass."""
    import numpy as np
    cols = fit_columns(data, flops)
    misses = {r: {name: [] for name, _ in FITS + [("committed", "")]} for r in runs}
    coefs = {name: [] for name, _ in FITS}
    for proc in data["native"]:
        for name, _ in FITS:
            c = fit_on_rooms(proc, cols, name)
            coefs[name].append(c)
            for r in runs:
                misses[r][name].append(float(np.array(cols(r)[name]) @ c / seconds_a_pass(proc, r) - 1))
        for r in runs:
            misses[r]["committed"].append(
                simulated_hemicube(data["callgrind"][r]["work"], flops, rates) / seconds_a_pass(proc, r) - 1)
    return misses, coefs


def ir_fit(data, runs, flops, name):
    """A pass's instructions fitted on the columns `name` over the rooms alone (relative least
    squares): the coefficients and every run's residual (fitted over counted, minus 1)."""
    import numpy as np
    cols = fit_columns(data, flops)
    ir = {r: data["callgrind"][r]["pass"]["Ir"] for r in runs}
    a = np.array([np.array(cols(r)[name]) / ir[r] for r in ROOMS])
    c, *_ = np.linalg.lstsq(a, np.ones(len(ROOMS)), rcond=None)
    return c, {r: float(np.array(cols(r)[name]) @ c / ir[r] - 1) for r in runs}


def real_native(data, flops, rates):
    """Each round: the rooms' fit of the model's kinds in that round's --hemicube-scenes process,
    what it predicts for the scene's kernel pass (over its time there, minus 1) and for the row's
    timed iterations (over their CPU seconds less what the committed platform simulates for
    their other work, minus 1); and the whole row at the committed rates."""
    import numpy as np
    cols = fit_columns(data, flops)
    out = {}
    for scene, _, _ in REAL:
        name = REAL_NAME[scene]
        x = {"run": [], "kernel": [], "ratio": [], "committed": [], "share": []}
        for row in data["real"]:
            a, b = row["real"][scene]
            d = {k: b["counts"][k] - a["counts"][k] for k in COUNTERS}
            cpu, simulated = b["cpu"] - a["cpu"], b["simulated"] - a["simulated"]
            hemicube = simulated_hemicube(d, flops, rates)
            host_hemicube = cpu - (simulated - hemicube)
            c = fit_on_rooms(row["kernel"], cols, "model")
            proj, ras, _, _ = kind_flops(d, flops)
            run = (c[0] * proj + c[1] * ras) / host_hemicube - 1
            kernel = np.array(cols(name)["model"]) @ c / seconds_a_pass(row["kernel"], name) - 1
            x["run"].append(run)
            x["kernel"].append(kernel)
            x["ratio"].append((1 + kernel) / (1 + run))
            x["committed"].append(simulated / cpu - 1)
            x["share"].append(hemicube / simulated)
        out[scene] = x
    return out


def probe_pairs(data, flops):
    """Each pair: what the probe's own hemicube rates predict for the scenes' kernels in the
    --hemicube-scenes process beside it, and what that process's own fit of its rooms predicts."""
    import numpy as np
    cols = fit_columns(data, flops)
    out = {r: {"probe": [], "process": []} for r in SCENES}
    rates = {"projection_speed": [], "raster_speed": [], "fit_projection": [], "fit_raster": []}
    for pair in data.get("probe_pairs", []):
        proc = pair["native"]
        c = fit_on_rooms(proc, cols, "model")
        for k in ("projection_speed", "raster_speed"):
            rates[k].append(pair["rates"][k])
        rates["fit_projection"].append(1 / c[0])
        rates["fit_raster"].append(1 / c[1])
        for r in SCENES:
            t = seconds_a_pass(proc, r)
            out[r]["probe"].append(simulated_hemicube(data["callgrind"][r]["work"], flops, pair["rates"]) / t - 1)
            out[r]["process"].append(float(np.array(cols(r)["model"]) @ c / t - 1))
    return out, rates


def records_snapshot():
    """The current records' hemicube rows (docs/machines/prediction_records.jsonl): each run's
    simulated and host seconds, kept in the measurements so that the page is made from them
    alone."""
    records = prediction_records.current(prediction_records.load(prediction_records.RECORDS))
    rows = {scene: [] for scene, _, _ in REAL}
    for record in records:
        for row in record["rows"]:
            if row["kind"] == "hemicube" and row["scene"] in rows:
                rows[row["scene"]].append({"host": row["host"], "simulated": row["simulated"]})
    return {"runs": len(records), "from": min(r["date"] for r in records),
            "to": max(r["date"] for r in records), "rows": rows}


def records_against_study(data, flops, rates):
    """Each row's records against this study: the records' host and simulated seconds, the
    whole rounds' host seconds (the same iterations: the same counts), and what the rooms' fit
    (each coefficient the median over the native processes) gives those counts."""
    import numpy as np
    cols = fit_columns(data, flops)
    c = np.median([fit_on_rooms(proc, cols, "model") for proc in data["native"]], axis=0)
    out = {}
    for scene, _, _ in REAL:
        a, b = data["real"][0]["real"][scene]
        d = {k: b["counts"][k] - a["counts"][k] for k in COUNTERS}
        proj, ras, _, _ = kind_flops(d, flops)
        other = (b["simulated"] - a["simulated"]) - simulated_hemicube(d, flops, rates)
        rec = data["records"]["rows"][scene]
        out[scene] = {"records_host": [r["host"] for r in rec],
                      "records_simulated": [r["simulated"] for r in rec],
                      "rounds_host": [row["real"][scene][1]["cpu"] - row["real"][scene][0]["cpu"]
                                      for row in data["real"]],
                      "fit": c[0] * proj + c[1] * ras + other}
    return out


def probe_pair():
    """A fresh probe (as the prediction table makes one), then a --hemicube-scenes process."""
    with tempfile.TemporaryDirectory() as tmp:
        platform = os.path.join(tmp, "probe.xml")
        done = subprocess.run(["nice", "-n", "19", lp.PROBE, "--out", platform], capture_output=True)
        if done.returncode == 4:  # a fit the host disturbed: refused, nothing written
            return None
        done.check_returncode()
        rates = lp.platform_rates(platform)
    return {"rates": {k: rates[k] for k in ("projection_speed", "raster_speed")}, "native": native(21)}


def pct(x, digits=1):
    return f"{100 * x:+.{digits}f} %"


def median_range(values, digits=1):
    import numpy as np
    v = 100 * np.array(values)
    return f"{np.median(v):+.{digits}f} % ({v.min():+.{digits}f} to {v.max():+.{digits}f})"


def tables(data):
    """The section's text: what was found, in figures, then the tables."""
    import numpy as np
    flops, rates = costs_and_rates()
    runs = [r for r in ROOMS + SCENES if r in data["callgrind"]]
    f = features(data, runs, flops)
    misses, coefs = rooms_to_scenes(data, runs, flops, rates)
    c_model, ir_model = ir_fit(data, runs, flops, "model")
    c_rows, ir_rows = ir_fit(data, runs, flops, "rows")
    procs = len(data["native"])
    text = []
    # The table of runs.
    rows = []
    for r in runs:
        x = f[r]
        ns = [1e9 * seconds_a_pass(p, r) / x["flops"] for p in data["native"]]
        rows.append(f"| {r} | {x['polygons']:.0f} | {100 * x['raster_share']:.0f} % | "
                    f"{100 * x['rows_share']:.1f} % | {x['cells_a_polygon']:.0f} | "
                    f"{x['rows_a_polygon']:.1f} | {x['cut_share']:.3f} | {x['footprint_kib']:.0f} | "
                    f"{x['Ir']:.2f} | {x['D1']:.3f} | {x['LL']:.3f} | {x['Bcm']:.3f} | "
                    f"{np.median(ns):.3f} ({min(ns):.3f}–{max(ns):.3f}) |")
    text += ["| run | polygons a hemicube | raster share of the counted flops | rows' share of the "
             "raster flops | cells a polygon scanned | rows a polygon scanned | clip cuts a clip "
             "test | top face's buffers, KiB | Ir a counted flop | D1 misses a cell | LL misses a "
             "cell | mispredicts a counted flop | host ns a counted flop, median (least–largest) |",
             "|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|", *rows, ""]
    text += [f"A pass's instructions (render_hemicube's, callgrind) fitted on the six rooms alone "
             f"(relative least squares), what each fit gives every run (fitted over counted, minus "
             f"1): the model's two kinds, {c_model[0]:.2f} instructions a projection flop and "
             f"{c_model[1]:.2f} a raster flop; rows apart, {c_rows[0]:.2f}, {c_rows[1]:.2f} a "
             f"row's flop and {c_rows[2]:.2f} a cell's.", "",
             "| run | the model's kinds | rows at a rate of their own |", "|---|--:|--:|"]
    text += [f"| {r} | {pct(ir_model[r])} | {pct(ir_rows[r])} |" for r in runs]
    text += ["", f"Fitted on the six rooms alone, in each of the {procs} processes, what each fit "
             "predicts (fitted over measured, minus 1; median over the processes, least to "
             "largest; the rooms' own rows are residuals), and the committed "
             "`cluster-2024.xml`'s rates on the same passes. Medians of the fits: the model's "
             f"{1 / np.median([c[0] for c in coefs['model']]):.3g} and "
             f"{1 / np.median([c[1] for c in coefs['model']]):.3g} flop/s (projection, raster); "
             f"rows apart {1 / np.median([c[1] for c in coefs['rows']]):.3g} flop/s a row's flop, "
             f"{1 / np.median([c[2] for c in coefs['rows']]):.3g} a cell's.", "",
             "| run | " + " | ".join(label for _, label in FITS) + " | the committed rates |",
             "|---|" + "--:|" * (len(FITS) + 1)]
    for r in runs:
        text.append(f"| {r} | " + " | ".join(median_range(misses[r][n]) for n, _ in FITS) +
                    f" | {median_range(misses[r]['committed'])} |")
    # What the model leaves, against what the counts and the simulated caches give a run.
    left = np.array([100 * np.median(misses[r]["model"]) for r in runs])
    text += ["", "| the model's miss (median a run, above) regressed on | slope | R² |", "|---|--:|--:|"]
    for key, label in REGRESSORS:
        coef, r2, _ = lp.fit([regressor(f, runs, key, label)], left)
        text.append(f"| {label} | {coef[1]:+.3g} % a unit | {r2:.2f} |")
    real = None
    if data.get("real_callgrind"):
        text += ["", "Whole runs under callgrind (the difference of two runs' iterations): "
                 "render_hemicube's own inclusive counts against the process's, and its "
                 "instructions against the rooms' fit of the model's kinds above:", "",
                 "| scene, iterations | render_hemicube's share of the process's Ir | its Ir fitted "
                 "from the counts over counted | Ir a counted flop | LL misses a cell | "
                 "mispredicts a counted flop | the process's Ir beyond the kernel, a hemicube polygon set up |",
                 "|---|--:|--:|--:|--:|--:|--:|"]
        for scene, r in data["real_callgrind"].items():
            w, k, p = r["work"], r["kernel"], r["process"]
            proj, ras, _, _ = kind_flops(w, flops)
            a, b = r["iterations"]
            text.append(f"| {scene}, iterations {a + 1} to {b} | {100 * k['Ir'] / p['Ir']:.1f} % | "
                        f"{pct((c_model[0] * proj + c_model[1] * ras) / k['Ir'] - 1)} | "
                        f"{k['Ir'] / (proj + ras):.2f} | "
                        f"{(k['DLmr'] + k['DLmw']) / w['hemicube_cells_read']:.3f} | "
                        f"{k['Bcm'] / (proj + ras):.3f} | "
                        f"{(p['Ir'] - k['Ir']) / w['hemicube_polygons_set_up']:.0f} |")
    if data.get("real"):
        real = real_native(data, flops, rates)
        text += ["", f"Whole runs natively, {len(data['real'])} rounds (each: the rows' runs of N "
                 "and 2N iterations, one process each, and a --hemicube-scenes process of 3 rounds "
                 "beside them): the rooms' fit of the model's kinds in that round's process, what it "
                 "predicts for the scene's kernel pass there and for the row's timed iterations "
                 "(their CPU seconds less what the committed platform simulates for their other "
                 "work), and the kernel's over the run's (1: the run's hemicubes cost what the "
                 "kernel's do, a counted flop for a counted flop); last, the whole row's simulated "
                 "seconds on the committed `cluster-2024.xml` over its CPU seconds, as the "
                 "prediction table measures it:", "",
                 "| scene | hemicube share of the simulated seconds | the rooms' fit over the kernel "
                 "− 1 | the rooms' fit over the run − 1 | run over kernel, a counted flop | "
                 "simulated over host − 1 at the committed rates |",
                 "|---|--:|--:|--:|--:|--:|"]
        for scene, _, extra in REAL:
            x = real[scene]
            ratio = x["ratio"]
            text.append(f"| {scene} ({' '.join(extra) or 'default'}) | {100 * np.median(x['share']):.0f} % | "
                        f"{median_range(x['kernel'])} | {median_range(x['run'])} | "
                        f"{np.median(ratio):.2f} ({min(ratio):.2f} to {max(ratio):.2f}) | "
                        f"{median_range(x['committed'])} |")
    pairs = None
    if data.get("probe_pairs"):
        pairs, probe_rates = probe_pairs(data, flops)
        n = len(data["probe_pairs"])
        text += ["", f"The probe's own rates against the same rooms timed alone: {n} pairs, each a "
                 "fresh `build/machine_probe --out` (the default 7 repeats, as the prediction table "
                 "makes one) and then a `--hemicube-scenes 21` process. The probe gave "
                 f"`projection_speed` {np.median(probe_rates['projection_speed']):.3g} and "
                 f"`raster_speed` {np.median(probe_rates['raster_speed']):.3g} flop/s (medians), the "
                 "processes' fits of the same rooms "
                 f"{np.median(probe_rates['fit_projection']):.3g} and "
                 f"{np.median(probe_rates['fit_raster']):.3g}; what each predicts for the scenes' "
                 "kernels in the process (fitted over measured, minus 1, median over the pairs, "
                 "least to largest):", "",
                 "| scene | the probe's rates | the process's own fit of the rooms |", "|---|--:|--:|"]
        for r in SCENES:
            text.append(f"| {r} | {median_range(pairs[r]['probe'])} | {median_range(pairs[r]['process'])} |")
    against = None
    if data.get("records") and data.get("real"):
        against = records_against_study(data, flops, rates)
        rec = data["records"]
        text += ["", f"The records against this study: the {rec['runs']} current records of the "
                 f"prediction table ({rec['from']} to {rec['to']}), whose hemicube rows time the "
                 "same iterations as the whole rounds above (the same counts: each record's "
                 "simulated seconds are its probe's rates on them), their host seconds beside the "
                 "rounds', and what the rooms' fit in this study's processes (each coefficient "
                 "the median over the processes) gives those counts:", "",
                 "| row | the records' host s, median (least to largest) | the rounds' host s | "
                 "the rooms' fit, s | the records' simulated s, median | records' median miss | "
                 "their medians' ratio − 1 | of it: the probes' rates over the rooms' fit | the "
                 "rooms' fit over the records' host (medians) | the rounds' host over the records' "
                 "(medians) |",
                 "|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|"]
        for scene, _, extra in REAL:
            x = against[scene]
            rh, ph, sim = np.median(x["records_host"]), np.median(x["rounds_host"]), np.median(x["records_simulated"])
            text.append(f"| {scene} ({' '.join(extra) or 'default'}) | {rh:.3f} ({min(x['records_host']):.3f} to "
                        f"{max(x['records_host']):.3f}) | {ph:.3f} ({min(x['rounds_host']):.3f} to "
                        f"{max(x['rounds_host']):.3f}) | {x['fit']:.3f} | {sim:.3f} | "
                        f"{pct(np.median([s_ / h - 1 for s_, h in zip(x['records_simulated'], x['records_host'])]))} | "
                        f"{pct(sim / rh - 1)} | {pct(sim / x['fit'] - 1)} | {pct(x['fit'] / rh - 1)} | {pct(ph / rh - 1)} |")
    found, sentence = opening(data, misses, ir_model, ir_rows, f, real, pairs, against, procs)
    return found, sentence, "\n".join(text) + "\n"


REGRESSORS = [("rows_share", "rows' share of the raster flops"),
              ("cells_a_polygon", "cells a polygon scanned (log10)"),
              ("cut_share", "clip cuts a clip test"),
              ("polygons", "polygons a hemicube (log10)"),
              ("LL", "simulated LL misses a cell"), ("Ir", "Ir a counted flop"),
              ("Bcm", "simulated mispredicts a counted flop")]


def regressor(f, runs, key, label):
    import numpy as np
    return np.array([np.log10(f[r][key]) if "log10" in label else f[r][key] for r in runs])


def sign_test(k, n):
    """Two-sided sign test: the chance of k or more (or n - k or fewer) of n falling one way."""
    tail = sum(math.comb(n, j) for j in range(max(k, n - k), n + 1)) / 2 ** n
    return min(1.0, 2 * tail)


def name_of(run):
    return {"cornell-box, hemicube at elements": "the Cornell box",
            "scene0, hemicube at 400": "scene0", "scene1, hemicube": "scene1"}.get(run, run)


def opening(data, misses, ir_model, ir_rows, f, real, pairs, against, procs):
    """The finding, in figures: the section's first paragraph and the page opening's sentence."""
    import numpy as np
    med = {r: {n: float(np.median(v)) for n, v in misses[r].items()} for r in misses}
    room_model = [med[r]["model"] for r in ROOMS]
    scene = ", ".join(f"{name_of(s)} {median_range(misses[s]['model'])}" for s in SCENES)
    moved = {n: max(abs(med[s][n] - med[s]["model"]) for s in SCENES) for n in ("rows", "cells")}
    worst = {n: max(abs(med[s][n]) for s in SCENES) for n, _ in FITS}
    runs = list(f)
    r2 = max(lp.fit([regressor(f, runs, k, label)], np.array([100 * med[r]["model"] for r in runs]))[1]
             for k, label in REGRESSORS)
    room400, scene400 = "room of 49 patches, 400 x 400 cells", "scene0, hemicube at 400"
    lines = ["**Found.** The two counted kinds carry the hemicube's work: no rate or counted kind "
             "is justified by these measurements, and the rows' far misses in the records are "
             "not a cost of the scenes this study can find. In figures (the tables below):", "",
             f"* **Instructions are counted work, to a few per cent.** callgrind's count of "
             f"`render_hemicube`'s instructions a pass, fitted on the six rooms alone on the two "
             f"kinds, gives the scenes' within {pct(min(ir_model[s] for s in SCENES))} to "
             f"{pct(max(ir_model[s] for s in SCENES))} (" +
             ", ".join(f"{name_of(s)} {pct(ir_model[s])}" for s in SCENES) +
             f"; the rooms' own {pct(min(ir_model[r] for r in ROOMS))} to "
             f"{pct(max(ir_model[r] for r in ROOMS))}): the scenes' many small polygons "
             f"({f[SCENES[0]]['polygons']:.0f} and {f[SCENES[2]]['polygons']:.0f} a hemicube on the "
             f"Cornell box and scene1, {f[SCENES[2]]['rows_a_polygon']:.1f} to "
             f"{f[SCENES[0]]['rows_a_polygon']:.1f} rows a polygon) run a few more instructions a "
             f"counted flop than the rooms' mix gives; with rows at a rate of their own "
             + ", ".join(f"{name_of(s)} {pct(ir_rows[s])}" for s in SCENES) + ".",
             f"* **In one process the rooms predict the scenes' kernels.** Fitted on the six rooms "
             f"alone in each of {procs} processes that time every run round by round, the model's "
             f"two kinds predict {scene} (medians over the processes, least to largest; the rooms' "
             f"own residuals {100 * min(room_model):+.1f} to {100 * max(room_model):+.1f} %). Rows "
             f"at a rate of their own move the scenes' medians by at most "
             f"{100 * moved['rows']:.1f} points, rows, depth tests and cells read each at their "
             f"own by at most {100 * moved['cells']:.1f}; instructions at one rate miss by up to "
             f"{100 * worst['Ir']:.1f} %, with the simulated last-level misses by up to "
             f"{100 * worst['Ir+LL']:.1f} %.",
             f"* **No candidate carries what is left.** The model's median miss a run regressed "
             f"on rows' share of the raster flops, a polygon's size on the face, the share of clip "
             f"tests that cut, polygons a hemicube, simulated last-level misses, instructions or "
             f"mispredictions a counted flop: R² ≤ {r2:.2f}. The buffers at 400 × 400 (2,500 KiB "
             f"a top face) are in the rate already: the room of 49 patches at 400 × 400 and "
             f"scene0 at 400 × 400 have the same buffers and {f[room400]['LL']:.2f} and "
             f"{f[scene400]['LL']:.2f} simulated last-level misses a cell, and the room's "
             f"residual is {pct(med[room400]['model'])} where scene0's miss is "
             f"{pct(med[scene400]['model'])}. scene1's {f[SCENES[2]]['polygons']:.0f} polygons "
             f"overflow the simulated last level ({f[SCENES[2]]['LL']:.1f} misses a cell against "
             f"{max(f[r]['LL'] for r in f if r != SCENES[2] and r != ROOMS[0]):.2f} at most in the "
             f"other runs but the 8 × 8 room) at no visible cost ({pct(med[SCENES[2]]['model'])})."]
    if real and data.get("real_callgrind"):
        rc = data["real_callgrind"]
        shares = {s: rc[s]["kernel"]["Ir"] / rc[s]["process"]["Ir"] for s in rc}
        beyond = {s: (rc[s]["shot"]["Ir"] - rc[s]["kernel"]["Ir"]) / rc[s]["work"]["hemicube_polygons_set_up"]
                  for s in rc}
        flops = prediction_flops()
        c_model, _ = ir_fit(data, list(f), flops, "model")
        whole_ir = {s: (c_model[0] * kind_flops(rc[s]["work"], flops)[0] +
                        c_model[1] * kind_flops(rc[s]["work"], flops)[1]) / rc[s]["kernel"]["Ir"] - 1
                    for s in rc}
        lines.append(
            f"* **Whole runs cost what their kernels do.** In the timed iterations "
            f"`render_hemicube` is {100 * min(shares.values()):.1f} to "
            f"{100 * max(shares.values()):.1f} % of the process's instructions (callgrind), the "
            f"rest of scene1's mostly the polygon lists each shot builds, charged nothing (a "
            f"shot's instructions beyond the kernel, its gather's included: "
            f"{beyond['scene1']:.0f} a polygon drawn); natively, "
            f"in {len(data['real'])} rounds, a counted flop of a whole run costs the kernel's "
            + ", ".join(f"{np.median(real[sc]['ratio']):.2f} times ({min(real[sc]['ratio']):.2f} to "
                        f"{max(real[sc]['ratio']):.2f}) on {name_of(REAL_NAME[sc])}" for sc, _, _ in REAL) +
            f" (medians, least to largest); and the rooms' fit of a pass's instructions misses "
            f"the whole runs' `render_hemicube` as it misses their kernels' ("
            + ", ".join(f"{pct(whole_ir[sc])} against {pct(ir_model[REAL_NAME[sc]])}"
                        for sc, _, _ in REAL if sc in whole_ir) + ").")
    if against and pairs:
        part = {sc: (np.median(against[sc]["records_simulated"]) / against[sc]["fit"] - 1,
                     against[sc]["fit"] / np.median(against[sc]["records_host"]) - 1,
                     np.median(against[sc]["rounds_host"]) / np.median(against[sc]["records_host"]) - 1)
                for sc, _, _ in REAL}
        shift = {s: np.median(pairs[s]["probe"]) - np.median(pairs[s]["process"]) for s in SCENES}
        cols = fit_columns(data, prediction_flops())
        fits = np.array([fit_on_rooms(p["native"], cols, "model") for p in data["probe_pairs"]])
        lower = [sum(p["rates"][k] < 1 / c[i] for p, c in zip(data["probe_pairs"], fits))
                 for i, k in enumerate(("projection_speed", "raster_speed"))]
        resolved = max(sign_test(k, len(fits)) for k in lower) < 0.05
        lines.append(
            f"* **The records split in two.** Each hemicube row of the {data['records']['runs']} "
            f"records, its median simulated seconds over its median host seconds, is the records' "
            f"probes' rates over this study's fit of the same rooms ("
            + ", ".join(f"{pct(part[sc][0])}" for sc, _, _ in REAL) +
            " for the Cornell box, scene0 and scene1) times that fit over the records' host "
            "seconds (" + ", ".join(f"{pct(part[sc][1])}" for sc, _, _ in REAL) + "). "
            + ("Of the first part the probe's own is a few points" if resolved else
               "The first part is not shown to be the probe's own") +
            f": in {len(data['probe_pairs'])} pairs of a fresh probe "
            f"and a process timed just after it, the probe's rates predict the scenes' kernels "
            f"{100 * min(shift.values()):+.1f} to {100 * max(shift.values()):+.1f} points from "
            f"the process's own fit (medians; the probe's `projection_speed` below the process's "
            f"in {lower[0]} of the pairs, its `raster_speed` in {lower[1]}). Rates and host "
            "seconds of the same minutes agree closer: in this study's rounds the rooms' fit of "
            "the round's own process predicts the whole rows at "
            + ", ".join(f"{pct(np.median(real[sc]['run']))}" for sc, _, _ in REAL) +
            f" (medians of {len(data['real'])} rounds, each one process of N and one of 2N "
            "iterations; the records take the least of 2 or 3 processes, and at other hours: the "
            "rounds' host seconds are "
            + ", ".join(f"{pct(part[sc][2])}" for sc, _, _ in REAL) + " over the records' "
            "medians).")
    if real and against and pairs:
        rc = data["real_callgrind"]
        share = {s: 1 - rc[s]["kernel"]["Ir"] / rc[s]["process"]["Ir"] for s in rc}
        extra = {s: (rc[s]["shot"]["Ir"] - rc[s]["kernel"]["Ir"]) / rc[s]["kernel"]["Ir"] for s in rc}
        rates = {k: np.median([p["rates"][k] for p in data["probe_pairs"]]) for k in ("projection_speed", "raster_speed")}
        cols = fit_columns(data, prediction_flops())
        fits = np.array([fit_on_rooms(p["native"], cols, "model") for p in data["probe_pairs"]])
        lines += ["", "**Where the model cannot see, and its bound.** Four parts. (1) A scene's kernel "
                  "costs a counted flop more or less than the rooms' mix: "
                  f"{100 * min(med[s]['model'] for s in SCENES):+.1f} to "
                  f"{100 * max(med[s]['model'] for s in SCENES):+.1f} % (medians in one process, "
                  "above), which no count here follows. (2) The polygon lists a shot builds "
                  "(`hemicube_shot_form_factors`: each element's polygon and plane, every shot) are "
                  "host work no counter charges: by instructions " +
                  ", ".join(f"{100 * share[sc]:.1f} %" for sc, _, _ in REAL) +
                  " of the timed iterations' (the Cornell box, scene0, scene1; with the gather "
                  "and the rest of the process), and natively within the whole runs' ratios to "
                  "their kernels above, whose rounds spread from "
                  f"{min(min(real[sc]['ratio']) for sc, _, _ in REAL):.2f} to "
                  f"{max(max(real[sc]['ratio']) for sc, _, _ in REAL):.2f}. (3) The probe against "
                  "the same rooms timed alone just after it: `projection_speed` "
                  f"{rates['projection_speed']:.3g} against {np.median(1 / fits[:, 0]):.3g}, "
                  f"`raster_speed` {rates['raster_speed']:.3g} against "
                  f"{np.median(1 / fits[:, 1]):.3g} (medians of the pairs; the probe's hemicube "
                  "runs are 0.012 s a repeat, each after every room's loop and gather), lower in "
                  f"{lower[0]} and {lower[1]} of the {len(fits)} pairs: "
                  + ("a few per cent, which overpredicts every hemicube row by as much. "
                     if resolved else "a few per cent that the pairs, falling either way, do not "
                     "resolve (a sign test's p above 0.05). ") + "(4) The host's "
                  "draw: the records' host seconds for the same counted "
                  "work spread from " +
                  ", ".join(f"{min(against[sc]['records_host']):.3f} to {max(against[sc]['records_host']):.3f} s"
                            for sc, _, _ in REAL) +
                  " (the Cornell box, scene0, scene1), two processes' difference on a guest whose "
                  "host drifts (\"A quiet guest is not a quiet machine\", above).",
                  "", "**What a rate or counted kind would change.** Rows at a rate of their own "
                  f"(a `row_speed`) would move the scenes by at most {100 * moved['rows']:.1f} "
                  "points and is not supported by the data. A counted kind for the polygon lists "
                  "a shot builds (a polygon drawn, charged at a rate the probe would fit from "
                  "rooms of elements) would charge what is free now: by instructions up to " +
                  ", ".join(f"{100 * extra[sc]:.1f} %" for sc, _, _ in REAL) +
                  " more of the hemicube's seconds (the Cornell box, scene0, scene1), raising "
                  "rows the model already overpredicts, where the whole runs show no cost beyond "
                  "their kernels' that their rounds can resolve; it is not added. Nothing here "
                  "changes a simulated second."]
    sentence = ("**What a hemicube costs** (below, \"What a hemicube costs: the counted kinds, the "
                "rooms and the scenes\"). Inside one process the probe's hemicube rooms predict the "
                "scenes' hemicube kernels at " +
                ", ".join(f"{name_of(s)} {100 * med[s]['model']:+.1f} %" for s in SCENES) +
                f" (medians of {procs} processes), and a pass's instructions fit the two counted "
                f"kinds to {pct(min(ir_model[s] for s in SCENES))} to "
                f"{pct(max(ir_model[s] for s in SCENES))}; no candidate (rows at a rate of their "
                "own, the buffers' footprint at 400 × 400, a polygon's size, the clip share) "
                "carries what is left, and no rate or counted kind is added.")
    return "\n".join(lines), sentence


METHOD = """The runs: the probe's six hemicube rooms (whole patches drawn, no occluders, from 4
eyes: the light and three patches spread through the room) and the table's three hemicube
scenes drawn as a one-node run draws them (every element of every other patch: 1,078 polygons
on the Cornell box, 1,162 on scene0, 4,648 on scene1), from each scene's four shooters as
`--scenes` takes them (the brightest patch and three spread through its list; the Cornell
box's hemicubes at the shooters' elements, every k-th of them kept, 24 a pass). Counted by
valgrind's callgrind with `--toggle-collect` on `render_hemicube` (the loop study's simulated
caches: first level 32 KiB, 8-way, last level 512 KiB, 8-way, assumed for AMD's Zen; no
prefetcher; valgrind's own branch predictor), one pass as the difference of `--passes 1` and
`--passes 0`; timed natively by `build/machine_probe --hemicube-scenes ROUNDS` (each run's
median of its rounds, thread CPU time). A counted flop is the cost model's
(`platforms/cost_model.json`): projection flops at `projection_speed`, raster flops (rows,
depth tests, cells read) at `raster_speed`.

```sh
cmake --build build --target machine_probe simulate
/usr/bin/python3 docs/machines/hemicube_profile.py --processes 15 --rounds 21 --out /tmp/h.json  # about 8 min
/usr/bin/python3 docs/machines/hemicube_profile.py --from /tmp/h.json --real 16 --jobs 2 --out /tmp/h2.json  # about 10 min
/usr/bin/python3 docs/machines/hemicube_profile.py --from /tmp/h2.json --probe 14 --records --out /tmp/h3.json  # about 4 min
/usr/bin/python3 docs/machines/hemicube_profile.py --from docs/machines/hemicube_profile.json --page  # these tables again
```"""


def measured_when(data):
    log = data.get("log", [])
    return ("Measured " + "; ".join(log) + "." if log else "")


def replace_between(page, begin, end, text, name):
    if begin not in page or end not in page or not text.strip():
        raise SystemExit(f"hemicube_profile.py: {PAGE} has no {begin} ... {end}, or no {name}")
    b, e = page.index(begin) + len(begin), page.index(end)
    return page[:b] + "\n" + text.rstrip("\n") + "\n" + page[e:]


def measure_counts(data, jobs):
    missing = [r for r in ROOMS + SCENES if r not in data["callgrind"]]
    if not missing:
        return
    start = stamp()
    with ThreadPoolExecutor(jobs) as pool:
        for run, counted in zip(missing, pool.map(kernel_counts, missing)):
            data["callgrind"][run] = counted
    data.setdefault("log", []).append(f"callgrind of {len(missing)} kernel runs {start} to {stamp()}")


def main():
    parser = lp.study_parser(__doc__.split("\n")[0], 21, "callgrind", "hemicube-profile",
                             "hemicube rows'")
    parser.add_argument("--probe", type=int, default=0, metavar="PAIRS",
                        help="with --from: this many pairs more of a fresh probe and a "
                             "--hemicube-scenes process, added to its measurements")
    parser.add_argument("--records", action="store_true",
                        help="with --from: keep the current records' hemicube rows "
                             "(docs/machines/prediction_records.jsonl) in the measurements")
    args = parser.parse_args()
    if min(args.processes, args.real, args.probe) < 0 or args.rounds < 1 or args.jobs < 1:
        raise SystemExit("hemicube_profile.py: --processes, --real, --probe from 0, --rounds and --jobs "
                         "from 1; nothing written")
    needs = [] if args.source and not (args.more or args.real or args.probe) else [lp.PROBE]
    lp.check_built(needs + ([lp.SIMULATE] if args.real else []), "hemicube_profile.py")
    if args.source:
        data = lp.read_measurements(args.source, "hemicube_profile.py", ["native", "callgrind"])
    else:
        data = {"caches": lp.CACHES, "native": [], "callgrind": {}}
    if not args.source or args.more:
        measure_counts(data, args.jobs)
        if args.processes:
            start = stamp()
            data["native"] += [native(args.rounds) for _ in range(args.processes)]
            data.setdefault("log", []).append(f"{args.processes} processes of `--hemicube-scenes "
                                              f"{args.rounds}` {start} to {stamp()}")
    if args.real:
        start = stamp()
        if "real_callgrind" not in data:
            data.setdefault("log", []).append(f"callgrind of 3 whole runs from {stamp()}")
            with ThreadPoolExecutor(args.jobs) as pool:
                data["real_callgrind"] = {item[0]: r for item, r in
                                          zip(REAL_COUNTED, pool.map(real_counted, REAL_COUNTED))}
        data["real"] = data.get("real", []) + [real_round() for _ in range(args.real)]
        data.setdefault("log", []).append(f"{args.real} rounds of whole runs {start} to {stamp()}")
    if args.probe:
        start = stamp()
        pairs = [probe_pair() for _ in range(args.probe)]
        data["probe_pairs"] = data.get("probe_pairs", []) + [p for p in pairs if p]
        refused = sum(p is None for p in pairs)
        data.setdefault("log", []).append(
            f"{args.probe} pairs of a probe and `--hemicube-scenes 21` {start} to {stamp()}" +
            (f" ({refused} probe{'s' if refused > 1 else ''} refused, exit 4, left out)" if refused else ""))
    if args.records:
        data["records"] = records_snapshot()
    if args.out and (not args.source or args.more or args.real or args.probe or args.records):
        output_file.write(args.out, json.dumps(data, indent=1) + "\n")
    if not data["native"]:
        raise SystemExit("hemicube_profile.py: no native timing to tabulate (--processes 0)")
    found, sentence, text = tables(data)
    section = found + "\n\n" + METHOD + "\n\n" + measured_when(data) + "\n\n" + text
    sys.stdout.write(section)
    if args.page:
        with open(PAGE, encoding="utf-8") as f:  # the page itself, rewritten (not an input)
            page = f.read()
        page = replace_between(page, BEGIN, END, section, "table")
        page = replace_between(page, OPEN_BEGIN, OPEN_END, sentence, "opening")
        output_file.write(PAGE, page)


if __name__ == "__main__":
    lp.run_main(main, "hemicube_profile.py")
