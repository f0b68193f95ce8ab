#!/usr/bin/python3
"""What a ray-patch test costs the host in each scene and in the probe's rooms, and why:
the table of docs/machines/probe.md, "What a test costs: the simulated caches and branches".

    /usr/bin/python3 docs/machines/loop_profile.py [--processes P] [--rounds R] [--jobs J]
                                                   [--out FILE] [--from FILE]

For each run of `build/machine_probe --scenes` (the probe's six rooms whose tests fit
test_speed, and the four scenes with their patches in order and shuffled):

* counted by valgrind's cachegrind (--cache-sim=yes --branch-sim=yes; caches as CACHES below):
  two processes of `build/machine_probe --loop-only RUN --passes 0` and `--passes 1`, whose
  difference is one pass of the run's shots (the set-up, the warming pass and the process's
  start cancel); per ray-patch test: instructions (Ir), data reads (Dr) and writes (Dw),
  first-level data misses (D1mr + D1mw), last-level misses (DLmr + DLmw), conditional branches
  (Bc) and their mispredictions (Bcm). These are deterministic: the same binary gives the same
  figures;
* timed natively: P processes of `build/machine_probe --scenes R` (every run timed round by
  round in one process, thread CPU time, the median of its R rounds); the host's ns a test is
  each run's median time of a pass over its tests (all of the loop's time: rays and blocked
  rays included), given as the median over the P processes with their least and largest.

Then ns a test is regressed over the runs on each simulated count a test (least squares with
an intercept), and on instructions and mispredictions together; the table gives each fit's
slope, R^2 and its largest residual. A pass's instructions are fitted on the counted kinds; each
process's times are fitted on the rooms alone (the model's way, instructions at one rate, and
instructions with the simulated mispredictions) and the scenes predicted from them; each run's
median miss of the model is regressed on the simulated counts. With --real, the scenes' whole
runs as docs/machines/prediction_table.py times them: three under cachegrind (the loop
function's own counts, the difference of two runs' iterations) and ROUNDS rounds natively, each
against a --scenes process in the same round.

The measurements are kept in --out (JSON); --from makes the tables again from such a file
without running anything (--more, --real: adds to it); --page writes them into
docs/machines/probe.md between its loop-profile markers.
"""

import argparse
import json
import os
import re
import resource
import subprocess
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__)))), "analysis"))
from ncube.interpreter import use_project_python  # noqa: E402

use_project_python()   # Debian's /usr/bin/python3 (README.md, "Use"): numpy below

# numpy (0.1 s of CPU a start) is imported by the functions that use it: --help and refusals need none.

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(ROOT, "analysis"))
from ncube import input_file, output_file  # noqa: E402

PROBE = os.path.join(ROOT, "build", "machine_probe")
PLATFORM = os.path.join(ROOT, "platforms", "machines", "cluster-2024.xml")
PAGE = os.path.join(HERE, "probe.md")
BEGIN, END = "<!-- loop-profile:begin -->", "<!-- loop-profile:end -->"
ROOMS = [f"room of {n} patches" for n in (19, 49, 103, 241, 505, 985)]
SCENES = [f"{s} {o}" for s in ("cornell-box", "scene0", "scene1", "scene2")
          for o in ("in order", "shuffled")] + ["scene1 receivers together", "scene2 receivers together"]
# The simulated caches: a core of AMD's Zen 2/3 as its manuals give it, first-level 32 KiB 8-way,
# 64-byte lines; cachegrind's last level is set to the core's own second level, 512 KiB 8-way
# (this guest's /sys shows no cache sizes: assumed). Cachegrind has no prefetcher.
CACHES = ["--I1=32768,8,64", "--D1=32768,8,64", "--LL=524288,8,64"]
EVENTS = ["Ir", "I1mr", "ILmr", "Dr", "D1mr", "DLmr", "Dw", "D1mw", "DLmw", "Bc", "Bcm", "Bi", "Bim"]


