#!/usr/bin/python3
"""Holds the simulator against a real run of its own work: the tables of docs/machines/probe.md.

    /usr/bin/python3 docs/machines/prediction_table.py [--runs K] [--repeats N] [--platform FILE]
                                                       [--print] [--no-page] [--regenerate]

A run: without --platform, build/machine_probe first measures this computer into a temporary
platform file. Then, for each scene of SCENES, one-node runs (--R 1 --V 0) of N and of 2N
iterations on that platform, with the host's readable definitions alone on one thread
(--reference-visibility --threads 1): the prediction is the simulated seconds of iterations
N+1 .. 2N (the difference of the two runs), the measurement the host's CPU seconds of the same
iterations (the difference of the two processes' CPU time, each the least of N repeats: the
least is the run least disturbed by the other processes of a shared host; the two processes'
repeats alternate, so that one disturbance falls on one round of both). Differences, not
whole runs, because a process also starts, reads its scene, builds its elements and writes its
result, which no simulated node does. After the table a second probe measures the host again
(not used for the prediction): the record keeps its rates, and the page gives how far the host's
own speed moved within each run.

Each of the K runs (default 5; --time-cap S starts none that would end past S seconds) is appended as one record to
docs/machines/prediction_records.jsonl (docs/machines/prediction_records.py), and the page's
opening and tables (between its prediction-opening and prediction-table markers) are made
again from all the records (--no-page: printed only). --print: one run's table to standard
output, no record. --regenerate: no run, the page from the records.
"""

import argparse
import datetime
import hashlib
import json
import os
import re
import resource
import socket
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(ROOT, "analysis"))
import prediction_records  # noqa: E402  (beside this script)
from ncube import output_file  # noqa: E402
PAGE = os.path.join(HERE, "probe.md")
BEGIN, END = "<!-- prediction-table:begin -->", "<!-- prediction-table:end -->"
OPEN_BEGIN, OPEN_END = "<!-- prediction-opening:begin -->", "<!-- prediction-opening:end -->"
SIMULATE = os.path.join(ROOT, "build", "simulate")
PROBE = os.path.join(ROOT, "build", "machine_probe")
# The bound, stated before measuring: the prediction holds within it.
TOLERANCE = 0.10
# (scene, N): N iterations first, then 2N; chosen so that the timed iterations take about a
# second or more of host time (scene2's first iteration alone takes several).
SCENES = [("cornell-box", 40), ("scene0", 20), ("scene1", 3), ("scene2", 1)]
# The hemicube (--form-factors hemicube) on three scenes, (scene, N, its options): the same
# measurement, with the same 10 % as its goal, fixed before measuring (the request names the
# ray-traced method's bound; the hemicube's rates were measured after it). N chosen so that
# the timed iterations take about 0.5 s or more of host time where the scene allows: scene0's
# run ends before its 140th iteration (no energy left to shoot), so 61 to 120, about 0.25 s.
HEMICUBE_RUNS = [("cornell-box", 40, ["--hemicube-placement", "elements"]),
                 ("scene0", 60, ["--hemicube-resolution", "400"]),
                 ("scene1", 200, [])]


def run_pair(scene, n, platform, repeats, work, extra=()):
    """The runs of n and of 2n iterations, [(simulated seconds, least CPU seconds of `repeats`
    processes, counts)] for each, their processes alternating (n, 2n, n, 2n, ...): a disturbance
    of a few seconds falls on one round of both, which their least leaves out, rather than on
    every repeat of one of them (which made the difference up to 3 times too small)."""
    least, out = {}, {}
    for _ in range(repeats):
        for iterations in (n, 2 * n):
            out[iterations] = os.path.join(work, "result-%d.json" % iterations)
            before = resource.getrusage(resource.RUSAGE_CHILDREN)
            subprocess.run([SIMULATE, os.path.join(ROOT, "scenes", scene + ".json"), "--R", "1",
                            "--V", "0", "--iterations", str(iterations), "--reference-visibility",
                            "--threads", "1", "--platform", platform, "--json", out[iterations],
                            "--quiet"] + list(extra), check=True)
            after = resource.getrusage(resource.RUSAGE_CHILDREN)
            cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
            least[iterations] = min(least.get(iterations, cpu), cpu)
    runs = []
    for iterations in (n, 2 * n):
        with open(out[iterations], encoding="utf-8") as f:
            result = json.load(f)
        runs.append((result["simulated_seconds"], least[iterations], result["counts"]))
    return runs


