#!/usr/bin/python3
"""Host speed of ./simulate, today's code next to an older build in one run (a reported
figure, not a test; docs/performance.md shows its output).

  bench/speed_report.py [--old OLD_BUILD_DIR] [--repeat N] [--scale] [--converge]
  bench/speed_report.py --converge-only [--old OLD_BUILD_DIR] [--repeat N] [--threads N]
  bench/speed_report.py --scale-only [--repeat N]
  bench/speed_report.py --plot-only

OLD_BUILD_DIR holds an older build's simulate (e.g. main at c39b79f built in a worktree:
git worktree add /tmp/speed-old c39b79f && cmake -S /tmp/speed-old -B /tmp/speed-old/build
&& cmake --build /tmp/speed-old/build). Host seconds per iteration are the difference of
runs with more and fewer iterations (set-up not counted), the minimum over --repeat runs
(the host may be shared). Writes bench/measured/*.json; --scale also the plot
docs/images/performance-scale.png, which --plot-only redraws from bench/measured/scale.json.
The runs to convergence (--converge, --converge-only) run old and new in turn, report wall
seconds and peak resident memory, and check that both result files agree byte for byte apart
from host seconds, the code version and the paths of the input files.
"""

import sys  # noqa: E402
from pathlib import Path  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "analysis"))
from ncube.interpreter import use_project_python  # noqa: E402

use_project_python()   # Debian's /usr/bin/python3 (README.md, "Use")

import argparse
import json
import os
import re
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
NEW = os.path.join(ROOT, "build", "simulate")
RESULTS = os.path.join(ROOT, "bench", "measured")
SCALE_PLOT = os.path.join(ROOT, "docs", "images", "performance-scale.png")


def run(binary, args, env=None, keep_text=False):
    """Runs simulate; returns (result file, wall seconds), with keep_text also the file's text
    and the run's peak resident memory in MiB."""
    with tempfile.NamedTemporaryFile(suffix=".json", delete=False) as f:
        out = f.name
    start = time.perf_counter()
    # argv[0] is the same for every binary: the result file records the command line.
    process = subprocess.Popen(["simulate"] + args + ["--json", out, "--quiet"],
                               executable=binary, env=env)
    _, status, usage = os.wait4(process.pid, 0)
    wall = time.perf_counter() - start
    if status != 0:
        raise RuntimeError(f"{binary} {' '.join(args)} failed ({status})")
    with open(out) as f:
        text = f.read()
    os.unlink(out)
    if keep_text:
        return json.loads(text), wall, text, usage.ru_maxrss / 1024
    return json.loads(text), wall


def without_host_fields(text):
    """The result file's text without what may differ between two builds and runs: host
    seconds, the code version, the command line (temporary output path) and the input files'
    paths (each build's own source tree). Everything else is compared byte for byte."""
    text = re.sub(r'"command_line": \[.*?\]', "", text, flags=re.S)
    return re.sub(r'"(host_seconds|code_version|file)": [^\n]*', "", text)


def convergence(old, threads):
    """scene2 at R=8, V=7 with the calibrated defaults to convergence, old and new in turn;
    wall seconds, peak memory, and whether the result files agree apart from host fields."""
    scene2 = ["scene2.json", "--R", "8", "--V", "7"] + ([] if threads is None else ["--threads", str(threads)])
    rows, texts, results = {}, {}, {}
    for label, binary in (("old", old), ("new", NEW)):
        if binary is None:
            continue
        result, wall, text, rss = run(binary, scene2, keep_text=True)
        texts[label] = without_host_fields(text)
        results[label] = result
        rows[label] = {"iterations": result["iterations"], "converged": result["converged"],
                       "wall_seconds": wall, "host_seconds": result["host_seconds"],
                       "peak_resident_MiB": rss}
    if len(texts) == 2:
        rows["identical_apart_from_host_fields"] = texts["old"] == texts["new"]
        # When the simulated times were charged differently (e.g. one SimGrid activity for
        # several steps), the files differ in the times' last digits only: say so.
        old_r, new_r = results["old"], results["new"]
        rows["same_shooters_and_radiosities"] = (old_r["shooters"] == new_r["shooters"] and
                                                 old_r["patch_radiosity"] == new_r["patch_radiosity"])
        rows["max_relative_difference_of_iteration_seconds"] = max(
            (abs(a - b) / abs(a) for a, b in zip(old_r["iteration_seconds"], new_r["iteration_seconds"]) if a),
            default=0.0)
    return rows


