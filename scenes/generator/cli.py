"""Builds every scene, fits its elements, validates the text and writes the files (all or
nothing)."""

import argparse
import os
import sys

from .cornell_box import cornell_box
from .elements import fit_elements
from .interiors import scene0, scene1, scene2, scene3, scene4
from .targets import COMPACT, TARGETS, patch_cap
from .text import to_text
from .validation import validate


def build_all():
    scenes = []
    for make in (scene0, scene1, scene2, scene3, scene4):
        b = make()
        target = TARGETS[b.name]
        if len(b.patches) != target[0]:
            raise SystemExit("%s: %d patches, want %d" % (b.name, len(b.patches), target[0]))
        fit_elements(b.patches, target[1], patch_cap(b.name))
        scenes.append((b, target))
    scenes.append((cornell_box(), None))
    return scenes


def main(argv=None, description=None, default_out=None):
    """The command line of scenes/generate.py; default_out is the folder the files go to
    without --out (that script's own folder)."""
    if default_out is None:
        default_out = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("--out", default=default_out,
                        help="output folder (default: the folder of this script)")
    args = parser.parse_args(argv)
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
    os.makedirs(args.out, exist_ok=True)
    for filename, text in outputs:
        with open(os.path.join(args.out, filename), "w", encoding="utf-8", newline="\n") as f:
            f.write(text)
    return 0