def cachegrind(run, passes):
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "cg.out")
        done = subprocess.run(["nice", "-n", "19", "valgrind", "--tool=cachegrind",
                               "--cache-sim=yes", "--branch-sim=yes", *CACHES,
                               f"--cachegrind-out-file={out}", PROBE, "--loop-only", run,
                               "--passes", str(passes)], capture_output=True, text=True, check=True)
        text = input_file.read_input_text(out, "cachegrind's output", 1 << 30)
    events = re.search(r"^events: (.*)$", text, re.M).group(1).split()
    summary = [int(x) for x in re.search(r"^summary: (.*)$", text, re.M).group(1).split()]
    counts = dict(zip(events, summary))
    line = [x for x in done.stdout.splitlines() if x.startswith(run + " |")][0]
    work = {k: float(v) for k, v in re.findall(r"\| (\w+) ([0-9.]+)", line)}
    return counts, work


def simulate_counts(run):
    (base, _), (one, work) = cachegrind(run, 0), cachegrind(run, 1)
    return {"work": work, "pass": {e: one[e] - base[e] for e in EVENTS if e in one}}


def native(rounds):
    done = subprocess.run(["nice", "-n", "19", PROBE, "--scenes", str(rounds), "--network", PLATFORM],
                          capture_output=True, text=True, check=True)
    rows = {}
    for line in done.stdout.splitlines()[1:]:
        cells = [c.strip() for c in line.split("|")]
        rows[cells[0]] = {"passes": int(cells[4]), "median_s": float(cells[5]),
                          "spread_percent": float(cells[6].rstrip(" %")), "ns_a_test": float(cells[9])}
    return rows


# Whole runs of the scenes, as docs/machines/prediction_table.py times them: (scene, N), the
# iterations N+1 .. 2N the difference of a run of N and one of 2N (natively); under cachegrind
# fewer, (scene, a, b), the difference of a and b iterations.
REAL = [("cornell-box", 40), ("scene0", 20), ("scene1", 3), ("scene2", 1)]
REAL_COUNTED = [("cornell-box", 10, 20), ("scene0", 5, 10), ("scene1", 1, 2)]
KINDS = ["ray_patch_tests", "plane_crossings", "rays", "blocked_rays"]
SIMULATE = os.path.join(ROOT, "build", "simulate")


def simulate_run(scene, iterations, work, wrap=(), extra=(), counters=KINDS):
    out = os.path.join(work, f"{scene}-{iterations}.json")
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run(["nice", "-n", "19", *wrap, SIMULATE, os.path.join(ROOT, "scenes", scene + ".json"),
                    "--R", "1", "--V", "0", "--iterations", str(iterations), "--reference-visibility",
                    "--threads", "1", "--platform", PLATFORM, "--json", out, "--quiet", *extra],
                   check=True, capture_output=True)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    result = json.loads(input_file.read_input_text(out, "a result file", 1 << 26))
    return {"cpu": after.ru_utime - before.ru_utime + after.ru_stime - before.ru_stime,
            "simulated": result["simulated_seconds"],
            "counts": {k: result["counts"].get(k, 0) for k in counters}}


def real_round():
    """One round: each scene's runs of N and 2N iterations, then a --scenes process of 3 rounds."""
    row = {"real": {}}
    with tempfile.TemporaryDirectory() as work:
        for scene, n in REAL:
            row["real"][scene] = [simulate_run(scene, n, work), simulate_run(scene, 2 * n, work)]
    row["loop"] = native(3)
    return row