def per_iteration(binary, args, few, many, repeat, threads=None):
    """(min over `repeat` of host(many) - the same of host(few)) / (many - few), and the
    fastest run of `many` (the minima taken apart: a minimum of differences favours noise)."""
    extra = [] if threads is None else ["--threads", str(threads)]
    fewest, most, kept = None, None, None
    for _ in range(repeat):
        a, _ = run(binary, args + ["--iterations", str(few)] + extra)
        b, _ = run(binary, args + ["--iterations", str(many)] + extra)
        fewest = a["host_seconds"] if fewest is None else min(fewest, a["host_seconds"])
        if most is None or b["host_seconds"] < most:
            most, kept = b["host_seconds"], b
    return (most - fewest) / (many - few), kept


def embree_alone():
    bench = os.path.join(ROOT, "build", "benchmarks")
    out = subprocess.run([bench, "--benchmark_filter=embree_alone/scene3", "--benchmark_format=json"],
                         check=True, capture_output=True, text=True).stdout
    return json.loads(out)["benchmarks"][0]["rays_per_second"]


def load_average():
    with open("/proc/loadavg") as f:
        return float(f.read().split()[0])


def comparison(old, repeat, converge):
    report = {"load_average_at_start": load_average(), "cores": os.cpu_count()}
    scene2 = ["scene2.json", "--R", "8", "--V", "7", "--samples", "64"]
    scene3 = ["scene3.json", "--R", "1", "--unlimited-memory", "--samples", "64"]
    for label, binary in (("new", NEW), ("old", old)):
        if binary is None:
            continue
        threads = None if label == "old" else 0
        t2, _ = per_iteration(binary, scene2, 2, 12, repeat, threads)
        t3, run3 = per_iteration(binary, scene3, 1, 3, repeat, threads)
        rays = run3["counts"]["rays"] / 3
        report[label] = {"scene2_R8_V7_seconds_per_iteration": t2,
                         "scene3_R1_seconds_per_iteration": t3,
                         "scene3_R1_rays_per_second": rays / t3}
        if label == "new":
            t3_one, _ = per_iteration(binary, scene3, 1, 3, repeat, 1)
            report[label]["scene3_R1_seconds_per_iteration_1_thread"] = t3_one
            report[label]["scene3_R1_rays_per_second_1_thread"] = rays / t3_one
    report["embree_alone_rtcOccluded16_rays_per_second_1_thread"] = embree_alone()
    if converge:
        report["scene2_R8_V7_to_convergence"] = convergence(old, None)
    report["load_average_at_end"] = load_average()
    return report


def scale(repeat):
    """Host seconds per iteration against the scene's size and against the simulated nodes."""
    rows = {"scenes": [], "nodes": []}
    # Iterations 2 to `many`: enough of them on the small scenes for the time to stand
    # out of the start-up's noise (mostly first shots still: scene0 has 52 patches).
    scenes = [("scene0.json", 21), ("scene1.json", 11), ("scene2.json", 3), ("scene3.json", 3),
              ("scene4.json", 3)]
    for scene, many in scenes:
        t, result = per_iteration(NEW, [scene, "--R", "1", "--unlimited-memory", "--samples", "64"],
                                  1, many, repeat)
        path = scene if os.path.isabs(scene) else os.path.join(ROOT, "scenes", scene)
        patches = json.load(open(path))["patches"]
        rows["scenes"].append({"scene": os.path.basename(scene), "patches": len(patches),
                               "elements": sum(p["elements"][0] * p["elements"][1] for p in patches),
                               "rays_per_iteration": result["counts"]["rays"] / many,
                               "seconds_per_iteration": t})
    platform = json.load(open(os.path.join(ROOT, "platforms", "ncube2.json")))
    configs = [(1, 0), (2, 0), (4, 0), (2, 1), (8, 0), (4, 1), (16, 0), (4, 3), (32, 0), (8, 3),
               (64, 0), (8, 7), (4, 15), (128, 0), (16, 7), (256, 0), (32, 7), (512, 0), (64, 15)]
    for r, v in configs:
        nodes = r * (v + 1)
        args = ["scene2.json", "--R", str(r), "--V", str(v), "--samples", "64", "--unlimited-memory"]
        if nodes > 64:
            dimension = (nodes - 1).bit_length()
            platform["parameters"]["dimension"]["value"] = dimension
            path = f"/tmp/speed-platform-{dimension}.json"
            json.dump(platform, open(path, "w"))
            args += ["--platform", path]
        t, _ = per_iteration(NEW, args, 1, 3, repeat)
        rows["nodes"].append({"R": r, "V": v, "nodes": nodes, "seconds_per_iteration": t})
    return rows


