#!/usr/bin/python3
"""Golden runs: a few whole runs of ./simulate pinned to their simulated seconds.

Each run below is compared, to the last digit, with its record tests/goldens/<run>.json: its
status, iteration counts and every simulated-time field of its result file (every field named
*_seconds at any level, the run's, each node's, the rendering phase's and its nodes';
iteration_seconds entry by entry), never host_seconds or the provenance. So any change to a
simulated second fails tests/goldens_test.sh unless the records are regenerated on purpose,
with the one command

    tests/goldens/regenerate

whose commit says that it regenerates them and why (docs/reproduce.md, "Golden runs").

The runs: the calibration cells of analysis/calibration.json, each as its sweep runs it
(experiments/tableN.json, as analysis/calibrate.py does), scene0 to convergence, and one short
run each with adaptive subdivision, load balancing, octree visibility and parallel rendering
(blocks over the hypercube, scanlines over the ring). Each run also checks that it still
exercises what it is there for (cuts made, patches moved, octree cells visited, a picture).

usage: goldens.py check SIMULATE
       goldens.py regenerate [SIMULATE]     (default: build/simulate)
"""

import sys  # noqa: E402
from pathlib import Path  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "analysis"))
from ncube.interpreter import use_project_python  # noqa: E402

use_project_python()   # Debian's /usr/bin/python3 (README.md, "Use")

import json
import os
import sys
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent.parent / "analysis"))
from ncube import options as opts  # noqa: E402
from ncube import simulate, sweep  # noqa: E402
from ncube.paths import ANALYSIS, EXPERIMENTS, PLATFORMS, ROOT, SCENES  # noqa: E402

GOLDENS = Path(__file__).resolve().parent
REGENERATE = "tests/goldens/regenerate"


def relative(path):
    return str(Path(path).resolve().relative_to(ROOT))


def run_spec(name, scene, options, exercises, platform=PLATFORMS / "ncube2.json",
             cost_model=PLATFORMS / "cost_model.json", cfg=None):
    """A golden run: the scene file, its options (ncube.options names; the others default),
    and `exercises`, what the result must show for the run to test its feature."""
    return {"name": name, "scene": relative(scene), "options": dict(options),
            "platform": relative(platform), "cost_model": relative(cost_model),
            "cfg": dict(cfg or {}), "exercises": exercises}


def calibration_runs():
    """The cells analysis/calibrate.py fits, with their sweeps' options."""
    runs = []
    for c in json.loads((ANALYSIS / "calibration.json").read_text())["cells"]:
        cells = sweep.load(EXPERIMENTS / f"table{c['table']}.json").cells
        cell = next(x for x in cells if (x.scene, x.R, x.V) == (c["scene"], c["R"], c["V"]))
        changed = {k: v for k, v in cell.options.items() if v != opts.OPTIONS[k].default}
        runs.append(run_spec(f"calibration-table{c['table']}-{c['scene']}-R{c['R']}-V{c['V']}",
                             cell.scene_file, changed, "iterations", cell.platform_file,
                             cell.cost_model_file, cell.cfg))
    return runs


def runs():
    small = {"image_width": 160, "image_height": 120}
    return calibration_runs() + [
        run_spec("scene0-converged", SCENES / "scene0.json", {}, "converged"),
        run_spec("subdivide", SCENES / "scene1.json",
                 {"R": 4, "V": 1, "iterations": 5, "subdivide": True}, "cuts"),
        run_spec("balance", SCENES / "scene1.json",
                 {"R": 4, "V": 0, "iterations": 8, "subdivide": True, "balance": True}, "transfers"),
        run_spec("octree", SCENES / "scene1.json",
                 {"R": 4, "V": 3, "iterations": 5, "visibility": "octree"}, "octree"),
        run_spec("render-blocks-hypercube", SCENES / "scene1.json",
                 dict(small, R=4, V=0, iterations=3, render_parallel="blocks",
                      render_distribution="hypercube"), "picture"),
        run_spec("render-scanlines-ring", SCENES / "scene1.json",
                 dict(small, R=4, V=1, iterations=3, render_parallel="scanlines",
                      render_distribution="ring"), "picture"),
    ]


# What each run must show to test its feature (else a change of defaults could quietly turn
# a golden run into a plain one).
EXERCISES = {
    "iterations": lambda r: r["iterations"] == r["config"]["max_iterations"],
    "converged": lambda r: r["converged"],
    "cuts": lambda r: r["counts"]["elements_created"] > 0,
    "transfers": lambda r: r["patches_moved"] > 0,
    "octree": lambda r: r["counts"]["octree_cells_visited"] > 0,
    "picture": lambda r: r.get("render", {}).get("simulated_seconds", 0) > 0,
}


def command(spec, simulate_binary="./simulate", json_out=None):
    return opts.command(simulate_binary, spec["scene"], spec["options"], spec["platform"],
                        spec["cost_model"], spec["cfg"], json_out=json_out)


def times(value):
    """Every simulated-time field (named *_seconds) of a result, nested as in the result;
    host_seconds and the provenance left out."""
    if isinstance(value, dict):
        kept = {}
        for key, item in value.items():
            if key in ("host_seconds", "provenance"):
                continue
            if key.endswith("_seconds"):
                kept[key] = item
            else:
                inner = times(item)
                if inner:
                    kept[key] = inner
        return kept
    if isinstance(value, list):
        inner = [times(item) for item in value]
        return inner if any(inner) else None
    return None


