#!/usr/bin/python3
"""Writes each machine page's simulated network table beside the published figures.

    /usr/bin/python3 docs/machines/network_tables.py           # rewrite the tables in the pages
    /usr/bin/python3 docs/machines/network_tables.py --check   # exit 1 if a table differs or a
                                                                # figure is out of its tolerance

For every machine of platforms/machines/published_network.json (its platform file, its page,
its published one-way time and bandwidth with source, confidence and tolerance), this runs
build/network_bench on the platform file and writes, between <!-- network-table:begin --> and
<!-- network-table:end --> of the page, the simulated one-way time and streaming bandwidth from
8 bytes to 1 MB (neighbours and the farthest pair) and a comparison with each published figure.
The simulated figure of a published one-way time is the ping-pong's half round trip of a
message of that size between node 0 and its nearest node; that of a published bandwidth is the
streaming bandwidth of the largest message (1 MB) between the same two nodes. It must lie
within the stated tolerance (relative) of the published figure.

A machine whose platform file or page is not in this tree is skipped (said on stderr). Without
published_network.json, --check still holds the nCube2's simulated table in
docs/ncube2-sources.md to the benchmark (the comparison below it is then not checked).
docs/network-benchmark.md describes the benchmark. Python 3 standard library only.
"""

import argparse
import json
import math
import os
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent.parent
PUBLISHED = ROOT / "platforms" / "machines" / "published_network.json"
BEGIN, END = "<!-- network-table:begin -->", "<!-- network-table:end -->"
# The nCube2's files, for --check when published_network.json is not in this tree.
NCUBE2 = {"ncube2": {"platform": "platforms/ncube2.xml", "page": "docs/ncube2-sources.md"}}
# Table rows: every third doubling from 8 bytes, and the largest size.
ROW_FACTOR = 8
FIGURES = [("one_way_latency", "one-way time of a message of {bytes} bytes between neighbours", "µs"),
           ("asymptotic_bandwidth", "bandwidth of long messages", "MB/s")]


class Problem(Exception):
    pass


def significant(value, digits=4):
    """`value` with `digits` significant digits, in fixed notation with thousands separators."""
    if value == 0:
        return "0"
    decimals = max(0, digits - 1 - int(math.floor(math.log10(abs(value)))))
    return "{:,.{}f}".format(value, decimals)


def percent(fraction):
    """A signed percentage to one decimal ("0.0 %" for less than 0.05 %, never "-0.0 %")."""
    text = "%+.1f %%" % (100 * fraction)
    return "0.0 %" if text in ("+0.0 %", "-0.0 %") else text


def run_benchmark(bench, platform):
    """The benchmark's JSON for `platform` (relative to the repository root)."""
    with tempfile.TemporaryDirectory() as folder:
        out = os.path.join(folder, "network.json")
        command = [str(bench), "--platform", platform, "--json", out, "--quiet",
                   "--cost-model", "platforms/cost_model.json"]
        done = subprocess.run(command, cwd=ROOT, capture_output=True, text=True)
        if done.returncode != 0:
            raise Problem("%s failed (exit %d): %s" % (" ".join(command), done.returncode,
                                                      done.stderr.strip()))
        with open(out) as f:
            return json.load(f)


def pair(result, name):
    return next(p for p in result["pairs"] if p["pair"] == name)


def simulated_part(result):
    """The paragraph and the table of simulated figures."""
    near, far = pair(result, "neighbours"), pair(result, "farthest")

    def route(p):
        return "node-%d and node-%d, %d link%s, %g µs of route latency" % (
            p["from"], p["to"], p["links"], "" if p["links"] == 1 else "s",
            float("%.6g" % (p["route_latency_seconds"] * 1e6)))

    lines = [
        "Simulated by `build/network_bench --platform %s` through the node programs' runtime "
        "(%g µs of send and %g µs of receive overhead a message, a header of %g bytes; "
        "`docs/network-benchmark.md`), written by `docs/machines/network_tables.py`. "
        "One-way time: half a ping-pong round trip; bandwidth: payload bytes per second of %d "
        "messages sent back to back. Neighbours: %s; farthest pair: %s." % (
            result["platform_file"], float("%.6g" % (result["send_overhead_seconds"] * 1e6)),
            float("%.6g" % (result["receive_overhead_seconds"] * 1e6)),
            result["message_header_bytes"], result["stream_messages"], route(near), route(far)),
        "",
        "| payload (bytes) | one-way, neighbours (µs) | one-way, farthest (µs) "
        "| bandwidth, neighbours (MB/s) | bandwidth, farthest (MB/s) |",
        "|--:|--:|--:|--:|--:|",
    ]
    sizes = [s["bytes"] for s in near["sizes"]]
    for i, size in enumerate(sizes):
        ratio = size / sizes[0]
        if not (abs(math.log(ratio, ROW_FACTOR) - round(math.log(ratio, ROW_FACTOR))) < 1e-9
                or i == len(sizes) - 1):
            continue
        n, f = near["sizes"][i], far["sizes"][i]
        lines.append("| %s | %s | %s | %s | %s |" % (
            "{:,}".format(int(size)), significant(n["one_way_seconds"] * 1e6),
            significant(f["one_way_seconds"] * 1e6),
            significant(n["stream_bandwidth_bytes_per_second"] / 1e6),
            significant(f["stream_bandwidth_bytes_per_second"] / 1e6)))
    return "\n".join(lines) + "\n"


