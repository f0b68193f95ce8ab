#!/usr/bin/python3
"""How a local sweep ends when something goes wrong (docs/sweeps.md, "When a sweep stops"): a
results folder in use by a running sweep, a cell failing, an interruption and a full file
system each give one plain line saying what happened and what to do, their documented exit
code, and a last line naming only the tables written; finished cells stay valid and the same
command completes the sweep afterwards. The instants are driven (ncube.run_cell's test pause),
not raced. The cases run in turn on one sweep folder, in a private mount namespace (unshare
-rm) where the full file system is a 1 MiB tmpfs (without one, that case is skipped, saying
so)."""
import io
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "analysis"))
from ncube import outcome, results, sweep  # noqa: E402

SWEEP = [str(ROOT / "experiments" / "sweep")]
SIMULATE = os.path.abspath(os.environ.get("NCUBE_SIMULATE") or ROOT / "simulate")
failures = []

# Two cells where one that waits, then fails, and one other are all the cases need (each cell
# is a job: a Python and a ./simulate). The cases run in turn on one folder, one Snakemake run
# each: stopped, failing, full file system (the filler sized from the space left), completed.
PAIR = ("measure: total_seconds\noptions: {iterations: 1, samples: 4}\n"
        "grid: {scene: [scene0], R: [1, 2]}\n")


def check(condition, what):
    print(("ok   " if condition else "FAIL ") + what, flush=True)
    if not condition:
        failures.append(what)


def run_sweep(*args, env=None, timeout=300):
    return subprocess.run(SWEEP + [str(a) for a in args], capture_output=True, text=True,
                          timeout=timeout, env=env)


def last_line(done):
    lines = done.stdout.strip().splitlines()
    return lines[-1] if lines else ""


def plain_lines(done):
    """The sweep's own lines on stderr (Snakemake's messages are passed on around them)."""
    return [line for line in done.stderr.splitlines() if line.startswith("sweep: ")]


def paused_sweep(sweep_file, results_dir, point, cell, signals_dir):
    """A sweep whose job for `cell` waits at `point` (NCUBE_TEST_PAUSE), once it is there."""
    signals_dir.mkdir()
    environment = dict(os.environ, NCUBE_TEST_PAUSE=f"{point}:{cell.file}",
                       NCUBE_TEST_PAUSE_DIR=str(signals_dir))
    process = subprocess.Popen(SWEEP + [str(sweep_file), "--results", str(results_dir)],
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                               env=environment)
    deadline = time.monotonic() + 240
    while not (signals_dir / point).exists() and process.poll() is None and \
            time.monotonic() < deadline:
        time.sleep(0.05)
    return process, (signals_dir / point).exists()


