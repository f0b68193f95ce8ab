#!/usr/bin/python3
"""Writes the machine library's SimGrid platform files, platforms/machines/*.xml.

    /usr/bin/python3 platforms/machines/generate.py [--out DIR]

Each machine below is one entry: its figures (each with its source and confidence in
docs/machines/<page>.md) and how its network is built. Every machine has a 64-node file
<name>.xml; a machine that was built larger also has its family <name>-n<nodes>.xml, with
every figure of the 64-node file and only the network scaled (as platforms/ncube2-d7.json ..
d13 are for the nCube2). tests/machines_platforms_test.sh checks that the committed files are
exactly what this script writes, so a figure is changed here and nowhere else.

Conventions (docs/platforms.md): node k is the host node-k; node speed, the rates per kind of
work a machine gives ("rates", src/machine/work_kinds.h), node_memory, send_overhead and
receive_overhead are the same on every node; SimGrid's own cluster
topologies are used where the machine's network is one of them (TORUS, FAT_TREE); the
Paragon's mesh, which has no wrap-around links, is a Dijkstra zone of one router per node.
"""

import argparse
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))

# The network model of every file: CM02 without cross traffic and with fair sharing, as
# for the nCube2 (docs/model.md): a message of S bytes over links l_1..l_h takes
# sum(latency) + S / min(bandwidth).
CONFIG = """  <config>
    <prop id="network/model" value="CM02"/>
    <prop id="network/crosstraffic" value="0"/>
    <prop id="network/solver" value="fairbottleneck"/>
  </config>
"""

