#!/usr/bin/python3
"""The long runs researchers wait for, with the host's limit beside each figure (a reported
benchmark, not a test; docs/performance-log.md quotes it).

  bench/long_runs.py [--old OLD_BUILD_DIR] [--iterations N] [--profile] [--simgrid-alone]
                     [--runs NAME,...]

For each run (by default scene3 to convergence at R=8, V=7 and at R=64, V=0, and the octree
on scene2 R=8 V=7 for 20 iterations beside brute force) it reports the host's wall seconds,
the peak resident memory, the rays the simulated program traced and their rate, and the ray-
tracing library's own rate for such rays on the same two threads (Embree's rtcOccluded16 on
scene3's rays, build/benchmarks embree_alone/scene3_2threads): the ratio of the two rates is
the figure to drive down (with V > 0, against the library following every ray to its end,
which is the shares' question). Beside it, the library's floor for the run's own rays:
build/embree_floor traces every distinct shot of the result file (a repeated shot is answered
from the answer cache) through plain Embree on two threads, to the first hit (V = 0) or to
the end of every ray (V > 0). With --old, an older build's simulate runs the same commands in
turn, and the result files are compared byte for byte apart from host fields. With
--profile, the same run is sampled again by perf (199 samples a second, the whole run) and its
time split by library (the simulator, Embree, SimGrid, the C and maths libraries, malloc);
SimGrid's CPU seconds (its share of the run's CPU time) then give the run's floor with
SimGrid: the library's run floor on both threads plus SimGrid's CPU time spread over both,
the least wall time if the host did nothing else and both cores stayed busy.
With --simgrid-alone, the run is made once more recording its SimGrid activities
(NCUBE_RECORD_ACTIVITIES) and build/simgrid_replay replays them with no node program behind
them: SimGrid alone on the run's own messages, measured rather than sampled (the replay must
end at the run's simulated time, or the script says so); the floor with SimGrid then takes
the replay's CPU seconds.
--iterations N caps the runs at N iterations (quick checks of the script).
Writes bench/measured/long_runs.json.
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
import shutil
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
NEW = os.path.join(ROOT, "build", "simulate")
OUT = os.path.join(ROOT, "bench", "measured", "long_runs.json")

RUNS = {
    "scene3_R8_V7": ["scene3.json", "--R", "8", "--V", "7"],
    "scene3_R64_V0": ["scene3.json", "--R", "64", "--V", "0"],
    "scene2_R8_V7_octree_20": ["scene2.json", "--R", "8", "--V", "7", "--iterations", "20",
                               "--visibility", "octree"],
    "scene2_R8_V7_brute_force_20": ["scene2.json", "--R", "8", "--V", "7", "--iterations", "20"],
}


def run_floor(text, mode):
    """build/embree_floor on a result (its distinct shots): seconds on two threads."""
    with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as f:
        f.write(text)
        name = f.name
    try:
        out = subprocess.run([os.path.join(ROOT, "build", "embree_floor"), name, mode], check=True,
                             capture_output=True, text=True).stdout
    finally:
        os.unlink(name)
    return float(out.split()[-1]), out.strip()


def run(binary, args):
    """Runs simulate to a temporary result file: (result, text, wall s, CPU s, peak MiB)."""
    with tempfile.NamedTemporaryFile(suffix=".json", delete=False) as f:
        out = f.name
    env = dict(os.environ, NCUBE_ROOT=os.path.dirname(os.path.dirname(binary)))
    start = time.perf_counter()
    process = subprocess.Popen(["simulate"] + args + ["--json", out, "--quiet"], executable=binary,
                               env=env)
    _, status, usage = os.wait4(process.pid, 0)
    wall = time.perf_counter() - start
    if status != 0:
        raise RuntimeError(f"{binary} {' '.join(args)} failed ({status})")
    with open(out) as f:
        text = f.read()
    os.unlink(out)
    return json.loads(text), text, wall, usage.ru_utime + usage.ru_stime, usage.ru_maxrss / 1024


def simgrid_alone(binary, args, platform):
    """SimGrid alone on the run's messages: (host s, CPU s, peak MiB, simulated end, line)."""
    with tempfile.TemporaryDirectory() as work:
        record = os.path.join(work, "run.act")
        env = dict(os.environ, NCUBE_ROOT=os.path.dirname(os.path.dirname(binary)),
                   NCUBE_RECORD_ACTIVITIES=record)
        subprocess.run([binary] + args + ["--quiet", "--json", os.path.join(work, "r.json")],
                       check=True, env=env)
        line = subprocess.run([os.path.join(os.path.dirname(binary), "simgrid_replay"), platform,
                               record], check=True, capture_output=True, text=True).stdout.strip()
    m = re.search(r": ([0-9.]+) host s, ([0-9.]+) CPU s, peak ([0-9.]+) MiB, simulated end (\S+) s$",
                  line)
    return float(m[1]), float(m[2]), float(m[3]), float(m[4]), line