def pinned(result):
    return {"status": result["status"], "iterations": result["iterations"],
            "iterations_measured": result["iterations_measured"],
            "converged": result["converged"], "times": times(result)}


def perform(spec):
    """The run's pinned figures, or an error text."""
    try:
        result = simulate.run(ROOT / spec["scene"], spec["options"], ROOT / spec["platform"],
                              ROOT / spec["cost_model"], spec["cfg"], accept_out_of_memory=False,
                              threads=1)
    except simulate.SimulateError as error:
        return None, str(error)
    if not EXERCISES[spec["exercises"]](result):
        return None, f"the run no longer exercises {spec['exercises']!r}: choose another run"
    return pinned(result), None


def flatten(value, path=""):
    if isinstance(value, dict):
        out = {}
        for key, item in value.items():
            out.update(flatten(item, f"{path}.{key}" if path else key))
        return out
    if isinstance(value, list):
        out = {}
        for k, item in enumerate(value):
            out.update(flatten(item, f"{path}[{k}]"))
        return out
    return {path: value}


def differences(expected, got, most=12):
    """Lines naming each field that differs (at most `most`, then a count)."""
    e, g = flatten(expected), flatten(got)
    lines = []
    for path in sorted(set(e) | set(g), key=lambda p: (p not in e, p)):
        if path not in g:
            lines.append(f"{path}: recorded {e[path]!r}, now missing")
        elif path not in e:
            lines.append(f"{path}: new, {g[path]!r} (not recorded)")
        elif e[path] != g[path] or type(e[path]) is not type(g[path]):
            change = ""
            if isinstance(e[path], float) and isinstance(g[path], float) and e[path]:
                change = f" ({(g[path] - e[path]) / e[path]:+.3e} relative)"
            lines.append(f"{path}: recorded {e[path]!r}, now {g[path]!r}{change}")
    return lines[:most] + ([f"... and {len(lines) - most} more"] if len(lines) > most else [])


def record_path(spec):
    return GOLDENS / f"{spec['name']}.json"


def record(spec, figures):
    return {"about": "a golden run (tests/goldens/goldens.py): its simulated seconds to the last "
                     f"digit; regenerate on purpose with {REGENERATE} and say so in the commit",
            "command": " ".join(command(spec)),
            "run": {k: v for k, v in spec.items() if k != "name"},
            "pinned": figures}


def measure_all(specs):
    with ThreadPoolExecutor(2) as pool:   # one host thread per run, two runs at a time
        return list(pool.map(perform, specs))


def check():
    specs = runs()
    failures = []
    for stray in sorted(set(GOLDENS.glob("*.json")) - {record_path(s) for s in specs}):
        failures.append(f"{stray.name}: a record of no golden run (run {REGENERATE})")
    passed = 0
    for spec, (figures, error) in zip(specs, measure_all(specs)):
        name, path = spec["name"], record_path(spec)
        if error:
            failures.append(f"{name}: {error}")
        elif not path.exists():
            failures.append(f"{name}: no record {relative(path)} (run {REGENERATE})")
        else:
            recorded = json.loads(path.read_text())
            lines = differences(recorded["pinned"], figures)
            if recorded["run"] != {k: v for k, v in spec.items() if k != "name"}:
                failures.append(f"{name}: the run's definition changed since it was recorded "
                                f"(run {REGENERATE})")
            elif lines:
                failures.append(f"{name}: simulated figures differ from {relative(path)}\n  "
                                f"command: {recorded['command']}\n  " + "\n  ".join(lines))
            else:
                passed += 1
                print(f"ok   {name}: {figures['iterations']} iterations, "
                      f"{figures['times']['simulated_seconds']!r} simulated seconds")
    for failure in failures:
        print("FAIL " + failure)
    if failures:
        print(f"A simulated second changed. If that is intended, regenerate with {REGENERATE} "
              "and say so in the commit (docs/reproduce.md, \"Golden runs\").")
    print(f"goldens: {passed} passed, {len(failures)} failed")
    return 1 if failures else 0


def regenerate():
    specs = runs()
    outcomes = measure_all(specs)
    errors = [f"{s['name']}: {e}" for s, (_, e) in zip(specs, outcomes) if e]
    if errors:
        print("\n".join(errors), file=sys.stderr)
        return 1
    for stray in set(GOLDENS.glob("*.json")) - {record_path(s) for s in specs}:
        stray.unlink()
    for spec, (figures, _) in zip(specs, outcomes):
        record_path(spec).write_text(json.dumps(record(spec, figures), indent=1) + "\n")
        print(f"{relative(record_path(spec))}: {figures['iterations']} iterations, "
              f"{figures['times']['simulated_seconds']!r} simulated seconds")
    return 0


def main(argv):
    usable = (len(argv) == 3 and argv[1] == "check") or (argv[1:2] == ["regenerate"] and len(argv) <= 3)
    if argv[1:] in (["-h"], ["--help"]):
        print("usage: " + __doc__.split("usage:")[1].strip())
        return 0
    if not usable:
        print(__doc__.split("usage:")[1].strip(), file=sys.stderr)
        return 2
    os.environ["NCUBE_SIMULATE"] = str(Path(argv[2]).resolve()) if len(argv) > 2 else \
        str(ROOT / "build" / "simulate")
    return check() if argv[1] == "check" else regenerate()


if __name__ == "__main__":
    sys.exit(main(sys.argv))