def measure(platform, repeats):
    rows = []
    with tempfile.TemporaryDirectory() as work:
        for scene, n in SCENES:
            (s1, c1, k1), (s2, c2, k2) = run_pair(scene, n, platform, repeats, work)
            tests = k2["ray_patch_tests"] - k1["ray_patch_tests"]
            rays = k2["rays"] - k1["rays"]
            crossings = k2["plane_crossings"] - k1["plane_crossings"]
            rows.append({"scene": scene, "n": n, "simulated": s2 - s1, "host": c2 - c1, "tests": tests,
                         "startup": c1 - s1, "tests_per_ray": tests / rays if rays else 0,
                         "crossing_share": crossings / tests if tests else 0})
    return rows


def hemicube_kind_flops(counts, costs, kinds):
    """Counted flops of `counts` whose cost-model parameter is one of `kinds`' counters."""
    return sum(costs[KIND_COUNTERS[c]] * counts.get(c, 0) for c in kinds)


# The hemicube's counters by kind (src/machine/work_kinds.h), with their cost parameters.
RASTER = ["hemicube_rows_scanned", "hemicube_depth_tests", "hemicube_cells_read"]
PROJECTION = ["hemicube_vertices_transformed", "hemicube_polygons_set_up", "hemicube_clip_tests",
              "hemicube_clip_cuts", "hemicube_vertices_projected", "hemicube_polygons_scanned"]
KIND_COUNTERS = {"hemicube_rows_scanned": "flops_per_hemicube_row_scanned",
                 "hemicube_depth_tests": "flops_per_hemicube_depth_test",
                 "hemicube_cells_read": "flops_per_hemicube_cell_read",
                 "hemicube_vertices_transformed": "flops_per_hemicube_vertex_transformed",
                 "hemicube_polygons_set_up": "flops_per_hemicube_polygon_set_up",
                 "hemicube_clip_tests": "flops_per_hemicube_clip_test",
                 "hemicube_clip_cuts": "flops_per_hemicube_clip_cut",
                 "hemicube_vertices_projected": "flops_per_hemicube_vertex_projected",
                 "hemicube_polygons_scanned": "flops_per_hemicube_polygon_scanned"}


def measure_hemicube(platform, repeats):
    with open(os.path.join(ROOT, "platforms", "cost_model.json"), encoding="utf-8") as f:
        model = json.load(f)
    costs = {k: v["value"] for k, v in model["parameters"].items()}
    rows = []
    with tempfile.TemporaryDirectory() as work:
        for scene, n, extra in HEMICUBE_RUNS:
            extra = ["--form-factors", "hemicube"] + extra
            (s1, c1, k1), (s2, c2, k2) = run_pair(scene, n, platform, repeats, work, extra)
            diff = {c: k2.get(c, 0) - k1.get(c, 0) for c in RASTER + PROJECTION}
            raster = hemicube_kind_flops(diff, costs, RASTER)
            projection = hemicube_kind_flops(diff, costs, PROJECTION)
            rows.append({"scene": scene, "n": n, "options": " ".join(extra[2:]) or "(default)",
                         "simulated": s2 - s1, "host": c2 - c1,
                         "raster_share": raster / (raster + projection) if raster + projection else 0})
    return rows