def comparable(text):
    """The result without the host fields and the provenance (paths, versions, hashes)."""
    result = json.loads(text)
    result.pop("host_seconds", None)
    result.pop("provenance", None)
    return json.dumps(result, sort_keys=True)


def embree_two_threads(case="scene3_2threads"):
    """Embree's own rate on scene3's rays, 2 threads: to the first hit (scene3_2threads) or
    following every ray to its end (scene3_to_the_end_2threads, the question of V > 0)."""
    bench = os.path.join(ROOT, "build", "benchmarks")
    out = subprocess.run([bench, f"--benchmark_filter=embree_alone/{case}/",
                          "--benchmark_format=json"], check=True, capture_output=True,
                         text=True).stdout
    return json.loads(out)["benchmarks"][0]["rays_per_second"]


def profile(binary, args):
    """Share of samples per library for the run (None without perf)."""
    if not shutil.which("perf"):
        return None
    with tempfile.TemporaryDirectory() as work:
        data = os.path.join(work, "perf.data")
        subprocess.run(["perf", "record", "-q", "-F", "199", "-o", data, "--", binary] + args +
                       ["--quiet", "--json", os.path.join(work, "result.json")],
                       check=True, capture_output=True, env=dict(os.environ, NCUBE_ROOT=os.path.dirname(os.path.dirname(binary))))
        report = subprocess.run(["perf", "report", "-i", data, "--no-children", "--stdio",
                                 "--sort", "dso"], check=True, capture_output=True,
                                text=True).stdout
    shares = {}
    for line in report.splitlines():
        m = re.match(r"\s+([0-9.]+)%\s+(\S+)", line)
        if m and float(m.group(1)) >= 0.5:
            shares[re.sub(r"\.so.*", "", m.group(2))] = float(m.group(1))
    return shares


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--old", help="an older build directory (holding simulate)")
    parser.add_argument("--new", default=os.path.dirname(NEW), help="the build directory to measure")
    parser.add_argument("--iterations", type=int, help="cap every run at N iterations")
    parser.add_argument("--profile", action="store_true",
                        help="split each run's time by library; the floor with SimGrid")
    parser.add_argument("--simgrid-alone", action="store_true",
                        help="replay each run's messages with SimGrid alone (build/simgrid_replay)")
    parser.add_argument("--runs", default=",".join(RUNS), help="which runs (comma-separated)")
    options = parser.parse_args()
    # Checked before minutes of runs: one line and exit 2 for a count or a build that cannot be.
    if options.iterations is not None and options.iterations < 1:
        parser.error(f"argument --iterations: {options.iterations}: at least 1")
    unknown = [name for name in options.runs.split(",") if name not in RUNS]
    if unknown:
        parser.error(f"argument --runs: no run {unknown[0]!r} (the runs: {', '.join(RUNS)})")
    needed = [os.path.join(ROOT, "build", "benchmarks"), os.path.join(options.new, "simulate")]
    needed += [os.path.join(options.old, "simulate")] if options.old else []
    for binary in needed:
        if not (os.path.isfile(binary) and os.access(binary, os.X_OK)):
            print(f"long_runs.py: {binary}: not a built program (cmake --build build -j2)",
                  file=sys.stderr)
            return 2
    embree = embree_two_threads()
    to_the_end = embree_two_threads("scene3_to_the_end_2threads")
    report = {"embree_alone_rays_per_second_2_threads": embree,
              "embree_alone_to_the_end_rays_per_second_2_threads": to_the_end,
              "cores": os.cpu_count(), "load_average_at_start": os.getloadavg()[0], "runs": {}}
    print(f"Embree alone, scene3's rays, 2 threads: {embree / 1e6:.1f} M rays/s to the first hit, "
          f"{to_the_end / 1e6:.1f} M rays/s to the end of every ray (the question of V > 0)")
    print(f"{'run':30} {'build':5} {'wall s':>8} {'CPU s':>7} {'peak MiB':>9} {'M rays*':>8} "
          f"{'M rays/s':>9} {'of Embree':>9} {'floor s':>8} {'run floor s':>11}")
    for name in options.runs.split(","):
        args = list(RUNS[name])
        if options.iterations and "--iterations" not in args:
            args += ["--iterations", str(options.iterations)]
        entry = {"command": ["simulate"] + args}
        texts = {}
        builds = [("new", os.path.join(options.new, "simulate"))] + ([("old", os.path.join(options.old, "simulate"))] if options.old else [])
        for label, binary in builds:
            result, text, wall, cpu, peak = run(binary, args)
            texts[label] = text
            # With V > 0 each visibility processor of a group tests the same rays against its
            # share: the simulated program counts a ray V times, the host traces it once.
            v = result["config"].get("V", 0) or 1
            rays = result["counts"]["rays"] / v
            # The library's rate for the question asked: a share's "does one of my patches
            # block it" is not settled by the first blocker when V > 0.
            library = to_the_end if result["config"].get("V", 0) else embree
            entry[label] = {"wall_seconds": wall, "cpu_seconds": cpu, "peak_mib": peak,
                            "distinct_rays": rays,
                            "rays_per_second": rays / wall, "share_of_embree": rays / wall / library,
                            "embree_floor_seconds": rays / library,
                            "iterations": result.get("iterations"), "converged": result.get("converged")}
            run_floor_text = ""
            if label == "new" and result.get("counts", {}).get("rays", 0) > 0:
                mode = "to-the-end" if result["config"].get("V", 0) else "first-hit"
                seconds, line = run_floor(text, mode)
                entry["run_floor_seconds"] = seconds
                entry["run_floor"] = line
                run_floor_text = f"{seconds:11.1f}"
            print(f"{name:30} {label:5} {wall:8.1f} {cpu:7.1f} {peak:9.0f} {rays / 1e6:8.0f} "
                  f"{rays / wall / 1e6:9.1f} {rays / wall / library:9.2f} {rays / library:8.1f} "
                  f"{run_floor_text}", flush=True)
        if options.old:
            entry["same_result"] = comparable(texts["new"]) == comparable(texts["old"])
            print(f"{'':30} result files {'equal' if entry['same_result'] else 'DIFFER'}")
        if options.profile:
            shares = profile(os.path.join(options.new, "simulate"), args)
            entry["profile_percent_by_library"] = shares
            print(f"{'':30} profile: {shares}")
            if shares is not None:
                simgrid = shares.get("libsimgrid", 0.0) / 100 * entry["new"]["cpu_seconds"]
                entry["simgrid_cpu_seconds"] = simgrid
                line = f"{'':30} SimGrid's CPU time: {simgrid:.1f} s"
                if "run_floor_seconds" in entry:
                    floor = entry["run_floor_seconds"] + simgrid / 2
                    entry["floor_with_simgrid_seconds"] = floor
                    line += (f"; floor with SimGrid on two cores: {floor:.1f} s "
                             f"(the run takes {entry['new']['wall_seconds'] / floor:.2f} times it)")
                print(line)
        if options.simgrid_alone:
            binary = os.path.join(options.new, "simulate")
            host, cpu, peak, end, line = simgrid_alone(binary, args, os.path.join(
                os.path.dirname(os.path.dirname(binary)), "platforms", "ncube2.json"))
            same_end = end == json.loads(texts["new"])["simulated_seconds"]
            entry["simgrid_alone"] = {"host_seconds": host, "cpu_seconds": cpu, "peak_mib": peak,
                                      "ends_at_the_run_time": same_end, "replay": line}
            text = (f"{'':30} SimGrid alone on the run's messages: {host:.1f} s, {cpu:.1f} CPU s, "
                    f"{peak:.0f} MiB; ends at the run's simulated time: {'yes' if same_end else 'NO'}")
            if "run_floor_seconds" in entry:
                # SimGrid runs on one thread: the floor is never below its own time.
                floor = max(entry["run_floor_seconds"] + cpu / 2, cpu)
                entry["floor_with_simgrid_alone_seconds"] = floor
                text += (f"\n{'':30} floor with SimGrid alone on two cores: {floor:.1f} s (the run "
                         f"takes {entry['new']['wall_seconds'] / floor:.2f} times it)")
            print(text, flush=True)
        report["runs"][name] = entry
    print("* distinct rays: with V > 0 the program counts each ray once per share; floor: the "
          "distinct rays at Embree's own rate on the first shooter's rays; run floor: plain Embree "
          "on the run's own distinct shots (build/embree_floor)")
    report["load_average_at_end"] = os.getloadavg()[0]
    os.makedirs(os.path.dirname(OUT), exist_ok=True)
    # Runs measured before and not now stay in the file, with the date they were measured.
    stamp = time.strftime("%Y-%m-%d")
    for entry in report["runs"].values():
        entry["measured"] = stamp
    if os.path.exists(OUT):
        with open(OUT) as f:
            earlier = json.load(f).get("runs", {})
        report["runs"] = {**earlier, **report["runs"]}
    with open(OUT, "w") as f:
        json.dump(report, f, indent=1)
        f.write("\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