MACHINES = [
    {
        "name": "transputer-t800",
        "page": "docs/machines/transputer-t800.md",
        "title": "INMOS T800 transputer network (20 MHz T800, four 20 Mbit/s links a node)",
        "speed": 1.5e6,
        "memory": 2 * 1024 * 1024,
        "bandwidth": 1.74e6,
        "latency": 20e-6,
        "send_overhead": 10e-6,
        "receive_overhead": 10e-6,
        "network": ("torus", (8, 8)),
        "network_doc": "a 2-D torus of 8 x 8: each node's four links go to its four neighbours",
        # Figures no readable source gives (docs/machines/<page>.md says why each is chosen).
        "assumed": ["link_bandwidth", "hop_latency", "send_overhead", "receive_overhead"],
        "family": [(128, (16, 8)), (256, (16, 16)), (512, (32, 16)), (1024, (32, 32))],
    },
    {
        "name": "ipsc860",
        "page": "docs/machines/ipsc860.md",
        "title": "Intel iPSC/860 (40 MHz i860 XR nodes, Direct-Connect hypercube)",
        "speed": 8e6,
        "memory": 8 * 1024 * 1024,
        "bandwidth": 2.5e6,
        "latency": 1e-6,
        "send_overhead": 33e-6,
        "receive_overhead": 33e-6,
        "network": ("torus", (2,) * 6),
        "network_doc": "a 6-dimensional binary hypercube routed dimension by dimension "
                       "(e-cube), written as a TORUS of extent 2 in 6 dimensions",
        "assumed": ["node_speed", "hop_latency", "send_overhead", "receive_overhead"],
        "family": [(128, (2,) * 7)],
    },
    {
        "name": "paragon",
        "page": "docs/machines/paragon.md",
        "title": "Intel Paragon XP/S under OSF/1 AD and NX (50 MHz i860 XP nodes, 2-D mesh of "
                 "routing chips)",
        "speed": 10e6,
        # 16 MB less OSF/1 AD's 8 MB, plus back the 768 KB reserve every machine is charged
        # (node_reserve_bytes): the program has the 8 MB OSF/1 leaves it.
        "memory": 16 * 1024 * 1024 - 8 * 1024 * 1024 + 768 * 1024,
        "bandwidth": 32.5e6,
        "latency": 0.04e-6,
        "send_overhead": 50e-6,
        "receive_overhead": 50e-6,
        "network": ("mesh", (8, 8)),
        "network_doc": "a 2-D mesh of 8 x 8 routing chips without wrap-around links, one node "
                       "on each; shortest paths (Dijkstra)",
        "assumed": ["node_speed", "hop_latency"],
        "family": [(128, (16, 8)), (256, (16, 16)), (512, (16, 32)), (1024, (16, 64))],
    },
    {
        # The variant: the same machine under SUNMOS (docs/machines/paragon-sunmos.md).
        "name": "paragon-sunmos",
        "page": "docs/machines/paragon-sunmos.md",
        "title": "Intel Paragon XP/S under SUNMOS (50 MHz i860 XP nodes, 2-D mesh of routing "
                 "chips)",
        "speed": 10e6,
        "memory": 16 * 1024 * 1024,
        "bandwidth": 175e6,
        "latency": 0.04e-6,
        "send_overhead": 35e-6,
        "receive_overhead": 35e-6,
        "network": ("mesh", (8, 8)),
        "network_doc": "a 2-D mesh of 8 x 8 routing chips without wrap-around links, one node "
                       "on each; shortest paths (Dijkstra)",
        "assumed": ["node_speed", "hop_latency"],
        "family": [],
    },
    {
        "name": "cm5",
        "page": "docs/machines/cm5.md",
        "title": "Thinking Machines CM-5 (32 MHz SPARC nodes, their vector units unused by "
                 "compiled scalar C; CMMD on the fat-tree data network)",
        "speed": 5e6,
        "memory": 32 * 1024 * 1024,
        "bandwidth": 8.06e6,
        "latency": 1e-6,
        "send_overhead": 42.6e-6,
        "receive_overhead": 42.6e-6,
        "network": ("fat_tree", ((4, 4, 4), (2, 2, 2))),
        "network_doc": "a 4-ary fat tree of 3 levels: 2 up-links a node and a switch, each "
                       "at CMMD's 8.06 MB/s (the wire's 10 MB/s less CMMD's copy), so twice "
                       "that a node into its group of 4, once into its group of 16 and half "
                       "beyond",
        "assumed": ["node_memory", "hop_latency"],
        "family": [(128, ((4, 4, 4, 2), (2, 2, 2, 4))), (256, ((4, 4, 4, 4), (2, 2, 2, 4))),
                   (512, ((4, 4, 4, 4, 2), (2, 2, 2, 4, 4))),
                   (1024, ((4, 4, 4, 4, 4), (2, 2, 2, 4, 4)))],
    },
    {
        "name": "cluster-2024",
        "page": "docs/machines/cluster-2024.md",
        "title": "A 64-node cluster of today (one process a node on one core of the AMD EPYC "
                 "host this project is built on, its rates measured by build/machine_probe; "
                 "InfiniBand HDR 200 Gb/s fat tree)",
        # Measured on this project's build host ("AMD EPYC", 2.6 GHz, 1 MB L2 a core) by
        # build/machine_probe --repeats 15 on 2026-11-28 02:11 UTC (load average 5 on 2
        # cores), rounded to 3 digits: test_speed, ray_speed and blocked_ray_speed the relative
        # least squares fit over the probe's 8 loop runs (root mean square residual 2.1 %, runs
        # within -2.9 to +4.7 %), arithmetic_speed and edge_term_speed the gather's over its 8
        # (4.1 %, -6.0 to +5.8 %); docs/machines/probe.md. node speed is the test rate.
        # projection_speed and raster_speed (the hemicube's kinds, added later) from
        # build/machine_probe --repeats 15 on 2026-11-28 02:48 UTC (load average 4 on 2
        # cores), the fit over its 6 hemicube runs (root mean square residual 11 %, runs within
        # -24 to +9 %; the other five rates of that probe within 1.2 % of these).
        "speed": 4.34e9,
        "rates": {"test_speed": 4.34e9, "ray_speed": 6.05e9, "blocked_ray_speed": 5.6e9,
                  "arithmetic_speed": 1.4e9, "edge_term_speed": 1.28e9,
                  "projection_speed": 7.29e8, "raster_speed": 9.33e8},
        "rates_measured": "Measured by build/machine_probe --repeats 15 on this project's build "
                          "host (AMD EPYC,\n         2.6 GHz) on 2026-11-28 02:11 UTC (projection_speed and "
                          "raster_speed at\n         02:48 UTC), rounded to 3 digits: "
                          "docs/machines/probe.md.",
        "memory": 256 * 1024 ** 3,
        "bandwidth": 25e9,
        "latency": 0.1e-6,
        "send_overhead": 0.5e-6,
        "receive_overhead": 0.5e-6,
        "network": ("fat_tree", ((16, 4), (1, 4), (1, 4))),
        "network_doc": "a non-blocking two-level fat tree: 4 leaf switches of 16 nodes, 4 "
                       "spine switches, 4 links from each leaf to each spine",
        "assumed": ["node_memory", "hop_latency"],
        "family": [],
    },
]


def number(value):
    """A value as SimGrid and strtod both read it, shortest form."""
    return repr(float(value)) if value != int(value) or abs(value) >= 1e16 else str(int(value))


