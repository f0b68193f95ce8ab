#!/usr/bin/python3
"""Host cost of the simulator against the size of the simulated hypercube: for 64 to 8,192
nodes (platforms/ncube2.json and ncube2-d7.json .. ncube2-d13.json), one fixed scene and one
configuration per size, the host's wall time and peak memory (/usr/bin/time -v) per simulated
iteration. A benchmark, not a test: prints a Markdown table (docs/performance-scale.md).

    /usr/bin/python3 bench/hypercube_scale.py [--scene scene2.json] [--V 15] [--repeat 3]
                                              [--iterations 2] [--simulate ./simulate]

Configuration per size: V visibility processors per group (default 15) and R = nodes / (V+1)
radiosity processors, so that every node is used. Each size is run with --iterations 0 (load
the scene, plan the memory, build the platform and the node programs, choose the first
shooter) and with --iterations N; per iteration = (time(N) - time(0)) / N. Each run is
repeated and the minimum kept (the host may be shared). Peak memory is the maximum resident
set size of the N-iteration run.
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

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def platform_file(dimension):
    name = "ncube2.json" if dimension == 6 else "ncube2-d%d.json" % dimension
    return os.path.join(ROOT, "platforms", name)


def timed_run(command):
    """(wall seconds, peak resident kilobytes) of one run."""
    with tempfile.NamedTemporaryFile(mode="r", suffix=".time") as report:
        subprocess.run(["/usr/bin/time", "-v", "-o", report.name] + command, check=True,
                       stdout=subprocess.DEVNULL)
        text = report.read()
    wall = re.search(r"Elapsed \(wall clock\) time \(h:mm:ss or m:ss\): (\S+)", text).group(1)
    seconds = 0.0
    for part in wall.split(":"):
        seconds = seconds * 60.0 + float(part)
    peak = int(re.search(r"Maximum resident set size \(kbytes\): (\d+)", text).group(1))
    return seconds, peak


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--scene", default="scene2.json")
    parser.add_argument("--V", type=int, default=15)
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--iterations", type=int, default=2)
    parser.add_argument("--dimensions", default="6,7,8,9,10,11,12,13")
    parser.add_argument("--simulate", default=os.path.join(ROOT, "simulate"))
    args = parser.parse_args()
    print("scene %s, V = %d, R = nodes / %d, %d iterations, minimum of %d runs"
          % (args.scene, args.V, args.V + 1, args.iterations, args.repeat))
    print()
    print("| nodes | R | V | host s, setup | host s per iteration | peak host MB "
          "| simulated s per iteration |")
    print("|---:|---:|---:|---:|---:|---:|---:|")
    with tempfile.TemporaryDirectory() as work:
        out = os.path.join(work, "result.json")
        for d in (int(x) for x in args.dimensions.split(",")):
            nodes = 1 << d
            r = nodes // (args.V + 1)
            base = [args.simulate, args.scene, "--R", str(r), "--V", str(args.V),
                    "--platform", platform_file(d), "--quiet"]
            setup = min(timed_run(base + ["--iterations", "0"])[0] for _ in range(args.repeat))
            runs = [timed_run(base + ["--iterations", str(args.iterations), "--json", out])
                    for _ in range(args.repeat)]
            total = min(seconds for seconds, _ in runs)
            peak = max(kb for _, kb in runs)
            with open(out, encoding="utf-8") as f:
                simulated = json.load(f)["simulated_seconds"] / args.iterations
            print("| %d | %d | %d | %.2f | %.2f | %.0f | %.3f |"
                  % (nodes, r, args.V, setup, (total - setup) / args.iterations, peak / 1024.0,
                     simulated), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