def hemicube_table(rows):
    lines = ["", "The hemicube (`--form-factors hemicube`), the same measurement; its goal, fixed "
             "before measuring, the same %d %%:" % round(TOLERANCE * 100), "",
             "| scene | options | iterations timed | raster flops of the hemicube's | simulated s | "
             "host CPU s | prediction | within %d %% |" % round(TOLERANCE * 100),
             "|---|---|--:|--:|--:|--:|--:|:-:|"]
    for r in rows:
        error = r["simulated"] / r["host"] - 1
        lines.append("| %s | %s | %d to %d | %.0f %% | %.4g | %.4g | %+.1f %% | %s |" % (
            r["scene"], r["options"].replace("--", "`--", 1) + "`" if r["options"] != "(default)"
            else "(default)", r["n"] + 1, 2 * r["n"], 100 * r["raster_share"], r["simulated"],
            r["host"], 100 * error, "yes" if abs(error) <= TOLERANCE else "**no**"))
    return lines


def rates(platform):
    """The platform's rates as its <prop>s give them (for the table's heading)."""
    with open(platform, encoding="utf-8") as f:
        text = f.read()
    found = dict(re.findall(r'<prop id="(\w+_speed)" value="([^"]+)"', text))
    return ", ".join("`%s` %.4g flop/s" % (k, float(v)) for k, v in found.items())


def table(rows, platform, heading):
    lines = [heading, "",
             "Rates: %s. Tolerance, stated before measuring: %d %%." % (rates(platform),
                                                                      round(TOLERANCE * 100)),
             "",
             "| scene | iterations timed | ray-patch tests a ray | tests that cross the plane | "
             "simulated s | host CPU s | prediction | within %d %% | host − simulated a test |"
             % round(TOLERANCE * 100),
             "|---|--:|--:|--:|--:|--:|--:|:-:|--:|"]
    for r in rows:
        error = r["simulated"] / r["host"] - 1
        timed = ("%d" % (r["n"] + 1) if r["n"] == 1 else "%d to %d" % (r["n"] + 1, 2 * r["n"]))
        lines.append("| %s | %s | %.0f | %.0f %% | %.4g | %.4g | %+.1f %% | %s | %+.2f ns |" % (
            r["scene"], timed, r["tests_per_ray"], 100 * r["crossing_share"],
            r["simulated"], r["host"], 100 * error, "yes" if abs(error) <= TOLERANCE else "**no**",
            1e9 * (r["host"] - r["simulated"]) / r["tests"] if r["tests"] else 0.0))
    return lines


def machine():
    """(CPU model, a short hash of the machine's id) for a record: the id names the machine
    without publishing it (/etc/machine-id, else the host name)."""
    with open("/proc/cpuinfo", encoding="utf-8") as f:
        cpu = next((l.split(":", 1)[1].strip() for l in f if l.startswith("model name")), "?")
    ident = ""
    for path in ("/etc/machine-id", "/var/lib/dbus/machine-id"):
        try:
            with open(path, encoding="utf-8") as f:
                ident = f.read().strip()
            break
        except OSError:
            pass
    ident = ident or "host:" + socket.gethostname()
    return cpu, hashlib.sha256(ident.encode()).hexdigest()[:8]


def commit():
    """The version the probe binary was built from (its --version: the commit, "-dirty" when
    built from a changed tree), not the checkout's: --build may name another build."""
    try:
        out = subprocess.run([PROBE, "--version"], check=True, capture_output=True,
                             text=True).stdout.split()
        return out[-1] if out else "?"
    except (OSError, subprocess.CalledProcessError):
        return "?"


def platform_rates(platform):
    with open(platform, encoding="utf-8") as f:
        text = f.read()
    return {k: float(v) for k, v in re.findall(r'<prop id="(\w+_speed)" value="([^"]+)"', text)}


# build/machine_probe's exit 4: a fit gave no rate, the host too disturbed to measure (its
# --help). Probed again, up to this many times in all, as the threat model's cells do
# (tests/robustness/threat_cases.py).
PROBE_ATTEMPTS = 3
PROBE_DISTURBED = 4


