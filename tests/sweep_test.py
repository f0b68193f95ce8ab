#!/usr/bin/python3
"""Sweeps through the real Snakemake (docs/sweeps.md): validation of sweep files, a small sweep
on the local cores, results that do not belong to their cell run again, an interrupted sweep
resumes without losing a finished cell and leaves no simulation running. The path a cluster
takes (Snakemake's generic cluster mode with a submit command that runs here,
tests/sweep_local_submit.sh) is tests/sweep_shell_words_test.py's: its one cell's result
checked and its job seen in Snakemake's log."""
import contextlib
import io
import json
import os
import signal
import struct
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "analysis"))
from ncube import options, results, runner, simulate, sweep  # noqa: E402

SWEEP = [str(ROOT / "experiments" / "sweep")]
SIMULATE = os.path.abspath(os.environ.get("NCUBE_SIMULATE") or ROOT / "simulate")
failures = []


def check(condition, what):
    print(("ok   " if condition else "FAIL ") + what, flush=True)
    if not condition:
        failures.append(what)


def run_sweep(*args, timeout=240):
    return subprocess.run(SWEEP + [str(a) for a in args], capture_output=True, text=True,
                          timeout=timeout)


def check_in_process(*args):
    """experiments/sweep's own entry (ncube.runner.main, which the script calls after choosing
    its Python) run here, as a completed process: its exit code, what it printed. A refusal
    reads the sweep file and asks ./simulate, as the script does, without a Python started and
    its modules imported for each case (run_sweep covers the script itself)."""
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        code = runner.main([str(a) for a in args])
    return subprocess.CompletedProcess(args, code, out.getvalue(), err.getvalue())


def processes_mentioning(text):
    found = []
    for entry in Path("/proc").iterdir():
        if entry.name.isdigit() and int(entry.name) != os.getpid():
            try:
                command = (entry / "cmdline").read_bytes().replace(b"\0", b" ").decode()
            except OSError:
                continue
            if text in command:
                found.append(command)
    return found