def test_folder_in_use_then_failing(work, disk=None):
    """A sweep in use, stopped, then run again with its stopped cell failing, then fixed: one
    sweep folder for the cases, each a Snakemake run fewer than a folder of its own. With
    `disk` (in a private mount namespace: main) the fixed run first meets a full file system
    (full_disk: the folder moved onto a 1 MiB tmpfs mounted there), then completes once space
    is freed."""
    (work / "busy.yaml").write_text(PAIR)
    cells = sweep.load(work / "busy.yaml").cells
    results_dir = (disk or work) / "busy"
    first, reached = paused_sweep(work / "busy.yaml", results_dir, "started", cells[0],
                                  work / "busy-signals")
    plan = (results_dir / "plan.json").read_bytes()
    second = run_sweep(work / "busy.yaml", "--results", results_dir)
    check(reached and second.returncode == 8, f"a second sweep on a folder in use: exit 8 "
                                              f"({second.returncode})")
    check(plain_lines(second) == [f"sweep: {results_dir} is in use by another sweep (process "
                                  f"{first.pid}): wait for it to end or stop it, then run this "
                                  f"command again"],
          f"one plain line says so ({second.stderr[-300:]})")
    check(last_line(second).endswith("written: no table") and "Snakemake" not in second.stderr,
          f"nothing else is said or written ({last_line(second)})")
    check((results_dir / "plan.json").read_bytes() == plan,
          "the running sweep's plan is left alone")
    first.send_signal(signal.SIGINT)
    _, stderr = first.communicate(timeout=120)
    stopped = [line for line in stderr.splitlines() if line.startswith("sweep: ")]
    check(first.returncode == 130 and stopped == [
        "sweep: interrupted (SIGINT): the running cells were stopped; finished cells are kept; "
        "run the same command again to go on"], f"an interrupted sweep: exit 130 and one line "
                                                 f"({first.returncode}, {stopped})")
    check(not (results_dir / cells[0].file).exists(), "the interrupted cell has no result")

    # The stopped cell fails when run again (a wrapper of ./simulate refuses its R).
    failing = cells[0]
    wrapper = work / "simulate-fails-R1"
    wrapper.write_text(f'#!/bin/sh\ncase " $* " in *" --R {failing.R} "*) echo "simulate: broken '
                       f'for the test" >&2; exit 4;; esac\nexec {SIMULATE} "$@"\n')
    wrapper.chmod(0o755)
    done = run_sweep(work / "busy.yaml", "--results", results_dir,
                     env=dict(os.environ, NCUBE_SIMULATE=str(wrapper)))
    check(done.returncode == 4, f"a cell failing: exit 4 ({done.returncode})")
    said = plain_lines(done)
    check(len(said) == 1 and said[0].startswith(f"sweep: 1 cell(s) failed: {failing.file}; their "
                                                f"messages are above and in ") and
          said[0].endswith("the other cells finished and are kept; fix the cause and run the "
                           "same command again"), f"one plain line names the cell ({said[:1]})")
    check("simulate: broken for the test" in done.stderr, "the cell's own message is shown")
    folder = results_dir / "sweeps" / "busy"
    check(last_line(done).endswith(f"written: {folder / 'summary.csv'}, {folder / 'summary.md'}")
          and not (folder / "cells.csv").exists() and
          f"R={failing.R} V=0 failed" in (folder / "summary.md").read_text(),
          f"the last line names the answer (the failed cell in it), not the complete table, "
          f"which was not written ({last_line(done)})")
    others = [c for c in cells if c is not failing]
    check(all(results.mismatch(results.read(results_dir / c.file), c) is None for c in others)
          and not (results_dir / failing.file).exists(), "the other cells finished")

    kept = others
    if disk:   # fixed, but the file system full: then freed
        kept = full_disk(work, results_dir, disk, cells)
    done = run_sweep(work / "busy.yaml", "--results", results_dir)
    check(done.returncode == 0 and f"{len(kept)} with a finished result file" in done.stdout and
          f"{len(cells) - len(kept)} to run" in done.stdout and
          results.mismatch(results.read(results_dir / failing.file), failing) is None,
          f"once fixed, the same command runs only the cells without a finished result "
          f"({done.stdout.splitlines()[:1]})")
    check(done.returncode == 0 and last_line(done).endswith(
        f"written: {folder / 'cells.csv'}, {folder / 'summary.csv'}, {folder / 'summary.md'}"),
        f"the same command completes it and names its table ({last_line(done)})")