def real_counted(item):
    """The loop function's own instructions (BruteForceOccluders::answer) in two whole runs."""
    scene, a, b = item
    out = {}
    with tempfile.TemporaryDirectory() as work:
        for iterations in (a, b):
            cg = os.path.join(work, "cg.out")
            run = simulate_run(scene, iterations, work,
                               ("valgrind", "--tool=cachegrind", "--cache-sim=yes",
                                "--branch-sim=yes", *CACHES, f"--cachegrind-out-file={cg}"))
            text = subprocess.run(["cg_annotate", "--auto=no", cg], capture_output=True, text=True,
                                  check=True).stdout
            line = [x for x in text.splitlines() if "BruteForceOccluders::answer" in x][0]
            numbers = [int(t.replace(",", "")) for t in line.split("???")[0].split()
                       if re.fullmatch(r"[\d,]+", t)]
            out[iterations] = {"counts": run["counts"], "answer": dict(zip(EVENTS, numbers))}
    return {"iterations": [a, b],
            "work": {k: out[b]["counts"][k] - out[a]["counts"][k] for k in KINDS},
            "pass": {e: out[b]["answer"][e] - out[a]["answer"][e] for e in EVENTS}}


def real_tables(data, ir_fit):
    import numpy as np
    out = []
    if data.get("real_cachegrind"):
        out += ["", "Whole runs under cachegrind (the loop function's own counts, the difference "
                "of two runs' iterations), against the loop's instructions fitted on the counted "
                "kinds above:", "",
                "| scene, iterations | tests a ray | crossing share | Ir a test | fitted from the "
                "counts over counted | D1 misses a test | mispredicts a test |",
                "|---|--:|--:|--:|--:|--:|--:|"]
        for scene, r in data["real_cachegrind"].items():
            w, p = r["work"], r["pass"]
            t = w["ray_patch_tests"]
            fitted = sum(c * w[k] for c, k in zip(ir_fit, KINDS))
            a, b = r["iterations"]
            out.append(f"| {scene}, iteration{'s' if b > a + 1 else ''} "
                       f"{f'{a + 1} to {b}' if b > a + 1 else b} | "
                       f"{t / w['rays']:.1f} | {w['plane_crossings'] / t:.3f} | {p['Ir'] / t:.1f} | "
                       f"{100 * (fitted / p['Ir'] - 1):+.2f} % | {(p['D1mr'] + p['D1mw']) / t:.3f} | "
                       f"{p['Bcm'] / t:.3f} |")
    if data.get("real"):
        costs, rates = cost_model(), platform_rates(PLATFORM)
        out += ["", f"Whole runs natively, {len(data['real'])} rounds (each: the runs of N and 2N "
                "iterations, one process each, and a --scenes process of 3 rounds beside them): "
                "the host's ns a test of the timed iterations (their CPU seconds less what the "
                "committed platform simulates for their other work, rays and blocked rays) over "
                "the loop's ns a test in the same round, and the crossing share of each:", "",
                "| scene | crossing share, run / loop | ns a test, run over loop: median (least to "
                "largest) | expected from the counted flops a test | simulated over host − 1 at "
                "the committed rates, median (least to largest) |", "|---|--:|--:|--:|--:|"]
        for scene, _ in REAL:
            ratio, sim = [], []
            for row in data["real"]:
                a, b = row["real"][scene]
                d = {k: b["counts"][k] - a["counts"][k] for k in KINDS}
                cpu, simulated = b["cpu"] - a["cpu"], b["simulated"] - a["simulated"]
                test_flops = (d["ray_patch_tests"] * costs["flops_per_ray_patch_test"] +
                              d["plane_crossings"] * costs["flops_per_plane_crossing"])
                host_tests = cpu - (simulated - test_flops / rates["test_speed"])
                ratio.append(host_tests / d["ray_patch_tests"] * 1e9 / row["loop"][scene + " in order"]["ns_a_test"])
                sim.append(simulated / cpu - 1)
            loop = data["cachegrind"][scene + " in order"]["work"]
            share_loop = loop["plane_crossings"] / loop["ray_patch_tests"]
            share_run = d["plane_crossings"] / d["ray_patch_tests"]
            expected = ((costs["flops_per_ray_patch_test"] + share_run * costs["flops_per_plane_crossing"]) /
                        (costs["flops_per_ray_patch_test"] + share_loop * costs["flops_per_plane_crossing"]))
            out.append(f"| {scene} | {share_run:.3f} / {share_loop:.3f} | "
                       f"{np.median(ratio):.2f} ({min(ratio):.2f} to {max(ratio):.2f}) | "
                       f"{expected:.2f} | {spread_text(sim)} |")
    return out


