#!/usr/bin/python3
"""One lookup rule for the scene, the platform and the cost model (docs/cli.md, "Finding the
input files"), in ./simulate (src/tools/input_lookup.cpp) and in the sweep tool
(analysis/ncube/paths.py) alike. Each case runs `simulate --list-inputs` from a folder that is
not the repository and checks the file it names against the one expected (worked out here by
hand from the rule) and against paths.find_input on the same name from the same folder; a name
found nowhere must be exit 2 from ./simulate, with the same places tried, in the same order, as
paths.input_candidates lists. A sweep file names a machine by its bare name.

Usage: NCUBE_SIMULATE=build/simulate /usr/bin/python3 tests/input_lookup_test.py"""
import json
import os
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "analysis"))
from ncube import paths  # noqa: E402
from ncube.sweep import load  # noqa: E402

SIMULATE = os.environ["NCUBE_SIMULATE"]
OPTION = {"scene": None, "platform": "--platform", "cost model": "--cost-model"}
failures = []


def check(condition, what):
    print(("ok   " if condition else "FAIL ") + what, flush=True)
    if not condition:
        failures.append(what)


def simulate(cwd, role, name):
    """./simulate --list-inputs from `cwd` with `name` in `role`: (exit code, listing or stderr)."""
    scene = name if role == "scene" else "scene0"
    args = [SIMULATE, scene, "--list-inputs"] + ([OPTION[role], name] if OPTION[role] else [])
    run = subprocess.run(args, cwd=cwd, capture_output=True, text=True, timeout=60,
                         env=dict(os.environ, NCUBE_ROOT=str(ROOT)))
    if run.returncode != 0:
        return run.returncode, run.stderr
    listed = {entry["role"]: entry["file"] for entry in json.loads(run.stdout)["inputs"]}
    return 0, listed.get(role) or listed.get("model")  # a model file is listed as one


def found(cwd, role, name, expected):
    code, file = simulate(cwd, role, name)
    python = paths.find_input(name, cwd, role)
    where = f"{role} {name!r} from {cwd}"
    check(code == 0, f"{where}: ./simulate finds it")
    if code == 0:
        check(os.path.realpath(Path(cwd) / file) == os.path.realpath(expected),
              f"{where}: ./simulate reads {expected} (read {file})")
    check(python is not None and os.path.realpath(python) == os.path.realpath(expected),
          f"{where}: paths.find_input finds {expected} (found {python})")


def missing(cwd, role, name):
    code, message = simulate(cwd, role, name)
    where = f"{role} {name!r} from {cwd}"
    check(code == 2, f"{where}: exit 2 when it is nowhere (exit {code})")
    check(paths.find_input(name, cwd, role) is None, f"{where}: paths.find_input finds nothing")
    # The message lists every place tried, in the order paths.input_candidates tries them.
    tried = message.split("(looked for: ", 1)[-1].rsplit(")", 1)[0].split(", ")
    from_cpp = [os.path.normpath(Path(cwd) / t) for t in tried]
    from_python = [os.path.normpath(c) for c in paths.input_candidates(name, cwd, role)]
    check(f"no such {role} file" in message and from_cpp == from_python,
          f"{where}: the message lists the places tried, as paths.py does ({message.strip()!r})")


with tempfile.TemporaryDirectory() as folder:
    elsewhere = Path(folder) / "elsewhere"
    elsewhere.mkdir()
    cwd = str(elsewhere)
    scenes, platforms = ROOT / "scenes", ROOT / "platforms"
    # A bare name in scenes/, with or without its extension (./simulate scene3).
    found(cwd, "scene", "scene3", scenes / "scene3.json")
    found(cwd, "scene", "scene3.json", scenes / "scene3.json")
    # A path relative to the repository root, from another folder (the README's examples).
    found(cwd, "scene", "tests/models/cornell-box.obj", ROOT / "tests/models/cornell-box.obj")
    found(cwd, "scene", "scenes/scene0.json", scenes / "scene0.json")
    # A platform by name: platforms/ first, then platforms/machines/.
    found(cwd, "platform", "cm5", platforms / "machines/cm5.xml")
    found(cwd, "platform", "cm5.xml", platforms / "machines/cm5.xml")
    found(cwd, "platform", "ncube2", platforms / "ncube2.json")
    found(cwd, "platform", "ncube2.xml", platforms / "ncube2.xml")
    found(cwd, "platform", "docs/examples/fat-tree-64.xml", ROOT / "docs/examples/fat-tree-64.xml")
    found(cwd, "cost model", "cost_model", platforms / "cost_model.json")
    # A file in the current folder comes first, before the repository's of the same name.
    shutil.copy(scenes / "cornell-box.json", elsewhere / "scene0.json")
    shutil.copy(platforms / "ncube2.json", elsewhere / "cm5")
    found(cwd, "scene", "scene0.json", elsewhere / "scene0.json")
    found(cwd, "platform", "cm5", elsewhere / "cm5")
    (elsewhere / "sub").mkdir()
    shutil.copy(scenes / "cornell-box.json", elsewhere / "sub" / "scenes.json")
    found(cwd, "scene", "sub/scenes.json", elsewhere / "sub" / "scenes.json")
    # Found nowhere: exit 2, and where it looked.
    missing(cwd, "scene", "nosuch")
    missing(cwd, "scene", "nosuch.json")
    missing(cwd, "scene", "sub/nosuch.json")
    missing(cwd, "platform", "nosuch")
    missing(cwd, "cost model", "nosuch.json")
    missing(cwd, "scene", str(elsewhere / "nosuch.json"))
    # build/network_bench finds its platform by the same rule.
    bench = Path(SIMULATE).parent / "network_bench"
    done = subprocess.run([str(bench), "--platform", "cm5", "--quiet", "--max-bytes", "64",
                           "--json", "bench.json"], cwd=cwd, capture_output=True, text=True,
                          timeout=60, env=dict(os.environ, NCUBE_ROOT=str(ROOT)))
    check(done.returncode == 0 and os.path.realpath(elsewhere / json.loads(
          (elsewhere / "bench.json").read_text())["platform_file"]) == str(elsewhere / "cm5"),
          f"network_bench --platform cm5 reads ./cm5 first ({done.stderr.strip()})")
    (elsewhere / "cm5").unlink()
    done = subprocess.run([str(bench), "--platform", "cm5", "--quiet", "--max-bytes", "64",
                           "--json", "bench.json"], cwd=cwd, capture_output=True, text=True,
                          timeout=60, env=dict(os.environ, NCUBE_ROOT=str(ROOT)))
    check(done.returncode == 0 and json.loads((elsewhere / "bench.json").read_text())["platform_file"]
          == str(platforms / "machines/cm5.xml"), f"network_bench --platform cm5 reads platforms/machines/cm5.xml ({done.stderr.strip()})")
    # A sweep file names a machine and a scene by their bare names, as ./simulate does.
    sweep = elsewhere / "machines.json"
    sweep.write_text(json.dumps({"name": "lookup", "cells": [
        {"scene": "scene0", "platform": "cm5.xml", "R": 1}]}))
    cell = load(sweep).cells[0]
    check(Path(cell.platform_file) == platforms / "machines/cm5.xml"
          and Path(cell.scene_file) == scenes / "scene0.json",
          f"a sweep's cell finds scene0 and cm5.xml ({cell.scene_file}, {cell.platform_file})")

if failures:
    print(f"{len(failures)} failures", file=sys.stderr)
    sys.exit(1)
