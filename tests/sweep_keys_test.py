#!/usr/bin/python3
"""Names in a sweep file corrected as typed (docs/sweeps.md, "Validation"): a misspelt key, a
command-line spelling of a key, a misspelt scene or platform name each get one line naming the
file, the place (top level, options, grid, a grid group's entry, cells[N]) and the nearest
known name; exit 2; nothing written (no results folder made)."""
import contextlib
import io
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "analysis"))
from ncube import runner  # noqa: E402

SWEEP = [str(ROOT / "experiments" / "sweep")]
failures = []


def sweep_in_process(args):
    """experiments/sweep's own entry (ncube.runner.main, which the script calls) run here, as
    a completed process: a refusal reads the sweep file as the script does, without a Python
    started for each case (the unchanged file goes through the script itself)."""
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        code = runner.main([str(a) for a in args])
    return subprocess.CompletedProcess(args, code, out.getvalue(), err.getvalue())


def check(condition, what):
    print(("ok   " if condition else "FAIL ") + what, flush=True)
    if not condition:
        failures.append(what)


GOOD = {"top": "measure: seconds_per_iteration", "options": "iterations: 1",
        "grid": "scene: [scene0]\n  R: [1]\n  split: [{V: 0}, {V: 1}]",
        "cells": "  - {scene: scene0, R: 2}\n  - {scene: scene0, R: 4, samples: 4}"}

# (what, the part changed, its new text, the line expected after "sweep: FILE: ")
CASES = [
    ("a misspelt option key", "options", "iteration: 1",
     "options: unknown key 'iteration'; did you mean 'iterations'?"),
    ("the command-line spelling of a key", "options", "block-size: 50",
     "options: unknown key 'block-size': the sweep key is 'block_size' (--block-size is the "
     "command-line spelling)"),
    ("a misspelt grid key", "grid", "scene: [scene0]\n  R: [1]\n  platfrom: [cm5]",
     "grid: unknown key 'platfrom'; did you mean 'platform'?"),
    ("a misspelt key in a group's entry", "grid", "scene: [scene0]\n  R: [1]\n  split: [{V: 0}, {v: 1}]",
     "grid, group 'split' (entry 2): unknown key 'v'; did you mean 'V'?"),
    ("a misspelt key of a listed cell", "cells", "  - {scene: scene0, R: 2}\n  - {scene: scene0, R: 4, samplse: 4}",
     "cells[2]: unknown key 'samplse'; did you mean 'samples'?"),
    ("a misspelt top-level key", "top", "mesure: seconds_per_iteration",
     "top level: unknown key 'mesure'; did you mean 'measure'?"),
    ("a misspelt platform name", "options", "iterations: 1\n  platform: cm-5",
     "options: key 'platform': no platform 'cm-5' (a path, or a name in platforms/, "
     "platforms/machines/); did you mean 'cm5' (platforms/machines/cm5.xml) or 'cm5-n512' "
     "(platforms/machines/cm5-n512.xml) or 'cm5-n256' (platforms/machines/cm5-n256.xml)?"),
    ("a misspelt scene name in a cell", "cells", "  - {scene: scene0, R: 2}\n  - {scene: scen2, R: 4}",
     "cells[2]: key 'scene': no scene 'scen2' (a path, or a name in scenes/); did you mean "
     "'scene2' (scenes/scene2.json) or 'scene4' (scenes/scene4.json) or 'scene3' "
     "(scenes/scene3.json)?"),
]


def document(parts):
    return (f"{parts['top']}\noptions:\n  {parts['options']}\ngrid:\n  {parts['grid']}\n"
            f"cells:\n{parts['cells']}\n")


def main():
    with tempfile.TemporaryDirectory(prefix="ncube-sweep-keys-test-") as folder:
        work = Path(folder)
        good = work / "good.yaml"
        good.write_text(document(GOOD))
        done = subprocess.run(SWEEP + [str(good), "--check"], capture_output=True, text=True,
                              timeout=120)
        check(done.returncode == 0, f"the unchanged file is taken ({done.stderr.strip()})")
        for what, part, text, expected in CASES:
            sweep_file = work / "typo.yaml"
            sweep_file.write_text(document(dict(GOOD, **{part: text})))
            results = work / "results"
            done = sweep_in_process([sweep_file, "--results", results])
            said = done.stderr.splitlines()
            check(done.returncode == 2 and said == [f"sweep: {sweep_file}: {expected}"] and
                  not done.stdout and not results.exists(),
                  f"{what}: one line, exit 2, nothing written ({done.returncode}, {said})")
    print(f"sweep_keys_test: {len(failures)} failure(s)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