def fit(x, y):
    """Least squares y = a + b x (x a matrix of columns): coefficients, R^2, residuals."""
    import numpy as np
    a = np.column_stack([np.ones(len(y)), *x])
    coef, *_ = np.linalg.lstsq(a, y, rcond=None)
    res = y - a @ coef
    return coef, 1 - (res @ res) / ((y - y.mean()) @ (y - y.mean())), res


def platform_rates(path):
    text = input_file.read_input_text(path, "platform", 1 << 22)
    return {k: float(v) for k, v in re.findall(r'<prop id="(\w+_speed)" value="([0-9.eE+-]+)"', text)}


def cost_model():
    text = input_file.read_input_text(os.path.join(ROOT, "platforms", "cost_model.json"),
                                      "cost model", 1 << 20)
    return {k: v["value"] for k, v in json.loads(text)["parameters"].items()}


def rooms_to_scenes(data, runs):
    """Each process's times fitted on the rooms alone, three ways, and what each predicts for
    every run (fitted over measured, minus 1; the rooms' own are residuals): the model's way
    (tests and crossings at one test rate, the rays and blocked rays taken off at the committed
    platform's rates), the instructions' (the loop's whole time at one rate an instruction), and
    the instructions with the simulated mispredictions as a second kind."""
    import numpy as np
    costs, rates = cost_model(), platform_rates(PLATFORM)
    rooms = [r for r in runs if r in ROOMS]
    misses = {r: {"model": [], "Ir": [], "Ir+Bcm": []} for r in runs}
    for proc in data["native"]:
        t, model_x, ir, bcm = {}, {}, {}, {}
        present = [r for r in runs if r in proc]  # a run added later is in later processes only
        for r in present:
            w, p = data["cachegrind"][r]["work"], data["cachegrind"][r]["pass"]
            t[r] = proc[r]["median_s"] / proc[r]["passes"]
            others = (w["rays"] * costs["flops_per_ray"] / rates["ray_speed"] +
                      w["blocked_rays"] * costs["flops_per_blocked_ray"] / rates["blocked_ray_speed"])
            flops = (w["ray_patch_tests"] * costs["flops_per_ray_patch_test"] +
                     w["plane_crossings"] * costs["flops_per_plane_crossing"])
            model_x[r] = (flops, t[r] - others)
            ir[r], bcm[r] = p["Ir"], p["Bcm"]
        xs = np.array([model_x[r][0] / model_x[r][1] for r in rooms])
        s = xs.sum() / (xs @ xs)  # relative least squares, one rate
        for r in present:
            misses[r]["model"].append(s * model_x[r][0] / model_x[r][1] - 1)
        xs = np.array([ir[r] / t[r] for r in rooms])
        s = xs.sum() / (xs @ xs)
        for r in present:
            misses[r]["Ir"].append(s * ir[r] / t[r] - 1)
        a = np.array([[ir[r] / t[r], bcm[r] / t[r]] for r in rooms])
        c, *_ = np.linalg.lstsq(a, np.ones(len(rooms)), rcond=None)
        for r in present:
            misses[r]["Ir+Bcm"].append((c[0] * ir[r] + c[1] * bcm[r]) / t[r] - 1)
        misses.setdefault("_coef", []).append(c)
    return misses


def spread_text(values):
    import numpy as np
    v = 100 * np.array(values)
    return f"{np.median(v):+.1f} % ({v.min():+.1f} to {v.max():+.1f})"