def header(machine, nodes, network_doc):
    return ("<?xml version='1.0'?>\n"
            "<!DOCTYPE platform SYSTEM \"https://simgrid.org/simgrid.dtd\">\n"
            "<!-- %s: %d nodes.\n"
            "     Network: %s.\n"
            "     Assumed (no readable source): %s; every other figure is sourced.\n"
            "     Written by platforms/machines/generate.py (do not edit by hand); every figure,\n"
            "     its source, its confidence and what is assumed: %s. -->\n"
            "<platform version=\"4.1\">\n" % (machine["title"], nodes, network_doc,
                                              ", ".join(machine["assumed"]), machine["page"]))


# The machine parameters a SimGrid file gives as <prop>s, read from the one list
# (src/machine/machine_parameters.h, through docs/platform_tables.py): a parameter added there
# is written here without naming it. A machine's table below names each by the parameter's
# name, but node_memory, which it calls "memory"; the optional ones (rates per kind of work)
# are in its "rates" when it gives them.
sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(HERE)), "docs"))
import platform_tables  # noqa: E402

PROPERTIES = [p for p in platform_tables.machine_parameters() if p["xml"] == "kProperty"]
TABLE_KEY = {"node_memory": "memory"}


def properties(machine, indent):
    pad = " " * indent
    lines = ["%s<!-- What SimGrid has no notion of: the node's memory (bytes) and the CPU time per\n"
             "%s     message on each side (seconds), as in docs/platforms.md. -->\n" % (pad, pad)]
    rates = []
    for p in PROPERTIES:
        if p["optional"]:
            if p["name"] in machine.get("rates", {}):
                rates.append("%s<prop id=\"%s\" value=\"%s\"/>\n"
                             % (pad, p["name"], number(machine["rates"][p["name"]])))
            continue
        key = TABLE_KEY.get(p["name"], p["name"])
        if key not in machine:
            raise SystemExit("generate.py: %s gives no %s (%r)" % (machine["name"], p["name"], key))
        lines.append("%s<prop id=\"%s\" value=\"%s\"/>\n" % (pad, p["name"], number(machine[key])))
    unknown = set(machine.get("rates", {})) - {p["name"] for p in PROPERTIES if p["optional"]}
    if unknown:
        raise SystemExit("generate.py: %s: no such rate %s" % (machine["name"], sorted(unknown)))
    if rates:
        measured = ""
        if "rates_measured" in machine:
            measured = "\n%s     %s" % (pad, machine["rates_measured"])
        rates.insert(0, "%s<!-- Rates per kind of work (flop/s, src/machine/work_kinds.h); node "
                        "speed is\n%s     the test rate.%s -->\n" % (pad, pad, measured))
    return "".join(rates + lines)


def link_attributes(machine):
    return 'bw="%sBps" lat="%ss"' % (number(machine["bandwidth"]), number(machine["latency"]))


def cluster(machine, nodes, topology, parameters):
    return ("  <cluster id=\"%s\" topology=\"%s\" topo_parameters=\"%s\" prefix=\"node-\"\n"
            "           radical=\"0-%d\" suffix=\"\" speed=\"%sf\" %s\n"
            "           sharing_policy=\"SPLITDUPLEX\" loopback_bw=\"1000TBps\" loopback_lat=\"0s\">\n"
            "%s"
            "  </cluster>\n"
            % (machine["name"], topology, parameters, nodes - 1, number(machine["speed"]),
               link_attributes(machine), properties(machine, 4)))


def torus(machine, nodes, dimensions):
    assert nodes == _product(dimensions)
    return cluster(machine, nodes, "TORUS", ",".join(str(d) for d in dimensions))


def fat_tree(machine, nodes, shape):
    down, up = shape[0], shape[1]
    parallel = shape[2] if len(shape) > 2 else (1,) * len(down)
    assert nodes == _product(down) and len(down) == len(up) == len(parallel)
    parameters = "%d;%s;%s;%s" % (len(down), ",".join(map(str, down)), ",".join(map(str, up)),
                                  ",".join(map(str, parallel)))
    return cluster(machine, nodes, "FAT_TREE", parameters)