def simulated_figure(result, key, figure):
    """The simulated counterpart of a published figure, in the table's unit, and its label."""
    near = pair(result, "neighbours")
    if key == "one_way_latency":
        size = figure.get("message_bytes", 8)
        for s in near["sizes"]:
            if s["bytes"] == size:
                return s["one_way_seconds"] * 1e6, ""
        raise Problem("no simulated one-way time of a %s-byte message" % size)
    largest = near["sizes"][-1]
    return largest["stream_bandwidth_bytes_per_second"] / 1e6, " (%s bytes, streamed)" % (
        "{:,}".format(int(largest["bytes"])))


def comparison_part(result, machine, entry):
    """The table of published figures beside the simulated ones; the figures out of tolerance."""
    lines = ["| published figure | published | simulated | difference | tolerance | confidence "
             "| source |", "|---|--:|--:|--:|--:|---|---|"]
    failures = []
    for key, label, unit in FIGURES:
        figure = entry.get(key)
        if figure is None:
            continue
        name = label.format(bytes=figure.get("message_bytes", 8))
        simulated, how = simulated_figure(result, key, figure)
        value = figure.get("value")
        if value is None:
            lines.append("| %s | not found | %s %s%s | | | | %s |" % (
                name, significant(simulated), unit, how, figure.get("note") or ""))
            continue
        published = value * (1e6 if unit == "µs" else 1e-6)
        difference = simulated / published - 1
        tolerance = figure["tolerance"]
        lines.append("| %s | %s %s | %s %s%s | %s | %g %% | %s | %s |" % (
            name, significant(published), unit, significant(simulated), unit, how,
            percent(difference), 100 * tolerance, figure.get("confidence") or "", figure["source"]))
        if abs(difference) > tolerance:
            failures.append("%s: %s, simulated %s %s against the published %s %s: %+.1f %%, "
                            "beyond the tolerance of %g %%" % (
                                machine, name, significant(simulated), unit,
                                significant(published), unit, 100 * difference, 100 * tolerance))
    return "\n".join(lines) + "\n", failures


def block_of(text, page):
    start, end = text.find(BEGIN), text.find(END)
    if start < 0 or end < start:
        raise Problem("%s: no %s ... %s markers" % (page, BEGIN, END))
    return start + len(BEGIN), end


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--check", action="store_true",
                        help="change nothing; exit 1 if a table differs or a figure is out of tolerance")
    parser.add_argument("--bench", default=str(ROOT / "build" / "network_bench"),
                        help="the network_bench binary (default: build/network_bench)")
    parser.add_argument("--published", default=str(PUBLISHED),
                        help="the published figures (default: platforms/machines/published_network.json)")
    args = parser.parse_args()

    if not (os.path.isfile(args.bench) and os.access(args.bench, os.X_OK)):
        print("network_tables.py: --bench %s: not a program (cmake --build build -j2 builds "
              "build/network_bench); nothing written" % args.bench, file=sys.stderr)
        return 2
    have_published = os.path.lexists(args.published)
    if have_published:
        # Through the input gate (analysis/ncube/input_file.py): a regular file within 1 MiB,
        # strict JSON, nesting bounded; a FIFO, a device or a folder refused at once.
        sys.path.insert(0, str(ROOT / "analysis"))
        from ncube import input_file
        try:
            machines = input_file.read_json(args.published, "published figures", 1 << 20)
            machines = machines["machines"] if isinstance(machines, dict) else None
            if not isinstance(machines, dict) or not all(
                    isinstance(e, dict) and isinstance(e.get("platform"), str) and
                    isinstance(e.get("page"), str) for e in machines.values()):
                raise input_file.InputFileError("%s: published figures: machines: not an object "
                                                "of machines with their platform and page"
                                                % args.published)
        except input_file.InputFileError as e:
            print("network_tables.py: %s; nothing written" % e, file=sys.stderr)
            return 2
    elif args.check:
        print("network_tables.py: SKIP published figures: %s is not in this tree; checking the "
              "nCube2's simulated table only" % os.path.relpath(args.published, ROOT), file=sys.stderr)
        machines = NCUBE2
    else:
        print("network_tables.py: %s not found: nothing written" % args.published, file=sys.stderr)
        return 2

    problems = []
    for machine, entry in machines.items():
        missing = [entry[k] for k in ("platform", "page") if not (ROOT / entry[k]).exists()]
        if missing:
            print("network_tables.py: SKIP %s: %s not in this tree" % (machine, ", ".join(missing)),
                  file=sys.stderr)
            continue
        page = ROOT / entry["page"]
        try:
            result = run_benchmark(os.path.abspath(args.bench), entry["platform"])
            block = simulated_part(result)
            failures = []
            if have_published:
                comparison, failures = comparison_part(result, machine, entry)
                block += "\n" + comparison
            text = page.read_text()
            start, end = block_of(text, entry["page"])
            wanted = "\n" + block
            if args.check:
                held = text[start:end]
                if held != wanted and not (not have_published and held.startswith(wanted)):
                    failures.append("%s: the table in %s is not what docs/machines/"
                                    "network_tables.py writes (run it)" % (machine, entry["page"]))
            elif text[start:end] != wanted:
                page.write_text(text[:start] + wanted + text[end:])
                print("network_tables.py: wrote %s" % entry["page"], file=sys.stderr)
            problems += failures
            if not failures:
                print("network_tables.py: %s: ok" % machine, file=sys.stderr)
        except Problem as e:
            problems.append(str(e))
    for problem in problems:
        print("network_tables.py: " + problem, file=sys.stderr)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
