#!/usr/bin/python3
"""Regression test of the shapes of the speedup curves (issue 4), on small sweeps.

Runs short sweeps of scene0 and scene1 and checks ratios between configurations against the
values recorded in tests/expected_speedups.json (within the tolerance stated there), and the
orderings of the paper's findings F1 to F4. A change of the model that bends a curve fails
here and has to update the record on purpose:  tests/speedup_regression.py --record

usage: speedup_regression.py SIMULATE [--record]
"""
import json
import subprocess
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
EXPECTED = ROOT / "tests" / "expected_speedups.json"
ITERATIONS = 4  # scene1: enough to cover lights and first reflectors, a few seconds in all
SAMPLES = 64    # as in the sweeps of experiments/

CONFIGS = {
    "scene1": [(4, 0), (8, 0), (16, 0), (32, 0), (64, 0), (4, 1), (4, 3), (4, 7), (4, 15),
               (8, 7), (16, 3), (32, 1)],
    "scene0": [(1, 0), (8, 7), (32, 0), (16, 3)],  # to convergence (Table 5)
}


def run(simulate, scene, r, v, workdir):
    out = Path(workdir) / f"{scene}-{r}-{v}.json"
    args = [simulate, str(ROOT / "scenes" / f"{scene}.json"), "--R", str(r), "--V", str(v),
            "--samples", str(SAMPLES), "--json", str(out), "--quiet"]
    if scene != "scene0":
        args += ["--iterations", str(ITERATIONS)]
    subprocess.run(args, check=True, env={"NCUBE_ROOT": str(ROOT), "PATH": "/usr/bin:/bin"})
    result = json.loads(out.read_text())
    if scene == "scene0":
        return result["simulated_seconds"]
    return sum(result["seconds_per_iteration"]) / len(result["seconds_per_iteration"])


def measure(simulate):
    jobs = [(s, r, v) for s, configs in CONFIGS.items() for r, v in configs]
    with tempfile.TemporaryDirectory() as workdir, ThreadPoolExecutor(2) as pool:
        times = list(pool.map(lambda job: run(simulate, *job, workdir), jobs))
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


def orderings(t):
    s1 = lambda r, v: t[f"scene1 R={r} V={v}"]
    with_v = [(4, 15), (8, 7), (16, 3), (32, 1)]  # Table 4's 64-node configurations with V>0
    return {
        "F1 scene1: time falls with R (V=0)":
            all(s1(a, 0) > s1(b, 0) for a, b in ((4, 8), (8, 16), (16, 32), (32, 64))),
        "F1 scene1: sublinearly from R=4 to R=64": s1(4, 0) / s1(64, 0) < 16,
        "F2 scene1: V=1 slower than V=0 at R=4": s1(4, 1) > s1(4, 0),
        "F3 scene1: time falls with V at R=4":
            all(s1(4, a) > s1(4, b) for a, b in ((1, 3), (3, 7), (7, 15))),
        "F3 scene1: sublinearly (V=15 less than 16x faster than V=0)": s1(4, 0) / s1(4, 15) < 16,
        "F4 scene1: on 64 nodes R=8,V=7 fastest and R=32,V=1 slowest of those with V>0":
            min(with_v, key=lambda c: s1(*c)) == (8, 7) and
            max(with_v, key=lambda c: s1(*c)) == (32, 1),
    }


def main():
    simulate, record = sys.argv[1], "--record" in sys.argv
    times = measure(simulate)
    shapes = ratios(times)
    if record:
        EXPECTED.write_text(json.dumps({
            "about": "Speedup ratios of tests/speedup_regression.py, recorded with --record; "
                     "a change that bends a curve must update this on purpose.",
            "relative_tolerance": 0.05,
            "ratios": {k: round(v, 4) for k, v in shapes.items()}}, indent=1) + "\n")
        print(f"recorded {len(shapes)} ratios in {EXPECTED}")
        return 0
    expected = json.loads(EXPECTED.read_text())
    tolerance = expected["relative_tolerance"]
    failures = 0
    for name, value in shapes.items():
        want = expected["ratios"][name]
        ok = abs(value - want) <= tolerance * want
        failures += not ok
        print(f"{'ok  ' if ok else 'FAIL'} {name}: {value:.4f} (recorded {want:.4f} +- {tolerance:.0%})")
    for name, holds in orderings(times).items():
        failures += not holds
        print(f"{'ok  ' if holds else 'FAIL'} {name}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