def mesh(machine, nodes, shape):
    """A 2-D mesh without wrap-around: node k at column k % width, row k // width, on its own
    routing chip mrc-k; a SPLITDUPLEX link joins each node to its chip (at the link's speed, no
    latency) and each chip to its right and lower neighbour. SimGrid's Dijkstra routing takes a
    shortest path, which has the hop count of the machine's X-then-Y routing."""
    width, height = shape
    assert nodes == width * height
    lines = ["  <zone id=\"%s\" routing=\"DijkstraCache\">\n" % machine["name"], properties(machine, 4)]
    for k in range(nodes):
        lines.append("    <host id=\"node-%d\" speed=\"%sf\"/>\n" % (k, number(machine["speed"])))
    for k in range(nodes):
        lines.append("    <router id=\"mrc-%d\"/>\n" % k)
    bw, lat = number(machine["bandwidth"]), number(machine["latency"])
    for k in range(nodes):
        lines.append("    <link id=\"nic-%d\" bandwidth=\"%sBps\" latency=\"0s\" "
                     "sharing_policy=\"SPLITDUPLEX\"/>\n" % (k, bw))
        lines.append("    <link id=\"loop-%d\" bandwidth=\"1000TBps\" latency=\"0s\" "
                     "sharing_policy=\"FATPIPE\"/>\n" % k)
    edges = []
    for k in range(nodes):
        x, y = k % width, k // width
        if x + 1 < width:
            edges.append((k, k + 1))
        if y + 1 < height:
            edges.append((k, k + width))
    for a, b in edges:
        lines.append("    <link id=\"mesh-%d-%d\" bandwidth=\"%sBps\" latency=\"%ss\" "
                     "sharing_policy=\"SPLITDUPLEX\"/>\n" % (a, b, bw, lat))
    for k in range(nodes):
        lines.append("    <route src=\"node-%d\" dst=\"mrc-%d\"><link_ctn id=\"nic-%d\" "
                     "direction=\"UP\"/></route>\n" % (k, k, k))
        lines.append("    <route src=\"node-%d\" dst=\"node-%d\" symmetrical=\"NO\">"
                     "<link_ctn id=\"loop-%d\"/></route>\n" % (k, k, k))
    for a, b in edges:
        lines.append("    <route src=\"mrc-%d\" dst=\"mrc-%d\"><link_ctn id=\"mesh-%d-%d\" "
                     "direction=\"UP\"/></route>\n" % (a, b, a, b))
    lines.append("  </zone>\n")
    return "".join(lines)


def _product(values):
    result = 1
    for v in values:
        result *= v
    return result


BUILDERS = {"torus": torus, "fat_tree": fat_tree, "mesh": mesh}


def network_doc(machine, nodes, network):
    """The header's one-line description of a file's network."""
    if nodes == 64:
        return machine["network_doc"]
    kind, shape = network
    if kind == "torus" and set(shape) == {2}:
        doc = ("a %d-dimensional binary hypercube routed dimension by dimension (e-cube), "
               "written as a TORUS of extent 2 in %d dimensions" % (len(shape), len(shape)))
    elif kind == "torus":
        doc = "a %d-D torus of %s" % (len(shape), " x ".join(map(str, shape)))
    elif kind == "mesh":
        doc = ("a 2-D mesh of %d x %d routing chips without wrap-around links, one node on each; "
               "shortest paths (Dijkstra)" % shape)
    else:
        doc = ("a 4-ary fat tree of %d levels (down %s, up %s): twice the link a node into its "
               "group of 4, once into its group of 16 and half beyond"
               % (len(shape[0]), ",".join(map(str, shape[0])), ",".join(map(str, shape[1]))))
    return doc + "; every other figure is that of %s.xml" % machine["name"]


def platform_text(machine, nodes, network):
    kind, shape = network
    return (header(machine, nodes, network_doc(machine, nodes, network)) + CONFIG +
            BUILDERS[kind](machine, nodes, shape) + "</platform>\n")


def outputs():
    files = []
    for m in MACHINES:
        files.append(("%s.xml" % m["name"], platform_text(m, 64, m["network"])))
        for nodes, shape in m["family"]:
            files.append(("%s-n%d.xml" % (m["name"], nodes),
                          platform_text(m, nodes, (m["network"][0], shape))))
    return files


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--out", default=HERE, help="output folder (default: platforms/machines/)")
    args = parser.parse_args()
    # The output folder checked before any work: a file, a FIFO or a device there is one line
    # and exit 5 (an output that cannot be written), as every program's (docs/cli.md).
    if os.path.lexists(args.out) and not os.path.isdir(args.out):
        print("%s: --out %s: not a folder; nothing written" % ("platforms/machines/generate.py", args.out), file=sys.stderr)
        return 5
    try:
        os.makedirs(args.out, exist_ok=True)
    except OSError as e:
        print("%s: --out %s: cannot make the folder: %s; nothing written"
              % ("platforms/machines/generate.py", args.out, e.strerror or e), file=sys.stderr)
        return 5
    for name, text in outputs():
        with open(os.path.join(args.out, name), "w", encoding="utf-8", newline="\n") as f:
            f.write(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