def probe(out):
    """Probes this computer into `out`: True when measured, False when the host stayed too
    disturbed PROBE_ATTEMPTS times; any other failure ends the script with one line."""
    for _ in range(PROBE_ATTEMPTS):
        done = subprocess.run([PROBE, "--out", out], stdout=subprocess.DEVNULL,
                              stderr=subprocess.PIPE, text=True)
        if done.returncode == 0:
            return True
        if done.returncode != PROBE_DISTURBED:
            said = [line for line in done.stderr.splitlines() if line.strip()]
            raise SystemExit("prediction_table.py: build/machine_probe failed (exit %d): %s"
                             % (done.returncode, said[-1] if said else "no message"))
    return False


def one_run(args, work, index):
    """One whole prediction (a fresh probe unless --platform, then the table): its record, or
    (None, why) when the host stayed too disturbed to probe first."""
    load_before = [round(x, 2) for x in os.getloadavg()]
    started = time.time()
    platform = args.platform
    probe_seconds = 0.0
    if not platform:
        platform = os.path.join(work, "probed-%d.xml" % index)
        t = time.time()
        if not probe(platform):
            return None, ["prediction run %d: not made: the host was too disturbed to probe "
                          "(%d attempts)" % (index + 1, PROBE_ATTEMPTS)]
        probe_seconds = time.time() - t
    rows = measure(platform, args.repeats)
    hemicube_rows = measure_hemicube(platform, args.repeats)
    # The host probed again after the table (not used for the prediction): how far the host's
    # own speed moved within the run, which neither the load average nor a thread's CPU time
    # shows on a guest that reports no steal time (probe.md, "A quiet guest").
    rates_after = None
    if not args.platform:
        after = os.path.join(work, "probed-%d-after.xml" % index)
        # Too disturbed to probe again: the record has no second probe (as the earliest).
        rates_after = platform_rates(after) if probe(after) else None
    cpu, ident = machine()
    record = {
        "date": datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%dT%H:%M:%SZ"),
        "cpu": cpu, "machine": ident, "cores": os.cpu_count(), "commit": commit(),
        "repeats": args.repeats, "probed": not args.platform,
        "probe_allocator": prediction_records.PROBE_ALLOCATOR,
        "measurement": prediction_records.MEASUREMENT,
        "load_before": load_before, "load_after": [round(x, 2) for x in os.getloadavg()],
        "wall_seconds": round(time.time() - started, 1), "probe_wall_seconds": round(probe_seconds, 1),
        "rates": platform_rates(platform),
        **({"rates_after": rates_after} if rates_after else {}),
        "rows": [{"scene": r["scene"], "kind": "ray-traced", "options": "",
                  "simulated": r["simulated"], "host": r["host"],
                  "tests_per_ray": round(r["tests_per_ray"], 2),
                  "crossing_share": round(r["crossing_share"], 4),
                  "host_minus_simulated_ns_a_test":
                      round(1e9 * (r["host"] - r["simulated"]) / r["tests"], 4) if r["tests"] else 0.0}
                 for r in rows] +
                [{"scene": r["scene"], "kind": "hemicube", "options": r["options"],
                  "simulated": r["simulated"], "host": r["host"],
                  "raster_share": round(r["raster_share"], 4)} for r in hemicube_rows]}
    lines = table(rows, platform, "Run %d: %s, load average %.1f before, %.1f after." % (
        index + 1, record["date"], load_before[0], record["load_after"][0])) + hemicube_table(hemicube_rows)
    return record, lines


