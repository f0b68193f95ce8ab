#!/usr/bin/python3
"""Holds the simulator against a real run of its own work: the table of docs/machines/probe.md.

    /usr/bin/python3 docs/machines/prediction_table.py [--platform FILE] [--repeats N] [--print]

Without --platform, build/machine_probe first measures this computer into a temporary platform
file. Then, for each scene of SCENES, one-node runs (--R 1 --V 0) of N and of 2N iterations on
that platform, with the host's readable definitions alone on one thread (--reference-visibility
--threads 1): the prediction is the simulated seconds of iterations N+1 .. 2N (the difference
of the two runs), the measurement the host's CPU seconds of the same iterations (the difference
of the two processes' CPU time, each the least of N repeats: the least is the run least
disturbed by the other processes of a shared host). Differences, not whole runs, because a
process also starts, reads its scene, builds its elements and writes its result, which no
simulated node does. The table is written between <!-- prediction-table:begin --> and
<!-- prediction-table:end --> of docs/machines/probe.md (--print: to standard output only).
"""

import argparse
import json
import os
import re
import resource
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
PAGE = os.path.join(HERE, "probe.md")
BEGIN, END = "<!-- prediction-table:begin -->", "<!-- prediction-table:end -->"
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


def run(scene, iterations, platform, repeats, out, extra=()):
    """(simulated seconds, least CPU seconds of `repeats` processes, counts)."""
    least = None
    for _ in range(repeats):
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        subprocess.run([SIMULATE, os.path.join(ROOT, "scenes", scene + ".json"), "--R", "1",
                        "--V", "0", "--iterations", str(iterations), "--reference-visibility",
                        "--threads", "1", "--platform", platform, "--json", out, "--quiet"] + list(extra),
                       check=True)
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
        least = cpu if least is None else min(least, cpu)
    with open(out, encoding="utf-8") as f:
        result = json.load(f)
    return result["simulated_seconds"], least, result["counts"]


def measure(platform, repeats):
    rows = []
    with tempfile.TemporaryDirectory() as work:
        out = os.path.join(work, "result.json")
        for scene, n in SCENES:
            s1, c1, k1 = run(scene, n, platform, repeats, out)
            s2, c2, k2 = run(scene, 2 * n, platform, repeats, out)
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
        out = os.path.join(work, "result.json")
        for scene, n, extra in HEMICUBE_RUNS:
            extra = ["--form-factors", "hemicube"] + extra
            s1, c1, k1 = run(scene, n, platform, repeats, out, extra)
            s2, c2, k2 = run(scene, 2 * n, platform, repeats, out, extra)
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


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--platform", help="a probed platform file (default: probe now)")
    parser.add_argument("--repeats", type=int, default=3, help="processes a measurement (least)")
    parser.add_argument("--print", action="store_true", help="print the table, write no page")
    args = parser.parse_args()
    if not 1 <= args.repeats <= 100:
        parser.error("argument --repeats: from 1 to 100")
    for binary in (SIMULATE, PROBE):
        if not (os.path.isfile(binary) and os.access(binary, os.X_OK)):
            print("prediction_table.py: it runs %s, which is not built (cmake --build build -j2); "
                  "nothing written" % os.path.relpath(binary, ROOT), file=sys.stderr)
            return 2
    if args.platform and not os.path.isfile(args.platform):
        print("prediction_table.py: --platform %s: not a regular file; nothing written"
              % args.platform, file=sys.stderr)
        return 2
    with tempfile.TemporaryDirectory() as work:
        platform = args.platform
        if not platform:
            platform = os.path.join(work, "probed.xml")
            subprocess.run([PROBE, "--out", platform], check=True, stdout=subprocess.DEVNULL)
        rows = measure(platform, args.repeats)
        hemicube_rows = measure_hemicube(platform, args.repeats)
        with open("/proc/cpuinfo", encoding="utf-8") as f:
            cpu = next((l.split(":", 1)[1].strip() for l in f if l.startswith("model name")), "?")
        load = os.getloadavg()[0]
        heading = ("Measured on %s (load average %.1f on %d cores at the end) by "
                   "`/usr/bin/python3 docs/machines/prediction_table.py%s`."
                   % (cpu, load, os.cpu_count(), ("" if not args.platform else
                      " --platform " + os.path.relpath(args.platform, ROOT)) +
                      ("" if args.repeats == 3 else " --repeats %d" % args.repeats)))
        lines = table(rows, platform, heading) + hemicube_table(hemicube_rows)
    text = "\n".join(lines) + "\n"
    if args.print:
        sys.stdout.write(text)
        return 0
    with open(PAGE, encoding="utf-8") as f:
        page = f.read()
    if BEGIN not in page or END not in page:
        raise SystemExit("prediction_table.py: %s has no %s ... %s" % (PAGE, BEGIN, END))
    head, rest = page.split(BEGIN, 1)
    _, tail = rest.split(END, 1)
    with open(PAGE, "w", encoding="utf-8", newline="\n") as f:
        f.write(head + BEGIN + "\n" + text + END + tail)
    print("wrote the prediction table of docs/machines/probe.md")
    return 0


if __name__ == "__main__":
    sys.exit(main())
