#!/usr/bin/python3
"""Writes the larger members of the nCube2 family, platforms/ncube2-d7.json .. ncube2-d13.json
(128 to 8,192 nodes), from platforms/ncube2.json.

    /usr/bin/python3 platforms/generate.py [--out DIR]

ncube2.json is the one source of every machine parameter: each generated file is its text
with only the description and the "dimension" line replaced, so a change to ncube2.json is
carried over by running this script again (tests/platforms_reproducible_test.sh checks that
the committed files are exactly what it writes). The nCube2 was built with up to 8,192 nodes:
each node has 13 hypercube channels (TOP500 1994 report; docs/ncube2-sources.md).
"""

import argparse
import json
import os
import sys

DIMENSIONS = range(7, 14)
HERE = os.path.dirname(os.path.abspath(__file__))


def family_member(base_text, dimension):
    nodes = 1 << dimension
    description = ("The nCube2 of Stuerzlinger & Wild (1994) scaled to a %d-dimensional "
                   "hypercube of %s nodes; every other parameter is that of ncube2.json "
                   "(written from it by platforms/generate.py). Figures and sources: "
                   "docs/ncube2-sources.md and docs/model.md." % (dimension, "{:,}".format(nodes)))
    dimension_line = (
        '    "dimension": {"value": %d, "unit": "", "doc": "hypercube dimension; the machine has '
        '2^dimension nodes, node k\'s bit i is its coordinate in dimension i", "source": '
        '"nCube2 family: 13 hypercube channels per node, up to 8192 nodes (TOP500 1994 '
        'report); %d nodes here"},' % (dimension, nodes))
    lines = []
    replaced = set()
    for line in base_text.split("\n"):
        if line.startswith('  "description": '):
            line = '  "description": %s,' % json.dumps(description)
            replaced.add("description")
        elif line.startswith('    "dimension": '):
            line = dimension_line
            replaced.add("dimension")
        lines.append(line)
    if replaced != {"description", "dimension"}:
        raise SystemExit("platforms/generate.py: ncube2.json no longer has one description "
                         "line and one dimension line; update the generator")
    text = "\n".join(lines)
    # Everything but the dimension must be ncube2.json's.
    base, member = json.loads(base_text)["parameters"], json.loads(text)["parameters"]
    if member["dimension"]["value"] != dimension or set(base) != set(member) or any(
            base[k] != member[k] for k in base if k != "dimension"):
        raise SystemExit("platforms/generate.py: ncube2-d%d.json would differ from ncube2.json "
                         "in more than the dimension" % dimension)
    return text


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--out", default=HERE, help="output folder (default: platforms/)")
    args = parser.parse_args()
    # The output folder checked before any work: a file, a FIFO or a device there is one line
    # and exit 5 (an output that cannot be written), as every program's (docs/cli.md).
    if os.path.lexists(args.out) and not os.path.isdir(args.out):
        print("%s: --out %s: not a folder; nothing written" % ("platforms/generate.py", args.out), file=sys.stderr)
        return 5
    try:
        os.makedirs(args.out, exist_ok=True)
    except OSError as e:
        print("%s: --out %s: cannot make the folder: %s; nothing written"
              % ("platforms/generate.py", args.out, e.strerror or e), file=sys.stderr)
        return 5
    with open(os.path.join(HERE, "ncube2.json"), encoding="utf-8") as f:
        base_text = f.read()
    outputs = [("ncube2-d%d.json" % d, family_member(base_text, d)) for d in DIMENSIONS]
    for name, text in outputs:
        with open(os.path.join(args.out, name), "w", encoding="utf-8", newline="\n") as f:
            f.write(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
