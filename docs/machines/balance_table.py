#!/usr/bin/python3
"""Where the balance moves: the machines at the paper's block size and at fine-grained messages.

    /usr/bin/python3 docs/machines/balance_table.py [--print]

For every machine of the library (platforms/ncube2.json and the 64-node files of
platforms/machines/), scene1 with brute force at three of Table 4's 64-node rows (R=64 V=0,
R=8 V=7, R=4 V=15), 3 iterations, with the paper's blocks of 100 points (--block-size 100, the
default) and with one point a message (--block-size 1). Writes, between
<!-- balance-table:begin --> and <!-- balance-table:end --> of docs/machines/README.md, each
machine's seconds per iteration, its factor of speed against the nCube2 at the same row and
block size, which row is fastest (whether visibility processors pay), and the shares of
message overhead and waiting at R=8 V=7 (node-seconds over all nodes). About a minute of CPU.
"""

import argparse
import json
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
README = os.path.join(HERE, "README.md")
BEGIN, END = "<!-- balance-table:begin -->", "<!-- balance-table:end -->"
SIMULATE = os.path.join(ROOT, "build", "simulate")
MACHINES = [("nCube2", "platforms/ncube2.json"),
            ("T800 network", "platforms/machines/transputer-t800.xml"),
            ("iPSC/860", "platforms/machines/ipsc860.xml"),
            ("Paragon (OSF/1)", "platforms/machines/paragon.xml"),
            ("Paragon (SUNMOS)", "platforms/machines/paragon-sunmos.xml"),
            ("CM-5", "platforms/machines/cm5.xml"),
            ("cluster of 2024", "platforms/machines/cluster-2024.xml")]
ROWS = [(64, 0), (8, 7), (4, 15)]
BLOCKS = [100, 1]
ITERATIONS = 3


def run(platform, r, v, block, out):
    """(seconds per iteration, overhead share, waiting share), or None when out of memory."""
    done = subprocess.run([SIMULATE, os.path.join(ROOT, "scenes", "scene1.json"), "--R", str(r),
                           "--V", str(v), "--iterations", str(ITERATIONS), "--block-size",
                           str(block), "--platform", os.path.join(ROOT, platform), "--json", out,
                           "--quiet"])
    if done.returncode == 3:
        return None
    if done.returncode != 0:
        raise SystemExit("balance_table.py: ./simulate failed on %s R=%d V=%d" % (platform, r, v))
    with open(out, encoding="utf-8") as f:
        result = json.load(f)
    nodes = result["nodes"]
    parts = [sum(n[k] for n in nodes) for k in ("compute_seconds", "overhead_seconds",
                                                  "waiting_seconds")]
    total = sum(parts)
    return result["seconds_per_iteration"], parts[1] / total, parts[2] / total


def measure():
    found = {}
    with tempfile.TemporaryDirectory() as work:
        out = os.path.join(work, "r.json")
        for name, platform in MACHINES:
            for block in BLOCKS:
                for r, v in ROWS:
                    found[name, block, r, v] = run(platform, r, v, block, out)
    return found


def seconds(x):
    return "%.4g" % x


def table(found):
    head = ("| machine | block size | " + " | ".join("R=%d V=%d (s)" % rv for rv in ROWS) +
            " | × nCube2 at R=8 V=7 | fastest row | overhead at R=8 V=7 | waiting at R=8 V=7 |")
    lines = [head, "|---|--:|" + "--:|" * len(ROWS) + "--:|---|--:|--:|"]
    for block in BLOCKS:
        for name, _ in MACHINES:
            cells = [found[name, block, r, v] for r, v in ROWS]
            shown = [seconds(c[0]) if c else "out of memory" for c in cells]
            ok = [(c[0], rv) for c, rv in zip(cells, ROWS) if c]
            best = min(ok)[1] if ok else None
            mid, ref = found[name, block, 8, 7], found["nCube2", block, 8, 7]
            factor = "%.4g" % (ref[0] / mid[0]) if mid and ref else "—"
            lines.append("| %s | %d | %s | %s | %s | %s | %s |" % (
                name, block, " | ".join(shown), factor,
                "R=%d V=%d" % best if best else "—",
                "%.1f %%" % (100 * mid[1]) if mid else "—",
                "%.1f %%" % (100 * mid[2]) if mid else "—"))
    return lines


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--print", action="store_true", help="print the table, write no page")
    args = parser.parse_args()
    lines = ["Written by `/usr/bin/python3 docs/machines/balance_table.py`: scene1, brute force, "
             "%d iterations, seconds per iteration (simulated)." % ITERATIONS, ""] + \
        table(measure())
    text = "\n".join(lines) + "\n"
    if args.print:
        sys.stdout.write(text)
        return 0
    with open(README, encoding="utf-8") as f:
        page = f.read()
    if BEGIN not in page or END not in page:
        raise SystemExit("balance_table.py: %s has no %s ... %s" % (README, BEGIN, END))
    head, rest = page.split(BEGIN, 1)
    _, tail = rest.split(END, 1)
    with open(README, "w", encoding="utf-8", newline="\n") as f:
        f.write(head + BEGIN + "\n" + text + END + tail)
    print("wrote the balance table of docs/machines/README.md")
    return 0


if __name__ == "__main__":
    sys.exit(main())