def tables(data):
    import numpy as np
    runs = [r for r in ROOMS + SCENES if r in data["cachegrind"]]
    rows, per = [], {}
    for r in runs:
        cg = data["cachegrind"][r]
        tests = cg["work"]["ray_patch_tests"]
        p = cg["pass"]
        ns = [1e9 * proc[r]["median_s"] / proc[r]["passes"] / tests for proc in data["native"] if r in proc]
        per[r] = {"ns": float(np.median(ns)), "Ir": p["Ir"] / tests,
                  "D1": (p["D1mr"] + p["D1mw"]) / tests, "LL": (p["DLmr"] + p["DLmw"]) / tests,
                  "Bcm": p["Bcm"] / tests, "Bc": p["Bc"] / tests,
                  "D": (p["Dr"] + p["Dw"]) / tests}
        x = per[r]
        rows.append(f"| {r} | {cg['work']['patches_tested_a_ray']:.1f} | "
                    f"{cg['work']['plane_crossings'] / tests:.3f} | "
                    f"{cg['work']['blocked_rays'] / cg['work']['rays']:.3f} | "
                    f"{x['Ir']:.1f} | {x['D']:.1f} | {x['D1']:.3f} | {x['LL']:.4f} | {x['Bc']:.2f} | "
                    f"{x['Bcm']:.3f} | {x['ns']:.2f} ({min(ns):.2f}–{max(ns):.2f}) |")
    out = ["| run | tests a ray | crossing share | blocked a ray | Ir a test | data refs a test | "
           "D1 misses a test | LL misses a test | cond. branches a test | mispredicts a test | "
           "host ns a test, median (least–largest) |",
           "|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|", *rows, ""]
    y = np.array([per[r]["ns"] for r in runs])
    out += ["| ns a test regressed on | slope | R² | largest residual |", "|---|--:|--:|--:|"]
    for name, keys in [("Ir a test", ["Ir"]), ("D1 misses a test", ["D1"]),
                       ("mispredicts a test", ["Bcm"]), ("crossing share", ["cross"]),
                       ("Ir and mispredicts a test", ["Ir", "Bcm"])]:
        cols = []
        for k in keys:
            cols.append(np.array([data["cachegrind"][r]["work"]["plane_crossings"] /
                                  data["cachegrind"][r]["work"]["ray_patch_tests"] if k == "cross"
                                  else per[r][k] for r in runs]))
        coef, r2, res = fit(cols, y)
        slopes = ", ".join(f"{c:.3g} ns a unit" for c in coef[1:])
        out.append(f"| {name} | {slopes} | {r2:.2f} | {np.max(np.abs(res)):.2f} ns |")
    # The instructions of a pass as the counted kinds would charge them: a relative least
    # squares fit of Ir = a tests + b crossings + c rays + d blocked rays over every run.
    kinds = ["ray_patch_tests", "plane_crossings", "rays", "blocked_rays"]
    a = np.array([[data["cachegrind"][r]["work"][k] for k in kinds] for r in runs])
    ir = np.array([data["cachegrind"][r]["pass"]["Ir"] for r in runs])
    c, *_ = np.linalg.lstsq(a / ir[:, None], np.ones(len(runs)), rcond=None)
    res = 100 * (a @ c / ir - 1)
    out += ["", "Instructions of a pass fitted on the counted kinds over all "
            f"{len(runs)} runs (relative least squares): {c[0]:.1f} a test, {c[1]:.1f} a "
            f"crossing, {c[2]:.1f} a ray, {c[3]:.1f} a blocked ray; residuals "
            f"{res.min():+.2f} to {res.max():+.2f} % (the counts move together over these runs, "
            "so a coefficient is not its kind's own cost, and a ray's comes out negative; the "
            "residuals are what this checks: " +
            ", ".join(f"{r} {v:+.2f} %" for r, v in zip(runs, res)) + ")."]
    out += real_tables(data, c)
    misses = rooms_to_scenes(data, runs)
    coef = np.array(misses.pop("_coef"))
    out += ["", f"Fitted on the six rooms alone, in each of the {len(data['native'])} processes, "
            "what each fit predicts (fitted over measured, minus 1; median over the processes, "
            "least to largest; the rooms' own rows are residuals). The instructions and "
            "mispredictions fit gave "
            f"{np.median(coef[:, 0]) * 1e9:.3f} ns an instruction and "
            f"{np.median(coef[:, 1]) * 1e9:.2f} ns a simulated misprediction (medians).", "",
            "| run | the model's kinds (tests, crossings at one rate) | instructions at one rate "
            "| instructions and simulated mispredictions |", "|---|--:|--:|--:|"]
    for r in runs:
        m = misses[r]
        out.append(f"| {r} | {spread_text(m['model'])} | {spread_text(m['Ir'])} | "
                   f"{spread_text(m['Ir+Bcm'])} |")
    # The order: each scene's loop shuffled over in order, per process (the same counts).
    out += ["", "| scene | time shuffled over in order, median over the processes (least to largest) |",
            "|---|--:|"]
    for scene in ("cornell-box", "scene0", "scene1", "scene2"):
        ratios = [(1 + a) / (1 + b) - 1 for a, b in zip(misses[scene + " in order"]["model"],
                                                         misses[scene + " shuffled"]["model"])]
        out.append(f"| {scene} | {spread_text(ratios)} |")
    together = [f"{x} receivers together" for x in ("scene1", "scene2") if f"{x} receivers together" in runs]
    if together:
        out += ["", "| scene | the model's miss, its receivers one after another over every k-th (in "
                "order), median over the processes that timed both (least to largest) |", "|---|--:|"]
        for r in together:
            scene = r.split()[0]
            m_t = misses[r]["model"]
            m_o = misses[scene + " in order"]["model"][-len(m_t):]
            out.append(f"| {scene} | {spread_text([(1 + a) / (1 + b) - 1 for a, b in zip(m_t, m_o)])} |")
    # What the model's kinds leave (each run's median miss above) against what cachegrind
    # counts a test beyond them: does any of them carry it?
    left = np.array([np.median(misses[r]["model"]) for r in runs])
    costs = cost_model()
    flops = {r: costs["flops_per_ray_patch_test"] + costs["flops_per_plane_crossing"] *
             data["cachegrind"][r]["work"]["plane_crossings"] /
             data["cachegrind"][r]["work"]["ray_patch_tests"] for r in runs}
    out += ["", "| the model's miss (median a run, above) regressed on | slope | R² |", "|---|--:|--:|"]
    for name, values in [("Ir a counted test flop", [per[r]["Ir"] / flops[r] for r in runs]),
                         ("simulated D1 misses a test", [per[r]["D1"] for r in runs]),
                         ("simulated mispredicts a test", [per[r]["Bcm"] for r in runs]),
                         ("conditional branches a test", [per[r]["Bc"] for r in runs]),
                         ("tests a ray (log10)", [np.log10(data["cachegrind"][r]["work"]
                                                           ["patches_tested_a_ray"]) for r in runs])]:
        coef, r2, _ = fit([np.array(values)], 100 * left)
        out.append(f"| {name} | {coef[1]:+.3g} % a unit | {r2:.2f} |")
    return "\n".join(out) + "\n"


