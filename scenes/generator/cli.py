"""Builds every scene, fits its elements, validates the text and writes the files (all or
nothing)."""

import argparse
import os
import sys

from .cornell_box import cornell_box
from .elements import fit_elements
from .interiors import scene4
from .targets import COMPACT, TARGETS, patch_cap
from .text import to_text
from .validation import partition_imbalance, validate
from .variant import MAKERS, build_scene

PARTITION_TABLE_SCENES = ("scene1", "scene2", "scene3")
PARTITION_TABLE_PROCESSORS = (4, 8, 16, 32, 64)


def build_all():
    scenes = [(build_scene(name), TARGETS[name]) for name in MAKERS]
    for make in (scene4,):
        b = make()
        target = TARGETS[b.name]
        if len(b.patches) != target[0]:
            raise SystemExit("%s: %d patches, want %d" % (b.name, len(b.patches), target[0]))
        fit_elements(b.patches, target[1], patch_cap(b.name))
        scenes.append((b, target))
    scenes.append((cornell_box(), None))
    return scenes


def partition_table(scenes):
    """docs/scenes.md's table: largest / mean elements per radiosity processor when the whole
    patches are dealt out as the simulator does, for R = 4 .. 64."""
    rows = ["| Scene  | " + " | ".join(("R = %d" % r if i == 0 else "%-5d" % r)
                                        for i, r in enumerate(PARTITION_TABLE_PROCESSORS)) + " |",
            "|--------|" + "------:|" * len(PARTITION_TABLE_PROCESSORS)]
    for b, _ in scenes:
        if b.name not in PARTITION_TABLE_SCENES:
            continue
        counts = [p["nu"] * p["nv"] for p in b.patches]
        rows.append("| %-6s | " % b.name + " | ".join(
            "%.3f" % partition_imbalance(counts, r) for r in PARTITION_TABLE_PROCESSORS) + " |")
    return "\n".join(rows) + "\n"


def main(argv=None, description=None, default_out=None):
    """The command line of scenes/generate.py; default_out is the folder the files go to
    without --out (that script's own folder)."""
    if default_out is None:
        default_out = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("--out", default=default_out,
                        help="output folder (default: the folder of this script)")
    parser.add_argument("--partition-table", action="store_true",
                        help="write nothing; print docs/scenes.md's table of the partition "
                             "by elements (largest / mean per radiosity processor)")
    args = parser.parse_args(argv)
    if args.partition_table:
        sys.stdout.write(partition_table(build_all()))
        return 0
    # The output folder checked before any work: a file, a FIFO or a device there is one line
    # and exit 5 (an output that cannot be written), as every program's (docs/cli.md).
    if os.path.lexists(args.out) and not os.path.isdir(args.out):
        print("%s: --out %s: not a folder; nothing written" % ("scenes/generate.py", args.out), file=sys.stderr)
        return 5
    try:
        os.makedirs(args.out, exist_ok=True)
    except OSError as e:
        print("%s: --out %s: cannot make the folder: %s; nothing written"
              % ("scenes/generate.py", args.out, e.strerror or e), file=sys.stderr)
        return 5
    outputs = []
    failed = False
    for b, target in build_all():
        text = to_text(b, compact=b.name in COMPACT)
        problems = validate(b, text, target)
        for problem in problems:
            print("error: " + problem, file=sys.stderr)
        failed = failed or bool(problems)
        outputs.append((b.name + ".json", text))
    if failed:
        return 1
    for filename, text in outputs:
        with open(os.path.join(args.out, filename), "w", encoding="utf-8", newline="\n") as f:
            f.write(text)
    return 0
