#!/usr/bin/python3
"""Which configurations of a scene fit in the nodes' memory: for each visibility-processor
count V, the most radiosity processors R the machine has room for, R = floor(nodes / (V + 1)),
with the largest modeled bytes of a radiosity and of a visibility processor (the simulator's
own memory plan, src/nodes/memory_plan.cpp) against the node memory. Prints a Markdown table.

    /usr/bin/python3 bench/memory_fit.py [--scene scene4.json] [--platform platforms/ncube2.json]
                                          [--simulate ./simulate] [--V 0,1,2,...]

Runs `simulate --iterations 0 --unlimited-memory` once per row (nothing is shot; about 2 s
each for scene4, most of it loading the scene).
"""

import sys  # noqa: E402
from pathlib import Path  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "analysis"))
from ncube.interpreter import use_project_python  # noqa: E402

use_project_python()   # Debian's /usr/bin/python3 (README.md, "Use")

import argparse
import json
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--scene", default="scene4.json")
    parser.add_argument("--platform", default=os.path.join(ROOT, "platforms", "ncube2.json"))
    parser.add_argument("--simulate", default=os.path.join(ROOT, "simulate"))
    parser.add_argument("--V", default="0,1,2,3,4,5,6,7,8,9,11,15,31,63",
                        help="comma-separated visibility-processor counts")
    args = parser.parse_args()
    with open(args.platform, encoding="utf-8") as f:
        parameters = json.load(f)["parameters"]
    nodes = 1 << int(parameters["dimension"]["value"])
    capacity = parameters["node_memory"]["value"]
    print("| R | V | nodes | radiosity processor, bytes | visibility processor, bytes | fits |")
    print("|---:|---:|---:|---:|---:|:---|")
    with tempfile.TemporaryDirectory() as work:
        out = os.path.join(work, "result.json")
        for v in (int(x) for x in args.V.split(",")):
            r = nodes // (v + 1)
            if r < 1:
                continue
            subprocess.run([args.simulate, args.scene, "--R", str(r), "--V", str(v),
                            "--platform", args.platform, "--iterations", "0",
                            "--unlimited-memory", "--json", out, "--quiet"], check=True)
            with open(out, encoding="utf-8") as f:
                result = json.load(f)
            most = {"radiosity": 0.0, "visibility": 0.0}
            for node in result["nodes"]:
                most[node["role"]] = max(most[node["role"]], node["peak_memory_bytes"])
            over = [role for role, b in most.items() if b > capacity]
            verdict = "yes" if not over else "no: " + " and ".join(
                "%s processor %+.0f KB" % (role, (most[role] - capacity) / 1024) for role in over)
            vp = "{:,.0f}".format(most["visibility"]) if v > 0 else "-"
            print("| %d | %d | %d | %s | %s | %s |" % (r, v, r * (v + 1),
                                                      "{:,.0f}".format(most["radiosity"]), vp,
                                                      verdict))
    return 0


if __name__ == "__main__":
    sys.exit(main())
