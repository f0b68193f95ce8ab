#!/usr/bin/python3
"""Writes the machine table of docs/machines/README.md from the platform files themselves.

    /usr/bin/python3 docs/machines/index_table.py           # rewrite the table in README.md
    /usr/bin/python3 docs/machines/index_table.py --check   # exit 1 if README.md's table differs

The table sits between <!-- machine-table:begin --> and <!-- machine-table:end -->; every figure
in it is read from the SimGrid XML (a cluster's attributes and <prop>s, or a zone's hosts, links
and <prop>s), so it cannot drift from the files (tests/machines_platforms_test.sh runs --check).
"""

import argparse
import glob
import os
import re
import sys
import xml.etree.ElementTree as ET

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
README = os.path.join(HERE, "README.md")
BEGIN, END = "<!-- machine-table:begin -->", "<!-- machine-table:end -->"

# SimGrid's units as they appear in these files.
UNITS = {"f": 1.0, "kf": 1e3, "Mf": 1e6, "Gf": 1e9, "Bps": 1.0, "kBps": 1e3, "MBps": 1e6,
         "GBps": 1e9, "TBps": 1e12, "s": 1.0, "ms": 1e-3, "us": 1e-6, "ns": 1e-9}


def quantity(text):
    match = re.fullmatch(r"([0-9.eE+-]+)([A-Za-z]*)", text.strip())
    if not match or match.group(2) not in UNITS:
        raise SystemExit("index_table.py: cannot read the quantity %r" % text)
    return float(match.group(1)) * UNITS[match.group(2)]


def platform_files():
    files = [os.path.join(ROOT, "platforms", "ncube2.xml")]
    for path in sorted(glob.glob(os.path.join(ROOT, "platforms", "machines", "*.xml"))):
        if not re.search(r"-n\d+\.xml$", path):
            files.append(path)
    return files


def family(path):
    base = os.path.basename(path)[:-4]
    if base == "ncube2":
        return "`ncube2-d7.json` … `d13` (128 … 8,192)"
    sizes = sorted(int(re.search(r"-n(\d+)\.xml$", p).group(1)) for p in
                   glob.glob(os.path.join(os.path.dirname(path), base + "-n*.xml")))
    return ", ".join("{:,}".format(n) for n in sizes) if sizes else "—"


def page(path, text):
    match = re.search(r"(docs/(?:machines/)?[\w.-]+\.md)", text)
    if os.path.basename(path) == "ncube2.xml":
        return "../ncube2-sources.md"
    return os.path.relpath(os.path.join(ROOT, match.group(1)), HERE) if match else None


def describe(path):
    text = open(path, encoding="utf-8").read()
    # Comments are dropped first: SimGrid's reader takes a "--" inside one (platforms/ncube2.xml
    # has "--cfg" in a comment), which is not well-formed XML.
    root = ET.fromstring(re.sub(r"<!--.*?-->", "", text, flags=re.S))
    clusters, zones = root.findall("cluster"), root.findall("zone")
    if clusters:
        c = clusters[0]
        props = {p.get("id"): p.get("value") for p in c.findall("prop")}
        params = c.get("topo_parameters")
        dims = params.split(",") if c.get("topology") == "TORUS" else []
        if dims and set(dims) == {"2"}:
            topology = "hypercube, %d dimensions (`TORUS`)" % len(dims)
        elif dims:
            topology = "torus %s (`TORUS`)" % " x ".join(dims)
        else:
            topology = "fat tree `%s` (`%s`)" % (params, c.get("topology"))
        first, last = (int(v) for v in c.get("radical").split("-"))
        nodes = last - first + 1
        speed, bw, lat = quantity(c.get("speed")), quantity(c.get("bw")), quantity(c.get("lat"))
    else:
        z = zones[0]
        props = {p.get("id"): p.get("value") for p in z.findall("prop")}
        hosts = z.findall("host")
        nodes = len(hosts)
        links = [l for l in z.findall("link") if l.get("id").startswith("mesh-")]
        steps = {int(b) - int(a) for a, b in (l.get("id").split("-")[1:] for l in links)}
        width = max(steps)
        topology = "2-D mesh %d x %d, no wrap-around (`%s` zone)" % (width, nodes // width,
                                                                      z.get("routing"))
        speed = quantity(hosts[0].get("speed"))
        bw, lat = quantity(links[0].get("bandwidth")), quantity(links[0].get("latency"))
    return {
        "file": os.path.relpath(path, ROOT), "page": page(path, text), "topology": topology,
        "nodes": nodes, "speed": speed, "memory": float(props["node_memory"]), "bandwidth": bw,
        "latency": lat, "send": float(props["send_overhead"]),
        "receive": float(props["receive_overhead"]), "family": family(path),
    }


def si(value, unit):
    for factor, prefix in ((1e9, "G"), (1e6, "M"), (1e3, "k"), (1, "")):
        if value >= factor:
            return "%s %s%s" % (("%.3g" % (value / factor)), prefix, unit)
    return "%.3g %s" % (value, unit)


def mebibytes(value):
    return "%g MiB" % (value / 2 ** 20) if value < 2 ** 30 else "%g GiB" % (value / 2 ** 30)


def microseconds(value):
    return "%.3g µs" % (value * 1e6)


def table():
    rows = ["| machine | platform file | topology | nodes | larger family (nodes) | node speed | "
            "memory a node | link bandwidth (each way) | latency a hop | send / receive overhead |",
            "|---|---|---|--:|---|--:|--:|--:|--:|--:|"]
    for path in platform_files():
        d = describe(path)
        name = os.path.basename(path)[:-4]
        rows.append("| [%s](%s) | `%s` | %s | %d | %s | %s | %s | %s | %s | %s / %s |" % (
            name, d["page"], d["file"], d["topology"], d["nodes"], d["family"],
            si(d["speed"], "flop/s"), mebibytes(d["memory"]),
            si(d["bandwidth"], "B/s"), microseconds(d["latency"]), microseconds(d["send"]),
            microseconds(d["receive"])))
    return "\n".join(rows) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--check", action="store_true", help="fail if README.md's table differs")
    args = parser.parse_args()
    text = open(README, encoding="utf-8").read()
    if BEGIN not in text or END not in text:
        raise SystemExit("index_table.py: %s lacks the %s ... %s markers" % (README, BEGIN, END))
    head, rest = text.split(BEGIN, 1)
    _, tail = rest.split(END, 1)
    new = head + BEGIN + "\n" + table() + END + tail
    if args.check:
        if new != text:
            print("docs/machines/README.md: the machine table differs from the platform files "
                  "(run: /usr/bin/python3 docs/machines/index_table.py)", file=sys.stderr)
            return 1
        return 0
    with open(README, "w", encoding="utf-8", newline="\n") as f:
        f.write(new)
    return 0


if __name__ == "__main__":
    sys.exit(main())
