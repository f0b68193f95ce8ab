#!/usr/bin/python3
"""Regression test of the shapes of the speedup curves (issue 4), on small sweeps.

Runs short sweeps of scene0 and scene1 and checks ratios between configurations against the
values recorded in tests/expected_speedups.json (within the tolerance stated there), and the
verdicts of the paper's findings F1 to F4 on scene1, decided by the same definitions as the
report's (ncube.findings). A change of the model that bends a curve or turns a verdict fails
here and has to update the record on purpose:  tests/speedup_regression.py SIMULATE --record

usage: speedup_regression.py SIMULATE [--record]
"""

import sys  # noqa: E402
from pathlib import Path  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "analysis"))
from ncube.interpreter import use_project_python  # noqa: E402

use_project_python()   # Debian's /usr/bin/python3 (README.md, "Use")

import json
import os
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "analysis"))
sys.path.insert(0, str(Path(__file__).resolve().parent / "robustness"))
import forked_runs  # noqa: E402
from ncube import findings, paths, results  # noqa: E402
from ncube import options as opts  # noqa: E402
from ncube.paths import ROOT  # noqa: E402

EXPECTED = ROOT / "tests" / "expected_speedups.json"
ITERATIONS = 4  # scene1: enough to cover lights and first reflectors, a few seconds in all

CONFIGS = {
    "scene1": [(4, 0), (8, 0), (16, 0), (32, 0), (64, 0), (4, 1), (4, 3), (4, 7), (4, 15),
               (8, 7), (16, 3), (32, 1)],
    "scene0": [(1, 0), (8, 7), (32, 0), (16, 3)],  # to convergence (Table 5)
}


def simulate(scene, options):
    """The result of ./simulate on `scene` with `options`: the command ncube.simulate.run
    writes, forked from build/simulate_server (tests/robustness/forked_runs.py: about 85 ms of
    CPU less a run than a new ./simulate, whose own start-up the script tests try; started
    anew when no current server is built); anything but exit 0 fails."""
    with tempfile.TemporaryDirectory() as folder:
        out = Path(folder) / "result.json"
        scene_path = paths.find_input(scene, Path.cwd(), "scene") or scene
        command = opts.command(paths.simulate_binary(), scene_path, options, json_out=out,
                               threads=1)
        forked_runs.check_output(command[0], command[1:], cwd=os.getcwd(),
                                 env=paths.simulate_environment())
        return results.read(out)


def run(scene, r, v):
    options = {"R": r, "V": v, "samples": 64}   # the sweeps' samples (the default too)
    if scene == "scene0":
        return simulate(scene, options)["simulated_seconds"]
    options["iterations"] = ITERATIONS
    return simulate(scene, options)["seconds_per_iteration"]


def measure():
    jobs = [(s, r, v) for s, configs in CONFIGS.items() for r, v in configs]
    with ThreadPoolExecutor(2) as pool:
        times = list(pool.map(lambda job: run(*job), jobs))
    return {f"{s} R={r} V={v}": t for (s, r, v), t in zip(jobs, times)}


def ratios(t):
    """The shapes: speedups relative to a reference configuration of each curve."""
    s1 = lambda r, v: t[f"scene1 R={r} V={v}"]
    s0 = lambda r, v: t[f"scene0 R={r} V={v}"]
    shapes = {}
    for r in (8, 16, 32, 64):  # Table 1: time against R with V = 0
        shapes[f"scene1 V=0: t(R=4)/t(R={r})"] = s1(4, 0) / s1(r, 0)
    for v in (1, 3, 7, 15):  # Table 3: time against V at R = 4
        shapes[f"scene1 R=4: t(V=0)/t(V={v})"] = s1(4, 0) / s1(4, v)
    for r, v in ((8, 7), (16, 3), (32, 1), (64, 0)):  # Table 4: 64 nodes
        shapes[f"scene1 64 nodes: t(R=4,V=15)/t(R={r},V={v})"] = s1(4, 15) / s1(r, v)
    for r, v in ((8, 7), (32, 0), (16, 3)):  # Table 5: to convergence
        shapes[f"scene0 total: t(R=1)/t(R={r},V={v})"] = s0(1, 0) / s0(r, v)
    return shapes


def verdicts(t):
    """The findings' verdicts on scene1, by ncube.findings (the report's definitions)."""
    s1 = lambda r, v: t[f"scene1 R={r} V={v}"]
    return {
        "F1 scene1 (time falls with R at V=0, sublinearly)":
            findings.f1_holds([s1(r, 0) for r in (4, 8, 16, 32, 64)]),
        "F2 scene1 (V=1 slower than V=0 at R=4 by 0.5 % to 15 %)":
            findings.f2_holds(s1(4, 0), s1(4, 1)),
        "F3 scene1 (time falls with V at R=4 from V=1 on, sublinearly)":
            findings.f3_holds([s1(4, v) for v in (0, 1, 3, 7, 15)]),
        "F4 scene1 (64 nodes: R=8,V=7 fastest with V>0, R=32,V=1 slowest)":
            findings.f4_holds({rv: s1(*rv) for rv in findings.TABLE4_ROWS}),
    }


def main():
    if len(sys.argv) < 2 or sys.argv[1] in ("-h", "--help"):
        print("usage: speedup_regression.py SIMULATE [--record]\n" + __doc__)
        return 0 if len(sys.argv) > 1 else 2
    os.environ["NCUBE_SIMULATE"] = sys.argv[1]
    record = "--record" in sys.argv
    times = measure()
    shapes, holds = ratios(times), verdicts(times)
    if record:
        EXPECTED.write_text(json.dumps({
            "about": "Speedup ratios and findings' verdicts of tests/speedup_regression.py, "
                     "recorded with --record; a change that bends a curve or turns a verdict "
                     "must update this on purpose.",
            "relative_tolerance": 0.05,
            "ratios": {k: round(v, 4) for k, v in shapes.items()},
            "verdicts": holds}, indent=1) + "\n")
        print(f"recorded {len(shapes)} ratios and {len(holds)} verdicts in {EXPECTED}")
        return 0
    expected = json.loads(EXPECTED.read_text())
    tolerance = expected["relative_tolerance"]
    failures = 0
    for name, value in shapes.items():
        want = expected["ratios"][name]
        ok = abs(value - want) <= tolerance * want
        failures += not ok
        print(f"{'ok  ' if ok else 'FAIL'} {name}: {value:.4f} (recorded {want:.4f} +- {tolerance:.0%})")
    for name, holds_now in holds.items():
        want = expected["verdicts"][name]
        failures += holds_now != want
        print(f"{'ok  ' if holds_now == want else 'FAIL'} {name}: "
              f"{'holds' if holds_now else 'does not hold'} (recorded: "
              f"{'holds' if want else 'does not hold'})")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
