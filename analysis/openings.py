#!/usr/bin/python3
"""Writes each results page's opening from the page's own tables, without results or simulator.

The opening says what the page found, with figures and how sure: the sentences its script
writes when it writes the whole page (ncube.opening).

usage: /usr/bin/python3 analysis/openings.py [--check] [PAGE ...]

PAGE: analysis/report.md and the others below (default: all of them). --check writes nothing
and exits 1 naming every page whose opening is not the one its tables give (a table changed by
hand, or a sentence that no longer follows from it)."""

from ncube.interpreter import use_project_python  # noqa: E402

use_project_python()   # Debian's /usr/bin/python3 (README.md, "Use")

import argparse
import importlib
import sys
from pathlib import Path

from ncube import opening as op  # noqa: E402
from ncube import page  # noqa: E402
from ncube.paths import ANALYSIS  # noqa: E402

# page -> the script that writes it (its module has opening(tables)).
PAGES = {"report.md": "report", "unknowns.md": "unknowns", "machines.md": "machines",
         "adaptive.md": "adaptive", "predictions.md": "predictions",
         "memory-sensitivity.md": "memory_sensitivity", "patch-order.md": "patch_order",
         "claims.md": "claims"}


def reopened(path):
    """The page's text with the opening its own tables give."""
    module = importlib.import_module(PAGES[path.name])
    text = path.read_text()
    return op.with_opening(text, module.opening(op.tables(text)),
                           f"analysis/{PAGES[path.name]}.py")


@page.refusing_outputs("openings.py")
def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--check", action="store_true",
                        help="write nothing; exit 1 when a page's opening is not its tables'")
    parser.add_argument("pages", nargs="*", type=Path,
                        default=[ANALYSIS / name for name in PAGES])
    args = parser.parse_args()
    unknown = [str(p) for p in args.pages if p.name not in PAGES]
    if unknown:
        page.refuse("openings.py", f"not a results page: {', '.join(unknown)} (known: "
                                   f"{', '.join(PAGES)})")
    stale = []
    for path in args.pages:
        text = reopened(path)
        if text == path.read_text():
            continue
        stale.append(page.shown(path))
        if not args.check:
            page.write(path, text)
    if args.check and stale:
        print(f"openings.py: the opening is not what the page's tables give: {', '.join(stale)}",
              file=sys.stderr)
        return 1
    print(f"openings.py: {'rewritten' if stale else 'unchanged'}: "
          f"{', '.join(stale) if stale else len(args.pages)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