def study_parser(description, rounds, counter, markers, whole):
    """The options this study shares with docs/machines/hemicube_profile.py: `counter` names the
    valgrind tool, `markers` the page's, `whole` the rows the whole runs are of."""
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("--processes", type=int, default=3)
    parser.add_argument("--rounds", type=int, default=rounds)
    parser.add_argument("--jobs", type=int, default=1, help=f"{counter} processes at once")
    parser.add_argument("--out", help="keep the measurements here (JSON)")
    parser.add_argument("--from", dest="source", help="no runs: the tables from this JSON")
    parser.add_argument("--more", action="store_true",
                        help="with --from: time --processes more processes natively, added to "
                             f"its measurements ({counter}'s counts are the binary's own)")
    parser.add_argument("--page", action="store_true",
                        help=f"write the tables into docs/machines/probe.md between its {markers} "
                             "markers")
    parser.add_argument("--real", type=int, default=0, metavar="ROUNDS",
                        help=f"with --from: time the {whole} whole runs this many rounds more, and "
                             f"count three of them under {counter} (once), added to its measurements")
    return parser


def read_measurements(path, script, keys):
    """A measurements file this study wrote (--from): an object with `keys`, or a refusal."""
    data = input_file.read_json(path, "measurements", 1 << 24)
    if not isinstance(data, dict) or not all(isinstance(data.get(k), (dict, list)) for k in keys):
        raise SystemExit(f"{script}: {path}: not measurements of this study (an object with "
                         f"{', '.join(keys)}); nothing written")
    return data


