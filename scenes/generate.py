#!/usr/bin/env python3
"""Generates the radiosity test scenes of the simulator (described in docs/scenes.md).

    python3 scenes/generate.py [--out DIR]

writes into DIR (default: the folder of this script)

    scene0.json .. scene3.json  furnished interiors with exactly the patch and element counts
                                of the four test scenes of Stuerzlinger & Wild 1994, section 5;
    scene4.json                 a floor of a school building made of copies of those rooms
                                (51,200 patches: the too-large scenes of section 6);
    cornell-box.json            the published Cornell box data (geometry in mm).

The output is byte-for-byte reproducible: no randomness, a fixed patch order, a fixed number
format (at most 4 decimals) and a fixed layout of one patch per line. Python 3 standard library
only. Every scene is validated from the very text that is written (planarity, convexity, size,
orientation, overlaps, exact counts); a failed check prints the problem and exits with 1
without writing anything.

This file is the entry point only; the generator is the package scenes/generator/, one module
per concern (its __init__.py lists them).
"""

import os
import sys

sys.dont_write_bytecode = True  # no __pycache__ left beside the committed scenes
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from generator.cli import main  # noqa: E402  (needs the path above)

if __name__ == "__main__":
    sys.exit(main(description=__doc__.split("\n")[0],
                  default_out=os.path.dirname(os.path.abspath(__file__))))