def full_disk(work, results_dir, disk, cells):
    """The fixed sweep run again with its folder on a 1 MiB tmpfs all but full (about 90 KiB
    left): exit 5, one plain line, no table; the cells written are finished results. The
    folder is moved there first (its path unchanged: the same command), the filler removed
    afterwards. Returns the cells with a finished result."""
    sweep_file = work / "busy.yaml"
    shutil.move(results_dir, work / "stash")
    subprocess.run(["mount", "-t", "tmpfs", "-o", "size=1m", "tmpfs", str(disk)], check=True)
    shutil.move(work / "stash", results_dir)
    free = os.statvfs(disk)
    filler = disk / "filler"
    filler.write_bytes(bytes(max(0, free.f_bavail * free.f_frsize - 90 * 1024)))
    done = run_sweep(sweep_file, "--results", results_dir)
    check(done.returncode == 5 and "1 to run" in done.stdout,
          f"a full file system: exit 5; the failed cell is the one to run ({done.returncode})")
    said = plain_lines(done)
    check(len(said) == 1 and
          said[0].startswith(f"sweep: the file system of {results_dir} is full (")
          and said[0].endswith("KiB free): finished cells are kept; free some space and run the "
                               "same command again"), f"one plain line says so ({said[:1]})")
    check("Traceback" not in done.stderr and "Logging error" not in done.stderr,
          "no traceback")
    table = results_dir / "sweeps" / sweep_file.stem / "cells.csv"
    check(last_line(done).endswith("written: no table") and not table.exists(),
          f"the last line names no table, none was written ({last_line(done)})")
    kept = [c for c in cells if (results_dir / c.file).exists()]
    check(all(results.mismatch(results.read(results_dir / c.file), c) is None for c in kept),
          f"the cells written are finished results ({len(kept)} of {len(cells)})")
    filler.unlink()
    return kept


def in_namespace(folder):
    """Run in a private mount namespace (unshare -rm): the cases, the full file system among
    them (a tmpfs mounted on `disk`, the folder that holds the sweep folder)."""
    work = Path(folder)
    disk = work / "disk"
    disk.mkdir()
    test_folder_in_use_then_failing(work, disk)
    return 1 if failures else 0


def test_logging_tracebacks_dropped(_work):
    """Snakemake's logging on a full disk prints Python's "--- Logging error ---" blocks (a
    traceback, the call stack, the message): the sweep does not pass them on, but notes the
    full disk; the lines around them are passed on unchanged."""
    script = ("import errno, logging, sys\n"
              "class Full:\n"
              "    def write(self, text):\n"
              "        raise OSError(errno.ENOSPC, 'No space left on device')\n"
              "    def flush(self):\n"
              "        pass\n"
              "logging.getLogger().addHandler(logging.StreamHandler(Full()))\n"
              "print('before', file=sys.stderr, flush=True)\n"
              "logging.getLogger().error('a job finished')\n"
              "print('after', file=sys.stderr, flush=True)\n")
    process = subprocess.Popen([sys.executable, "-c", script], stderr=subprocess.PIPE)
    captured, saved = io.StringIO(), sys.stderr
    sys.stderr = captured
    try:
        messages = outcome.SnakemakeMessages(process.stderr)
        process.wait(timeout=60)
        messages.wait()
    finally:
        sys.stderr = saved
    check(captured.getvalue() == "before\nafter\n" and messages.full,
          f"logging tracebacks are not passed on, the full disk is noted ({captured.getvalue()!r})")


def main():
    if sys.argv[1:2] == ["--in-namespace"]:
        return in_namespace(sys.argv[2])
    os.environ["NCUBE_SIMULATE"] = SIMULATE
    with tempfile.TemporaryDirectory(prefix="ncube-sweep-failures-") as folder:
        work = Path(folder)
        print("-- test_logging_tracebacks_dropped", flush=True)
        test_logging_tracebacks_dropped(work)
        print("-- test_folder_in_use_then_failing", flush=True)
        inside = work / "namespace"
        inside.mkdir()
        probe = subprocess.run(["unshare", "-rm", "mount", "-t", "tmpfs", "tmpfs", str(inside)],
                               capture_output=True, text=True)
        if probe.returncode != 0:
            print(f"skip full file system: no private mount namespace here "
                  f"({probe.stderr.strip()[:120]})", flush=True)
            test_folder_in_use_then_failing(work)
        else:
            done = subprocess.run(["unshare", "-rm", sys.executable, __file__, "--in-namespace",
                                   str(inside)], capture_output=True, text=True, timeout=500)
            sys.stdout.write(done.stdout)
            check(done.returncode == 0, f"the cases ran, the full file system among them "
                                        f"({done.stderr[-300:]})")
    print(f"sweep_failures_test: {len(failures)} failure(s)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
