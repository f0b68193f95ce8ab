"""Where things are: the repository, ./simulate, scenes/ and platforms/."""
import os
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent.parent
ANALYSIS = ROOT / "analysis"
EXPERIMENTS = ROOT / "experiments"
SCENES = ROOT / "scenes"
PLATFORMS = ROOT / "platforms"
PYTHON = "/usr/bin/python3"   # Debian's, with matplotlib, numpy, yaml and snakemake


def simulate_binary():
    """The simulator: $NCUBE_SIMULATE (tests give the build's binary), else ./simulate."""
    return os.environ.get("NCUBE_SIMULATE") or str(ROOT / "simulate")


def simulate_environment():
    """./simulate finds scenes/ and platforms/ through NCUBE_ROOT."""
    return dict(os.environ, NCUBE_ROOT=os.environ.get("NCUBE_ROOT", str(ROOT)))


# Where a bare name of each role is looked up, in order, and the extensions a bare name may
# leave out: the one table of src/tools/input_lookup.cpp, held equal to it by
# tests/input_lookup_test.sh (which runs both on the same names).
INPUT_FOLDERS = {
    "scene": (("scenes",), (".json",)),
    "platform": (("platforms", "platforms/machines"), (".json", ".xml")),
    "cost model": (("platforms",), (".json",)),
}


def input_candidates(name, base, role, root=None):
    """Every path `name` is looked for at, in order (docs/cli.md, "Finding the input files"):
    as given (absolute, or relative to `base`: the current folder for a command line, the
    sweep file's folder in a sweep); relative to the repository root; and a bare name (no
    '/') in the role's folders, as given and with each of the role's extensions."""
    root = Path(root or ROOT)
    # "~/..." in a sweep file means what it means on a command line, where the shell expands it.
    name = os.path.expanduser(name)
    path = Path(name)
    if not name or path.is_absolute():
        return [path]
    candidates = [Path(base) / path, root / path]
    if "/" not in name:
        folders, extensions = INPUT_FOLDERS[role]
        for folder in folders:
            candidates.append(root / folder / name)
            candidates += [root / folder / (name + e) for e in extensions if path.suffix != e]
    return candidates


def find_input(name, base, role, root=None):
    """The first of input_candidates that exists (a broken link counts: the read gate reports
    it), as an absolute Path with links resolved; None when none does (see looked_for)."""
    for candidate in input_candidates(name, base, role, root):
        if os.path.lexists(candidate):
            return Path(candidate).resolve()
    return None


def looked_for(name, base, role, root=None):
    """"looked for: A, B, ..." for the message when find_input finds nothing."""
    return "looked for: " + ", ".join(str(c) for c in input_candidates(name, base, role, root))