def plot(rows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (a, b) = plt.subplots(1, 2, figsize=(10, 4))
    s = rows["scenes"]
    a.loglog([r["rays_per_iteration"] * r["patches"] for r in s], [r["seconds_per_iteration"] for r in s], "o-")
    for r in s:
        a.annotate(r["scene"].replace(".json", ""), (r["rays_per_iteration"] * r["patches"], r["seconds_per_iteration"]))
    a.set_xlabel("brute-force ray-patch tests per iteration (rays x patches)")
    a.set_ylabel("host seconds per iteration")
    a.set_title("R=1, V=0, M=64: scene size")
    n = rows["nodes"]
    for v in sorted({r["V"] for r in n}):
        pts = sorted((r["nodes"], r["seconds_per_iteration"]) for r in n if r["V"] == v)
        b.semilogx([p[0] for p in pts], [p[1] for p in pts], "o-", base=2, label=f"V={v}")
    b.axvline(64, color="grey", linestyle=":")
    b.set_xlabel("simulated nodes R x (V+1)")
    b.set_ylabel("host seconds per iteration")
    b.set_title("scene2, M=64: simulated machine")
    b.legend()
    fig.tight_layout()
    fig.savefig(path, dpi=100)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--old", help="build directory of the code to compare with")
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--scale", action="store_true")
    parser.add_argument("--converge", action="store_true")
    parser.add_argument("--converge-only", action="store_true",
                        help="only the run to convergence (old and new in turn), to "
                             "bench/measured/convergence.json")
    parser.add_argument("--threads", type=int, help="--threads for --converge-only (default: all cores)")
    parser.add_argument("--scale-only", action="store_true",
                        help="only the scale table, to bench/measured/scale.json and the plot")
    parser.add_argument("--plot-only", action="store_true",
                        help="no runs: redraw the plot from bench/measured/scale.json")
    args = parser.parse_args()
    if args.plot_only:
        with open(os.path.join(RESULTS, "scale.json")) as f:
            plot(json.load(f), SCALE_PLOT)
        print("wrote " + os.path.relpath(SCALE_PLOT, ROOT))
        return 0
    os.makedirs(RESULTS, exist_ok=True)
    old = os.path.join(args.old, "simulate") if args.old else None
    if args.converge_only:
        report = {"load_average_at_start": load_average(), "cores": os.cpu_count(),
                  "threads": args.threads or "all cores"}
        for r in range(args.repeat):
            report[f"run_{r + 1}"] = convergence(old, args.threads)
            print(json.dumps(report[f"run_{r + 1}"]), flush=True)
        report["load_average_at_end"] = load_average()
        json.dump(report, open(os.path.join(RESULTS, "convergence.json"), "w"), indent=1)
        print(json.dumps(report, indent=1))
        return 0
    if not args.scale_only:
        report = comparison(old, args.repeat, args.converge)
        json.dump(report, open(os.path.join(RESULTS, "comparison.json"), "w"), indent=1)
        print(json.dumps(report, indent=1))
    if args.scale or args.scale_only:
        rows = scale(args.repeat)
        json.dump(rows, open(os.path.join(RESULTS, "scale.json"), "w"), indent=1)
        print(json.dumps(rows, indent=1))
        plot(rows, SCALE_PLOT)


if __name__ == "__main__":
    sys.exit(main())