def check_built(programs, script):
    for program in programs:
        if not os.access(program, os.X_OK):
            raise SystemExit(f"{script}: {program} is not built (cmake --build build); nothing written")


def run_main(main, script):
    """`main` with the studies' exits: a refusal's message on one line, exit 2."""
    try:
        main()
    except SystemExit as e:
        if isinstance(e.code, str):
            print(e.code, file=sys.stderr)
            sys.exit(2)
        raise
    except (input_file.InputFileError, KeyError, StopIteration) as e:
        print(f"{script}: {e} (not a file this script wrote?); nothing written", file=sys.stderr)
        sys.exit(2)


def main():
    parser = study_parser(__doc__.split("\n")[0], 15, "cachegrind", "loop-profile", "scenes'")
    args = parser.parse_args()
    needs = [] if args.source and not (args.more or args.real) else [PROBE]
    check_built(needs + ([SIMULATE] if args.real else []), "loop_profile.py")
    if args.source:
        data = read_measurements(args.source, "loop_profile.py", ["native", "cachegrind"])
        if args.real:  # the whole runs' counts once; their rounds added to those kept
            if "real_cachegrind" not in data:
                with ThreadPoolExecutor(args.jobs) as pool:
                    data["real_cachegrind"] = {item[0]: r for item, r in
                                               zip(REAL_COUNTED, pool.map(real_counted, REAL_COUNTED))}
            data["real"] = data.get("real", []) + [real_round() for _ in range(args.real)]
            if args.out:
                output_file.write(args.out, json.dumps(data, indent=1) + "\n")
        if args.more:
            missing = [r for r in ROOMS + SCENES if r not in data["cachegrind"]]
            with ThreadPoolExecutor(args.jobs) as pool:
                for run, counted in zip(missing, pool.map(simulate_counts, missing)):
                    data["cachegrind"][run] = counted
            for _ in range(args.processes):
                data["native"].append(native(args.rounds))
            if args.out:
                output_file.write(args.out, json.dumps(data, indent=1) + "\n")
    else:
        data = {"caches": CACHES, "native": [], "cachegrind": {}}
        with ThreadPoolExecutor(args.jobs) as pool:
            for run, counted in zip(ROOMS + SCENES, pool.map(simulate_counts, ROOMS + SCENES)):
                data["cachegrind"][run] = counted
        for _ in range(args.processes):
            data["native"].append(native(args.rounds))
        if args.out:
            output_file.write(args.out, json.dumps(data, indent=1) + "\n")
    text = tables(data)
    sys.stdout.write(text)
    if args.page:
        with open(PAGE, encoding="utf-8") as f:  # the page itself, rewritten (not an input)
            page = f.read()
        if BEGIN not in page or END not in page or not text.strip():
            raise SystemExit(f"loop_profile.py: {PAGE} has no {BEGIN} ... {END}, or no table")
        begin, end = page.index(BEGIN) + len(BEGIN), page.index(END)
        output_file.write(PAGE, page[:begin] + "\n" + text + page[end:])


if __name__ == "__main__":
    run_main(main, "loop_profile.py")
