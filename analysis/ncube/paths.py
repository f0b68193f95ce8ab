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


def resolve_input(name, base, folder, suffix=".json"):
    """A path (absolute, or relative to `base`, the folder of the file naming it), else a bare
    name looked up in `folder` (with or without its suffix). Returns an absolute Path or None."""
    candidates = []
    path = Path(name).expanduser()
    if path.is_absolute():
        candidates.append(path)
    else:
        candidates.append(Path(base) / path)
        if "/" not in name:
            candidates += [folder / name, folder / (name + suffix)]
    for candidate in candidates:
        if candidate.is_file():
            return candidate.resolve()
    return None