def main(argv=None, default_runs=5):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--platform", help="a probed platform file (default: probe now, each run)")
    parser.add_argument("--repeats", type=int, default=3, help="processes a measurement (least)")
    parser.add_argument("--print", action="store_true",
                        help="one run's table to standard output; no record, no page")
    parser.add_argument("--runs", type=int, default=default_runs,
                        help="whole predictions (probe, then the table), each recorded (default %d)"
                        % default_runs)
    parser.add_argument("--time-cap", type=float, default=0,
                        help="seconds: start no run that the longest run so far would take past it")
    parser.add_argument("--records", default=prediction_records.RECORDS,
                        help="the records file each run is appended to (default %s)"
                        % os.path.relpath(prediction_records.RECORDS, ROOT))
    parser.add_argument("--no-page", action="store_true",
                        help="record the runs and print the summary, leave the pages alone "
                        "(before committing records, --regenerate: analysis/machines.md's "
                        "opening follows them)")
    parser.add_argument("--regenerate", action="store_true",
                        help="run nothing: the page's tables from the records file")
    parser.add_argument("--build", default=os.path.join(ROOT, "build"),
                        help="the folder of simulate and machine_probe (default build/)")
    args = parser.parse_args(argv)
    global SIMULATE, PROBE
    SIMULATE, PROBE = os.path.join(args.build, "simulate"), os.path.join(args.build, "machine_probe")
    if not 1 <= args.repeats <= 100 or not 0 <= args.runs <= 1000:
        parser.error("--repeats must be from 1 to 100, --runs from 0 to 1000")
    if args.time_cap < 0 or args.time_cap != args.time_cap or args.time_cap == float("inf"):
        parser.error("argument --time-cap: seconds, 0 or more (0: no cap)")
    if not args.regenerate:
        for binary in (SIMULATE, PROBE):
            if not (os.path.isfile(binary) and os.access(binary, os.X_OK)):
                print("prediction_table.py: it runs %s, which is not built (cmake --build build "
                      "-j2); nothing written" % os.path.relpath(binary, ROOT), file=sys.stderr)
                return 2
        if args.platform and not os.path.isfile(args.platform):
            print("prediction_table.py: --platform %s: not a regular file; nothing written"
                  % args.platform, file=sys.stderr)
            return 2
    if not args.regenerate:
        with tempfile.TemporaryDirectory() as work:
            if args.print:
                record, lines = one_run(args, work, 0)
                sys.stdout.write("\n".join(lines) + "\n")
                return 0 if record else 4
            started, longest = time.time(), 0.0
            for index in range(args.runs):
                if args.time_cap and index and time.time() - started + longest > args.time_cap:
                    print("prediction runs: stopped after %d of %d runs (the time cap, %.0f s)"
                          % (index, args.runs, args.time_cap), flush=True)
                    break
                t = time.time()
                record, lines = one_run(args, work, index)
                longest = max(longest, time.time() - t)
                if record is None:
                    print(lines[0], flush=True)
                    continue
                prediction_records.append(args.records, record)
                sys.stdout.write("\n".join(lines) + "\n\nrecord: " + json.dumps(record, sort_keys=True)
                                 + "\n\n")
                sys.stdout.flush()
    records = prediction_records.load(args.records)
    text = prediction_records.section(records, TOLERANCE)
    sys.stdout.write(prediction_records.opening(records, TOLERANCE) + "\n" + text)
    if args.no_page or not records:
        return 0
    with open(PAGE, encoding="utf-8") as f:
        page = f.read()
    if BEGIN not in page or END not in page:
        raise SystemExit("prediction_table.py: %s has no %s ... %s" % (PAGE, BEGIN, END))
    head, rest = page.split(BEGIN, 1)
    _, tail = rest.split(END, 1)
    page = head + BEGIN + "\n" + text + END + tail
    if OPEN_BEGIN in page and OPEN_END in page:
        head, rest = page.split(OPEN_BEGIN, 1)
        _, tail = rest.split(OPEN_END, 1)
        page = (head + OPEN_BEGIN + "\n" + prediction_records.opening(records, TOLERANCE) + OPEN_END
                + tail)
    output_file.write(PAGE, page)
    # analysis/machines.md's conclusions on the probed cluster carry the records' spread: its
    # opening follows them (from its own tables and these records, without results).
    if os.path.abspath(args.records) == os.path.abspath(prediction_records.RECORDS):
        subprocess.run([sys.executable, os.path.join(ROOT, "analysis", "openings.py"),
                        os.path.join(ROOT, "analysis", "machines.md")], check=True)
    print("wrote the prediction tables of docs/machines/probe.md from %d records" % len(records))
    return 0


if __name__ == "__main__":
    sys.exit(main())
