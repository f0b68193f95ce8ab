"""A cell's result file name (docs/sweeps.md, "A cell's identity"): readable, and unique by its
identity's digest. `cells/scene2-R8-V7-cm5-<12 hex digits>.json`: the scene's name, R and V,
then what else sets the cell apart from the defaults, in a fixed order: the platform's and the
cost model's file names (when not ncube2.json, cost_model.json), every option that differs from
its default (numbers as `block_size50`, switches as `balance`, words as `visibility_octree`)
and the SimGrid settings. A run's length (iterations, convergence) is left out: it is rarely
what a sweep compares, and the paper's sweeps keep their names. The name depends on the cell
alone, never on the sweep, so a cell in several sweeps is one file and runs once; the digest
keeps names unique whatever the readable part says (which is cut at NAME_CHARACTERS)."""
import functools
import re
from pathlib import Path

from . import options as opts
from . import paths

DEFAULT_PLATFORM = paths.PLATFORMS / "ncube2.json"
DEFAULT_COST_MODEL = paths.PLATFORMS / "cost_model.json"
LEFT_OUT = ("R", "V", "iterations", "convergence")   # R and V come first; the run's length never
NAME_CHARACTERS = 120                               # the readable part's most (a file name: 255)


def _word(text):
    """Characters a Snakemake wildcard, a shell and a file system read as plain (the
    Snakefile's name constraint, [A-Za-z0-9_.+-])."""
    return re.sub(r"[^A-Za-z0-9_.+-]", "_", str(text))


def _option_part(name, value):
    if isinstance(value, bool):
        return name if value else f"no_{name}"
    if isinstance(value, (int, float)):
        return f"{name}{value:g}" if isinstance(value, float) else f"{name}{value}"
    return f"{name}_{value}"


@functools.lru_cache(maxsize=1)
def _resolved_defaults():
    """The default platform and cost model with links resolved, once a process (every cell's
    name asks: 2 x 258 resolutions were a third of loading the machines study's sweep)."""
    return DEFAULT_PLATFORM.resolve(), DEFAULT_COST_MODEL.resolve()


def parts(cell):
    """The readable parts after the scene, R and V."""
    found = []
    for file, default in zip((cell.platform_file, cell.cost_model_file), _resolved_defaults()):
        if Path(file) != default:
            found.append(Path(file).stem)
    for name, option in opts.OPTIONS.items():
        if name not in LEFT_OUT and cell.options.get(name, option.default) != option.default:
            found.append(_option_part(name, cell.options[name]))
    for key, value in sorted(cell.cfg.items()):
        found.append(f"{key}_{value}")
    return found


def stem(cell):
    """`scene2-R8-V7-cm5`: the readable part of the name."""
    scene = re.sub(r"[^A-Za-z0-9_-]", "_", cell.scene)
    text = "-".join([f"{scene}-R{cell.R}-V{cell.V}"] + [_word(p) for p in parts(cell)])
    return text[:NAME_CHARACTERS].rstrip("-")


def file(cell):
    """The result file, relative to the results folder."""
    folder = "traced" if cell.trace else "cells"
    return f"{folder}/{stem(cell)}-{cell.id}.json"


def legacy_file(cell):
    """The name the same result had before the readable parts beyond the scene, R and V
    (`cells/scene2-R8-V7-<id>.json`): a sweep finds a finished result under it and gives it
    its present name (ncube.runner.adopt_legacy_names)."""
    folder = "traced" if cell.trace else "cells"
    scene = re.sub(r"[^A-Za-z0-9_-]", "_", cell.scene)
    return f"{folder}/{scene}-R{cell.R}-V{cell.V}-{cell.id}.json"


def rename_legacy(cells, folder):
    """In `folder`, every file named after a cell's former name (its stem, then any suffix:
    .json, .trace.json, .ply) renamed to the cell's present name, unless a file has that name
    already; returns [(old, new)]. For folders no sweep reads (analysis/claims.py keeps each
    cell's result and mesh under <stem>.json and <stem>.ply): a sweep renames its own results
    itself (ncube.runner.adopt_legacy_names)."""
    folder = Path(folder)
    renamed = []
    names = {Path(legacy_file(c)).stem: Path(file(c)).stem for c in cells}
    for path in sorted(folder.iterdir()) if folder.is_dir() else []:
        for old, new in names.items():
            if old != new and path.name.startswith(old + "."):
                target = folder / (new + path.name[len(old):])
                if not target.exists():
                    path.rename(target)
                    renamed.append((path.name, target.name))
    return renamed


def main(argv=None):
    """python3 -m ncube.cell_names FOLDER SWEEP_FILE...: renames the files of FOLDER named after
    the former names of the sweep files' cells (docs/sweeps.md, "A cell's identity")."""
    import sys
    from .sweep import SweepError, load_all
    argv = sys.argv[1:] if argv is None else argv
    if len(argv) < 2:
        print("usage: python3 -m ncube.cell_names FOLDER SWEEP_FILE...", file=sys.stderr)
        return 2
    try:
        sweeps = load_all(argv[1:])
    except SweepError as e:
        print(f"cell_names: {e}", file=sys.stderr)
        return 2
    renamed = rename_legacy([c for s in sweeps for c in s.cells], argv[0])
    for old, new in renamed:
        print(f"{old} -> {new}")
    print(f"cell_names: {len(renamed)} file(s) renamed in {argv[0]}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
