"""Names in a sweep file checked where they are written, before any cell is made: an unknown
key or input name gets one line naming the file, the place (the top level, `options`, `grid`,
a grid group, `cells[N]`, counted from 1) and the nearest known names ("did you mean"), as
./simulate answers a misspelt option. ncube.sweep calls check(); a SweepError ends the sweep
with exit 2 before anything is written (docs/sweeps.md, "Validation")."""
import difflib
from pathlib import Path

from . import paths


def nearest(name, known, count=1, cutoff=0.6):
    """The `count` known names closest to `name` (difflib's ratio, case-insensitive), best
    first; [] when none is close."""
    lowered = {k.lower(): k for k in known}
    return [lowered[m] for m in difflib.get_close_matches(str(name).lower(), list(lowered),
                                                          n=count, cutoff=cutoff)]


def _spelt_as_option(name, known):
    """The key a command-line spelling stands for (`block-size`, `--block-size` ->
    `block_size`), None when it is none."""
    key = str(name).lstrip("-").replace("-", "_")
    for k in known:
        if k.lower() == key.lower():
            return k
    return None


def unknown_key(where, place, key, known, what="key"):
    """The one line for an unknown `key` at `place` of the sweep file `where`."""
    key_text = repr(key) if len(repr(key)) <= 80 else repr(str(key)[:60]) + f" (cut; {len(str(key)):,} characters)"
    option = _spelt_as_option(key, known)
    if option is not None and option != key:
        if "-" in str(key):
            return (f"{where}: {place}: unknown {what} {key_text}: the sweep key is {option!r} "
                    f"(--{option.replace('_', '-')} is the command-line spelling)")
        return f"{where}: {place}: unknown {what} {key_text}; did you mean {option!r}?"
    close = nearest(key, known)
    if close:
        return f"{where}: {place}: unknown {what} {key_text}; did you mean {close[0]!r}?"
    return f"{where}: {place}: unknown {what} {key_text} (known: " + ", ".join(sorted(known)) + ")"


# The roles of the keys that name an input file, and where a bare name of each is looked up.
NAMED_INPUTS = {"scene": "scene", "platform": "platform", "cost_model": "cost model"}


def existing_names(role):
    """{bare name: file shown} of every file of `role` in its folders (scenes/, platforms/,
    platforms/machines/), as ./simulate finds a bare name (ncube.paths.INPUT_FOLDERS)."""
    folders, extensions = paths.INPUT_FOLDERS[role]
    names = {}
    for folder in folders:
        for file in sorted((paths.ROOT / folder).glob("*")):
            if file.suffix in extensions and file.is_file():
                names.setdefault(file.stem, f"{folder}/{file.name}")
    return names


def unknown_input(where, place, key, value, base):
    """The one line for an input name that names no file, with the nearest existing names;
    None when the name finds a file."""
    role = NAMED_INPUTS[key]
    if not isinstance(value, str) or paths.find_input(value, base, role) is not None:
        return None
    names = existing_names(role)
    stem = Path(value).name
    for extension in paths.INPUT_FOLDERS[role][1]:
        stem = stem.removesuffix(extension)
    close = nearest(stem, names, count=3, cutoff=0.5)
    folders = ", ".join(f + "/" for f in paths.INPUT_FOLDERS[role][0])
    if close:
        hint = "did you mean " + " or ".join(f"{n!r} ({names[n]})" for n in close) + "?"
    else:
        hint = f"the {role}s in {folders}: " + ", ".join(sorted(names))
    return f"{where}: {place}: key {key!r}: no {role} {value!r} (a path, or a name in {folders}); {hint}"


def _check_mapping(where, place, mapping, known, base):
    for key, value in mapping.items():
        if key not in known:
            return unknown_key(where, place, key, known)
        if key in NAMED_INPUTS:
            problem = unknown_input(where, place, key, value, base)
            if problem:
                return problem
    return None


def problem(document, where, top_keys, cell_keys, base):
    """The first unknown name of a sweep file as its one line, None when every name is known.
    Checks the top-level keys, then `options`, `grid` (its keys, the keys of each group's
    mappings and the values of scene, platform, cost_model) and each of `cells`; shapes (a
    mapping, a list) are left to the loader, which says them."""
    for key in document:
        if key not in top_keys:
            return unknown_key(where, "top level", key, top_keys)
    options = document.get("options")
    if isinstance(options, dict):
        found = _check_mapping(where, "options", options, cell_keys, base)
        if found:
            return found
    grid = document.get("grid")
    if isinstance(grid, dict):
        for key, values in grid.items():
            if key in cell_keys:
                if key in NAMED_INPUTS and isinstance(values, list):
                    for value in values:
                        found = unknown_input(where, "grid", key, value, base)
                        if found:
                            return found
                continue
            if isinstance(values, list) and values and all(isinstance(v, dict) and v
                                                            for v in values):
                for k, entry in enumerate(values, 1):
                    found = _check_mapping(where, f"grid, group {key!r} (entry {k})", entry,
                                           cell_keys, base)
                    if found:
                        return found
                continue
            said = unknown_key(where, "grid", key, cell_keys)
            if said.endswith(")"):   # no near name: what a grid key may be
                said += ("; a grid key is a cell key, or names a group of keys that vary "
                         "together (a list of mappings, e.g. {R: 4, V: 15})")
            return said
    cells = document.get("cells")
    if isinstance(cells, list):
        for k, cell in enumerate(cells, 1):
            if isinstance(cell, dict):
                found = _check_mapping(where, f"cells[{k}]", cell, cell_keys, base)
                if found:
                    return found
    return None