def test_validation(work):
    good = {"measure": "seconds_per_iteration", "options": {"iterations": 1, "samples": 4},
            "cells": [{"scene": "scene0", "R": 1, "V": 0}, {"scene": "scene0", "R": 2, "V": 1}]}
    cases = {
        "unknown cell key": ({"bogus": 10}, "'bogus'"),
        "impossible cell (72 nodes)": ({"R": 8, "V": 8}, "72"),
        "bad value (samples 20)": ({"samples": 20}, "'samples'"),
        "R not a whole number": ({"R": 2.5}, "'R'"),
        "unknown scene": ({"scene": "nowhere"}, "'scene'"),
        "hemicube with V > 0": ({"form_factors": "hemicube", "samples": 64}, "'V'"),
        "hemicube with a ray option": ({"form_factors": "hemicube", "V": 0}, "'samples'"),
        "odd hemicube resolution": ({"form_factors": "hemicube", "hemicube_resolution": 51},
                                    "'hemicube_resolution'"),
        "hemicube option without hemicube": ({"hemicube_placement": "elements"},
                                             "'hemicube_placement'"),
        "back faces without hemicube": ({"hemicube_back_faces": "pass"}, "'hemicube_back_faces'"),
        "shooters with V > 0": ({"parallelisation": "shooters"}, "'V'"),
        "shooters with subdivision": ({"parallelisation": "shooters", "V": 0, "subdivide": True},
                                      "'subdivide'"),
        "more shooters than nodes": ({"parallelisation": "shooters", "V": 0,
                                      "shooters_per_iteration": 3}, "'shooters_per_iteration'"),
        "shooters option without shooters": ({"shooters_per_iteration": 1},
                                             "'shooters_per_iteration'"),
        # SimGrid settings are asked of ./simulate --check-settings before anything runs.
        "unknown SimGrid setting": ({"cfg": {"bogus/name": "1"}}, "Bad config key: bogus/name"),
        "unknown SimGrid value": ({"cfg": {"network/model": "bogus"}}, "network/model must be one of LV08"),
        "empty SimGrid value": ({"cfg": {"network/model": ""}}, "NAME:VALUE"),
    }
    for what, (change, expected) in cases.items():
        document = json.loads(json.dumps(good))
        document["cells"][1].update(change)
        path = work / "bad.json"
        path.write_text(json.dumps(document))
        done = check_in_process(path, "--results", work / "never", "--check")
        # a cell's place: "cells[2]" where a name is checked as written (ncube.sweep_keys)
        check(done.returncode == 2 and str(path) in done.stderr and
              ("cell 2" in done.stderr or "cells[2]" in done.stderr)
              and expected in done.stderr, f"refused at once: {what} ({done.stderr.strip()[:160]})")
    path = work / "bad.yaml"
    path.write_text("measure: seconds_per_iteration\nmesure: x\ngrid: {scene: [scene0], R: [1]}\n")
    # In process too: the script's exit 2 on a refusal is tests/sweep_shell_words_test.py's
    # (its first refused name runs experiments/sweep).
    done = check_in_process(path, "--check")
    check(done.returncode == 2 and "'mesure'" in done.stderr, "unknown top-level key refused")
    check(not (work / "never").exists(), "nothing written for a refused sweep")
    # Identity: a changed option is another cell; the same configuration twice is refused.
    (work / "a.yaml").write_text("grid: {scene: [scene0], R: [1], iterations: [1, 2]}\n")
    cells = sweep.load(work / "a.yaml").cells
    check(len({c.id for c in cells}) == 2 and cells[0].file != cells[1].file,
          "cells differing in one option have different result files")
    (work / "b.yaml").write_text("grid: {scene: [scene0, scene0.json], R: [1]}\n")
    try:
        sweep.load(work / "b.yaml")
        check(False, "the same cell twice is refused")
    except sweep.SweepError as e:
        check("same configuration" in str(e), "the same cell twice is refused")
    # A model file as a cell's scene: imported by ./simulate, its MTL part of the identity.
    models = Path(__file__).resolve().parent / "models"
    for name in ("cornell-box.obj", "cornell-box.mtl"):
        (work / name).write_bytes((models / name).read_bytes())
    (work / "m.yaml").write_text("grid: {scene: [cornell-box.obj], R: [1, 4]}\n")
    before = [c.id for c in sweep.load(work / "m.yaml").cells]
    check(len(before) == 2, "a sweep over a model file has its cells")
    (work / "cornell-box.mtl").write_text((models / "cornell-box.mtl").read_text().replace("0.725", "0.7"))
    after = [c.id for c in sweep.load(work / "m.yaml").cells]
    check(not set(before) & set(after), "editing the model's MTL makes other cells")
    (work / "m2.yaml").write_text("grid: {scene: [cornell-box.obj], R: [18]}\n")
    try:
        sweep.load(work / "m2.yaml")
        check(False, "R above a model's patches refused")
    except sweep.SweepError as e:
        check("17 patches" in str(e), f"R above a model's patches refused ({e})")
    # A .glb's external buffer is part of its identity too (the JSON chunk names it).
    document = {"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
                "nodes": [{"mesh": 0}],
                "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "material": 0}]}],
                "materials": [{"name": "lamp", "emissiveFactor": [1, 1, 1],
                               "pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.5, 0.5, 1]}}],
                "buffers": [{"byteLength": 4}, {"uri": "lamp.bin", "byteLength": 72}],
                "bufferViews": [{"buffer": 1, "byteLength": 72}],
                "accessors": [{"bufferView": 0, "componentType": 5126, "count": 6, "type": "VEC3",
                               "min": [0, 0, 0], "max": [1, 1, 1]}]}
    text = json.dumps(document).encode()
    text += b" " * (-len(text) % 4)
    (work / "lamp.glb").write_bytes(struct.pack("<III", 0x46546C67, 2, 12 + 8 + len(text) + 12) +
                                    struct.pack("<II", len(text), 0x4E4F534A) + text +
                                    struct.pack("<II", 4, 0x004E4942) + bytes(4))
    corners = [(0, 0, 0), (0, 0, 1), (1, 0, 1), (0, 1, 0), (1, 1, 0), (0, 1, 1)]
    (work / "lamp.bin").write_bytes(b"".join(struct.pack("<3f", *c) for c in corners))
    (work / "g.yaml").write_text("grid: {scene: [lamp.glb], R: [1]}\n")
    before = [c.id for c in sweep.load(work / "g.yaml").cells]
    (work / "lamp.bin").write_bytes(b"".join(struct.pack("<3f", *c) for c in reversed(corners)))
    after = [c.id for c in sweep.load(work / "g.yaml").cells]
    check(len(before) == 1 and not set(before) & set(after), "editing a .glb's external buffer makes another cell")
    # The defaults the identity writes out are simulate's own.
    result = simulate.run("scene0", {"iterations": 0})
    check(result["config"] == dict(options.config_fields({"iterations": 0}), nodes=1),
          "ncube.options defaults are those of simulate")


def test_local_sweep(work):
    """A small sweep on the local cores (tiny.yaml): a grid of scene0 at two iterations, a traced
    cell of a scene file copied here, and test_kill_and_resume's three cells. It runs in
    test_kill_and_resume's stopped run: the grid's and the traced cell finish before the stop
    (check_local_sweep), test_kill_and_resume's are stopped; the resume runs the rest, its
    spoiled cells among them (check_reruns), and writes the sweep's table (check_table)."""
    (work / "tiny.yaml").write_text(
        "measure: seconds_per_iteration\noptions: {iterations: 2, samples: 4}\n"
        "grid: {scene: [scene0], R: [1, 2, 4], V: [0]}\n"
        "cells: [{scene: scenes_copy/box.json, R: 1, trace: true, iterations: 1},\n"
        "        {scene: scene0, R: 1, iterations: 1}, {scene: scene1, R: 1, iterations: 1},\n"
        "        {scene: scene0, R: 2, iterations: 1}]\n")
    (work / "scenes_copy").mkdir()
    (work / "scenes_copy" / "box.json").write_bytes((ROOT / "scenes" / "cornell-box.json").read_bytes())


def local_cells(work):
    """tiny.yaml's cells: the grid's three (two iterations), the traced one, and the three of
    test_kill_and_resume (quick, slow, earlier)."""
    cells = sweep.load(work / "tiny.yaml").cells
    grid = [c for c in cells if c.options["iterations"] == 2]
    traced = next(c for c in cells if c.trace)
    stopped = [c for c in cells if c not in grid and c is not traced]
    return grid, traced, stopped


def check_local_sweep(work, results_dir):
    """The grid's and the traced cell, finished in a sweep that was then stopped
    (test_kill_and_resume): each a finished result of its cell. Then files that are not a
    finished result of their cell are made, run again by the resume of test_kill_and_resume,
    checked there by check_reruns (that run's exit 0 is "the sweep resumes")."""
    grid, traced, _ = local_cells(work)
    for cell in grid + [traced]:
        check(results.mismatch(results.read(results_dir / cell.file), cell) is None,
              f"{cell.file} is a finished result of its cell")
    SPOILED.update(plain=grid, traced=traced, results_dir=results_dir,
                   stamp={c.id: (results_dir / c.file).stat().st_mtime_ns for c in grid})
    (results_dir / grid[0].file).write_text('{"status": "ok"}\n')
    (results_dir / grid[1].file).write_bytes((results_dir / grid[2].file).read_bytes())
    (results_dir / traced.trace_file).unlink()


def check_table(work, results_dir):
    """After the resume: the sweep's CSV has a row per cell, its plots are written."""
    table = results_dir / "sweeps" / "tiny" / "cells.csv"
    check(table.exists() and len(table.read_text().splitlines()) ==
          1 + len(sweep.load(work / "tiny.yaml").cells), "the sweep's CSV has a row per cell")
    check(all((results_dir / "sweeps" / "tiny" / f).exists() for f in
              ("time_vs_R.png", "speedup.png", "efficiency.png", "node_breakdown.png")),
          "the sweep's plots are written")


SPOILED = {}   # test_local_sweep's cells made unfinished, for check_reruns


def check_reruns(done):
    """After a sweep run over test_local_sweep's folder with its sweep file: the files that
    are not a finished result of their cell ran again, the finished ones did not."""
    if not SPOILED:
        check(False, "test_local_sweep's folder is there to run again")
        return
    plain, traced, results_dir = SPOILED["plain"], SPOILED["traced"], SPOILED["results_dir"]
    for cell, why in ((plain[0], "a bare {status: ok}"), (plain[1], "another cell's result"),
                      (traced, "a result whose trace was deleted")):
        result = results.read(results_dir / cell.file) or {}
        config = result.get("config", {})
        own = ((config.get("R"), config.get("V"), config.get("max_iterations")) ==
               (cell.R, cell.V, cell.options["iterations"]) and
               (not cell.trace or (results_dir / cell.trace_file).exists()))
        check(own and f"sweep: {cell.file} is not a finished result of its cell" in done.stderr,
              f"{why} is not taken as done")
    # grid[2] lent its bytes to grid[1] and is itself left finished
    check((results_dir / plain[2].file).stat().st_mtime_ns == SPOILED["stamp"][plain[2].id],
          "a finished cell is not run again")


def stopped_sweep(sweep_files, results_dir, pauses, signals_dir, before_stop=None, simulate=None):
    """Runs the sweeps with cell jobs held at chosen instants (ncube.run_cell's test hook,
    NCUBE_TEST_PAUSE: {point: cell}), waits until every one is reached, calls before_stop and
    stops the sweep with SIGTERM, as Ctrl-C or a scheduler would: the instant of the stop is
    driven, not raced. Returns whether every pause was reached."""
    signals_dir.mkdir()
    environment = dict(os.environ, NCUBE_TEST_PAUSE=",".join(f"{point}:{cell.file}" for point, cell
                                                             in pauses.items()),
                       NCUBE_TEST_PAUSE_DIR=str(signals_dir),
                       NCUBE_SIMULATE=str(simulate or SIMULATE))
    # A job per pause held at once, and two more cores for the others to run meanwhile.
    process = subprocess.Popen(SWEEP + [str(f) for f in sweep_files] +
                               ["--results", str(results_dir), "--cores", str(len(pauses) + 2)],
                               stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                               env=environment)
    deadline = time.monotonic() + 240
    while (not all((signals_dir / point).exists() for point in pauses) and
           process.poll() is None and time.monotonic() < deadline):
        time.sleep(0.05)
    reached = all((signals_dir / point).exists() for point in pauses)
    if before_stop:
        before_stop(process, deadline)
    process.send_signal(signal.SIGTERM)
    process.wait(timeout=60)
    time.sleep(0.5)
    return reached


def simulations_of(cell):
    """The processes running the real ./simulate (its executable, not a wrapper) for `cell`."""
    found = []
    real = os.path.realpath(SIMULATE)
    for entry in Path("/proc").iterdir():
        try:
            if entry.name.isdigit() and os.path.realpath(entry / "exe") == real and \
                    cell.id in (entry / "cmdline").read_bytes().decode(errors="replace"):
                found.append(int(entry.name))
        except OSError:
            continue
    return found


def file_state(path):
    """What a rerun of the cell would change: the inode (a new file is renamed into place), the
    modification time and the bytes (host-time fields differ between runs)."""
    try:
        status = path.stat()
        return status.st_ino, status.st_mtime_ns, path.read_bytes()
    except OSError:
        return None


def jobs_run(results_dir, cell):
    """Whether the sweep's log (Snakemake's messages of the last run: logs/snakemake.log) shows
    a job making the cell's result file."""
    log = Path(results_dir) / "logs" / "snakemake.log"
    return f"output: {cell.file}" in (log.read_text() if log.exists() else "")


def test_kill_and_resume(work):
    # The slow cell is slow in the stopped run only: there a wrapper of ./simulate waits for
    # the test's word (a FIFO; no CPU spent meanwhile) and then has its simulation (the real
    # one, exec'd) run to convergence at 1e-10 with 64 samples (about 4,000 iterations, some
    # 15 s on one host thread), so it is running when the sweep is stopped; the resume runs
    # the cell as the sweep file has it: one iteration, a fraction of a second.
    # The cells are tiny.yaml's (test_local_sweep): the other cells of the sweep finish before
    # the stop, then some are spoiled, and the resume runs those too.
    results_dir = work / "res"
    grid, traced, (quick, slow, earlier) = local_cells(work)
    go = work / "slow-go"
    os.mkfifo(go)
    slow_simulate = work / "simulate-slow"
    slow_simulate.write_text(
        f'#!/bin/bash\ncase " $* " in *{slow.id}*) ;; *) exec {SIMULATE} "$@";; esac\n'
        f'read -r _ < {go}\n'
        'args=()\nwhile [ $# -gt 0 ]; do\n  case "$1" in\n'
        '    --iterations) args+=(--iterations 100000); shift 2;;\n'
        '    --samples) args+=(--samples 64); shift 2;;\n'
        '    --convergence) args+=(--convergence 1e-10); shift 2;;\n'
        '    *) args+=("$1"); shift;;\n  esac\ndone\n'
        f'exec {SIMULATE} "${{args[@]}}"\n')
    slow_simulate.chmod(0o755)
    seen = {}

    def before_stop(process, deadline):
        # The other cells done (the held jobs keep their cores) ...
        while not all((results_dir / c.file).exists() for c in grid + [traced]) and \
                process.poll() is None and time.monotonic() < deadline:
            time.sleep(0.05)
        # ... then the slow cell's real simulation let go, and seen running.
        while process.poll() is None and time.monotonic() < deadline:
            try:
                writer = os.open(go, os.O_WRONLY | os.O_NONBLOCK)
            except OSError:   # ENXIO: its wrapper has not opened the FIFO yet
                time.sleep(0.05)
                continue
            os.write(writer, b"go\n")
            os.close(writer)
            break
        while not simulations_of(slow) and process.poll() is None and \
                time.monotonic() < deadline:
            time.sleep(0.02)
        seen["running"] = [c for c in processes_mentioning(str(results_dir))
                           if "simulate" in c and slow.id in c and "run_cell" not in c]
        seen["real"] = simulations_of(slow)
        # A lock as a Snakemake stopped between a job's end and its bookkeeping leaves
        # behind (seen once in CI): the stopped sweep must clear it, or the resume refuses
        # the folder.
        locks = results_dir / ".snakemake" / "locks"
        locks.mkdir(parents=True, exist_ok=True)
        (locks / "9.output.lock").write_text(str(results_dir / slow.file) + "\n")

    # One stop at three instants, one per cell. The worst for the quick cell: its verified
    # file has its final name but its job has not exited, so Snakemake has not recorded it
    # (marked incomplete, a failed job's output); on a cluster this is a job cancelled after its
    # file appeared. A moment earlier for the other quick cell: its result verified under its
    # temporary name, not yet given its final name.
    reached = stopped_sweep([work / "tiny.yaml"], results_dir,
                            {"written": quick, "started": slow, "verified": earlier},
                            work / "kill-signals", before_stop, simulate=slow_simulate)
    check(reached and (results_dir / quick.file).exists() and seen["running"] and seen["real"],
          "stopped with one cell's file written (its job not exited) and a simulation running")
    check_local_sweep(work, results_dir)
    kept = file_state(results_dir / quick.file)
    check(kept is not None, "the stopped cell's file is still there")
    left = processes_mentioning(str(results_dir))
    check(not left, f"a killed sweep leaves no simulation or job running ({left[:1]})")
    check(not (results_dir / slow.file).exists() and
          not list((results_dir / "cells").glob("*.running")),
          "the interrupted cell has no result file and no temporary one")
    check(reached and not [p for p in (results_dir / "cells").iterdir()
                           if p.name.startswith(Path(earlier.file).stem)],
          "a cell stopped before its file got its name leaves no file at all")
    locks = list((results_dir / ".snakemake" / "locks").glob("*"))
    check(not locks, f"a stopped sweep leaves no Snakemake lock ({[p.name for p in locks]})")
    # The next run finishes the interrupted cells and the 3 spoiled ones only: 2 of the 7 cells
    # finished (the quick cell, 1 of the grid's), 5 to run.
    done = run_sweep(work / "tiny.yaml", "--results", results_dir, timeout=280)
    check(done.returncode == 0, f"the sweep resumes ({done.stderr[-300:]})")
    check("2 with a finished result file" in done.stdout and "5 to run" in done.stdout,
          f"the sweep decides from the result files ({done.stdout.splitlines()[:1]})")
    check_reruns(done)
    check_table(work, results_dir)
    outside = [p for p in work.rglob("*.json") if results_dir not in p.parents and
               p.parent.name != "scenes_copy" and p.name != "bad.json"]
    check(not outside, f"results only under the results folder ({outside[:2]})")
    check(file_state(results_dir / quick.file) == kept and not jobs_run(results_dir, quick),
          "the finished cell is kept (no job for it; same file, time and bytes)")
    check(jobs_run(results_dir, slow) and
          results.mismatch(results.read(results_dir / slow.file), slow) is None,
          "the interrupted cell is done after the resume")
    check(jobs_run(results_dir, earlier) and
          results.mismatch(results.read(results_dir / earlier.file), earlier) is None,
          "the cell stopped before its file got its name runs again on the resume")
    # A job started for a finished cell (a scheduler starting it twice) does not run it.
    again = subprocess.run([sys.executable, "-m", "ncube.run_cell", "plan.json", quick.file],
                           cwd=results_dir, capture_output=True, text=True, timeout=60,
                           env=dict(os.environ, PYTHONPATH=str(ROOT / "analysis")))
    check(again.returncode == 0 and "not run again" in again.stderr and
          file_state(results_dir / quick.file) == kept,
          f"a cell's job leaves a finished result alone ({again.stderr.strip()[:120]})")


def test_reproduce_check(work):
    """experiments/reproduce --check lists the paper's cells and writes nothing."""
    folder = work / "reproduce-check"
    done = subprocess.run([str(ROOT / "experiments" / "reproduce"), "--results", str(folder),
                           "--check"], capture_output=True, text=True, timeout=240)
    check(done.returncode == 0 and "table1:" in done.stdout and "timeline:" in done.stdout
          and not folder.exists(),
          f"experiments/reproduce --check lists the cells, writes nothing ({done.stderr[-200:]})")


def main():
    with tempfile.TemporaryDirectory(prefix="ncube-sweep-test-") as folder:
        work = Path(folder)
        for test in (test_validation, test_local_sweep, test_kill_and_resume,
                     test_reproduce_check):
            print(f"-- {test.__name__}", flush=True)
            test(work)
    print(f"sweep_test: {len(failures)} failure(s)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
