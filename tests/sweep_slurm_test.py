#!/usr/bin/python3
"""A sweep on a real one-node Slurm cluster (started by tests/sweep_slurm_test.sh, SLURM_CONF
set): every cell is one Slurm job whose id the sweep's log shows; the result files are the local
run's byte for byte apart from host fields; a job cancelled with scancel while its simulation
runs (held there by ncube.run_cell's NCUBE_TEST_PAUSE, not raced) leaves no result file, is
reported with its job id, state and log, and runs again when the same command is repeated; a
cell that fails (a bad model) is reported with its job id and log path while the others finish;
each job asked for its cell's own memory and time (ncube.cell_resources); a job over its memory
request is said so.

One cluster run shows all of the failures at once (the cancelled job, the failed cell, the
job over its memory) and the same command then runs them again: each sweep run costs a
Snakemake and each job a Slurm job with a Snakemake of its own, seconds each. The local results
to compare with are made by the local job's own function (ncube.run_cell.run), without a
Snakemake (tests/sweep_test.py runs local sweeps)."""
import difflib
import os
import re
import signal
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "analysis"))
from ncube import cell_resources, results, run_cell, slurm_status, sweep  # noqa: E402

SWEEP = [str(ROOT / "experiments" / "sweep")]
SIMULATE = os.path.abspath(os.environ.get("NCUBE_SIMULATE") or ROOT / "simulate")
WORK = Path(os.environ["SLURM_TEST_WORK"])
MODEL = ROOT / "tests" / "models" / "cornell-box.obj"
failures = []

# 4 cells: a scene by name, the Cornell box scene file and its model (each kind of scene a
# job must find on the cluster), with V = 0 and V > 0, every cell on 2 nodes (one node count:
# each run's answer draws two plots, not the four of a varying one). Each cell is a Slurm
# job: more cells would show nothing more and cost a job each. Then, in the same sweep (one
# answer to draw per run, not three):
# - a model the sweep accepts (it imports) but whose simulation fails: the job's ./simulate
#   (a wrapper) is handed a broken copy, as if the file had been damaged on the cluster's disk;
# - a cell over its memory request: traced, so that its rule (traced_cell) alone is asked for
#   1 MB (Snakemake's --set-resources); its job held at "verified" (run_cell's Python alone
#   holds more) until Slurm kills it.
BAD = WORK / "bad-box.obj"
STUDY = ("measure: total_seconds\noptions: {iterations: 1, samples: 4}\n"
         "cells: [{scene: scene0, R: 2, V: 0}, {scene: scene0, R: 1, V: 1},\n"
         f"        {{scene: cornell-box.json, R: 2, V: 0}}, {{scene: '{MODEL}', R: 1, V: 1}},\n"
         f"        {{scene: '{BAD}', R: 2, V: 0}}, {{scene: scene0, R: 2, V: 0, trace: true}}]\n")
CELLS = 4


def check(condition, what):
    print(("ok   " if condition else "FAIL ") + what, flush=True)
    if not condition:
        failures.append(what)


def without_host_fields(path, results_dir):
    """The file's bytes without the host-time line and with the results folder's own path
    (in the command line it records) made neutral."""
    text = path.read_text()
    text = re.sub(r'\n *"host_seconds": [^\n]*', "", text)
    return text.replace(str(results_dir), "RESULTS")


def run_sweep(command, env=None, timeout=180):
    """The sweep's completed process; past the timeout it is stopped with SIGTERM (it then
    stops its Snakemake and jobs: a SIGKILL would leave them behind)."""
    process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                               text=True, env=env)
    try:
        out, err = process.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        process.terminate()
        out, err = process.communicate()
        err += f"\n(stopped after {timeout} s)\n"
    return subprocess.CompletedProcess(command, process.returncode, out, err)


def squeue_job(name):
    done = subprocess.run(["squeue", "-h", "-n", name, "-o", "%i"], capture_output=True,
                          text=True, check=False)
    return done.stdout.strip()


def main():
    (WORK / "study.yaml").write_text(STUDY)
    bad = BAD
    bad.write_bytes(MODEL.read_bytes() + b"# a copy of its own (another identity)\n")
    (WORK / "cornell-box.mtl").write_bytes(MODEL.with_suffix(".mtl").read_bytes())
    (WORK / "garbage.obj").write_text("v 1 2\nf 1 2 3 4 5\n")
    wrapper = WORK / "simulate-broken-model"
    # Only the cell's run (--json) gets the broken copy; the sweep's import of it works.
    wrapper.write_text('#!/bin/bash\nargs=()\nfor a in "$@"; do\n'
                       f'  [ "$a" = "{bad}" ] && [[ " $* " == *" --json "* ]] && '
                       f'a="{WORK / "garbage.obj"}"\n'
                       f'  args+=("$a")\ndone\nexec {SIMULATE} "${{args[@]}}"\n')
    wrapper.chmod(0o755)
    *cells, broken, over = sweep.load(WORK / "study.yaml").cells
    check(len(cells) == CELLS and Path(broken.scene_file).name == BAD.name and over.trace,
          f"the study has {CELLS} cells ({len(cells)}), the broken and the traced one")

    local_dir = WORK / "local"
    start = time.monotonic()
    os.environ["NCUBE_SIMULATE"] = SIMULATE   # as the sweep hands it to its jobs: absolute
    handlers = {s: signal.getsignal(s) for s in (signal.SIGTERM, signal.SIGINT)}
    codes = [run_cell.run(c, local_dir) for c in cells]
    for number, handler in handlers.items():   # run_cell.run sets its own, for its job
        signal.signal(number, handler)
    check(codes == [0] * CELLS, f"the local jobs finish ({codes}, "
                                f"{time.monotonic() - start:.1f} s)")

    cluster_dir = WORK / "cluster-results"
    held = next(c for c in cells if c.scene == "scene0" and c.R == 1 and c.V == 1)
    signals = WORK / "signals"
    signals.mkdir()
    command = SWEEP + [str(WORK / "study.yaml"), "--results", str(cluster_dir), "--slurm",
                       "--", "--set-resources", "traced_cell:mem_mb=1"]
    environment = dict(os.environ, NCUBE_SIMULATE=str(wrapper),
                       NCUBE_TEST_PAUSE=f"started:{held.file},verified:{over.file}",
                       NCUBE_TEST_PAUSE_DIR=str(signals))
    start = time.monotonic()
    first = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                             env=environment)
    deadline = time.monotonic() + 120
    while not (signals / "started").exists() and first.poll() is None and \
            time.monotonic() < deadline:
        time.sleep(0.1)
    held_job = squeue_job(slurm_status.job_name(held.file))
    check((signals / "started").exists() and held_job.isdigit(),
          f"the held cell runs as Slurm job {held_job or '?'}")
    asked = subprocess.run(["scontrol", "show", "job", "--oneliner", held_job or "0"],
                           capture_output=True, text=True, check=False).stdout
    subprocess.run(["scancel", held_job], check=False)
    try:
        out, err = first.communicate(timeout=180)
    except subprocess.TimeoutExpired:
        first.terminate()
        out, err = first.communicate()
    print(f"     first cluster run: {time.monotonic() - start:.1f} s", flush=True)
    # Snakemake's messages, the jobs' submissions among them, are in the sweep's log (the
    # terminal shows a progress line: docs/sweeps.md, "Running").
    log_file = cluster_dir / "logs" / "snakemake.log"
    log = out + err + (log_file.read_text() if log_file.exists() else "")
    submitted = re.findall(r"Submitted job \d+ with external jobid '(\d+)'", log)
    check(len(submitted) == CELLS + 2 and len(set(submitted)) == CELLS + 2,
          f"one Slurm job per cell, their ids in the sweep's log ({len(submitted)} submitted)")
    if len(submitted) != CELLS + 2:
        print(err[-3000:])
    job_logs = {job: cluster_dir / "logs" / "slurm" / f"{job}.log" for job in submitted}
    nested = [job for job, path in job_logs.items()
              if path.exists() and "Building DAG" in path.read_text(errors="replace")]
    check(not nested, f"the jobs run their cells without a Snakemake of their own (the sweep's "
                      f"job script, ncube.cluster_job; a Snakemake in jobs {nested})")
    check(first.returncode == 4, f"a cancelled job, a failed cell and one over its memory: exit 4 "
                                 f"({first.returncode})")
    said = [line for line in err.splitlines() if line.startswith("sweep: ")]
    cancelled = [line for line in said if line.startswith(f"sweep: {held.file}: ")]
    check(len(cancelled) == 1 and f"Slurm job {held_job}" in cancelled[0] and
          "CANCELLED" in cancelled[0] and
          str(cluster_dir / "logs" / "slurm" / f"{held_job}.log") in cancelled[0],
          f"the cancelled cell is named with its job, state and log ({cancelled})")
    check(not (cluster_dir / held.file).exists() and
          not list((cluster_dir / "cells").glob("*.running")),
          "the cancelled job left no result file")
    failed = [line for line in said if line.startswith(f"sweep: {broken.file}: ")]
    failed_job = re.search(r"Slurm job (\d+)", failed[0]) if failed else None
    check(failed_job is not None and
          str(cluster_dir / "logs" / "slurm" / f"{failed_job.group(1)}.log") in failed[0] and
          "FAILED" in failed[0],
          f"the failed cell is named with its job id and log path ({failed})")
    if failed_job:
        job_log = (cluster_dir / "logs" / "slurm" / f"{failed_job.group(1)}.log").read_text()
        check("simulate: " in job_log and str(WORK / "garbage.obj") in job_log,
              "its log holds the simulator's message")
    said_over = [line for line in said if line.startswith(f"sweep: {over.file}: ")]
    check(len(said_over) == 1 and "it used more than its memory request" in said_over[0] and
          not (cluster_dir / over.file).exists(),
          f"a job over its memory request is said so, no result file ({said_over})")
    others = [c for c in cells if c is not held]
    check(all(results.mismatch(results.read(cluster_dir / c.file), c) is None for c in others),
          "the other cells finished")
    # ncube.cell_resources for the default platform's 64 nodes: 384 + 16 MB rounded up to
    # 448, 10 + 0.5 minutes rounded up to 11; the scheduler holds the job to them.
    check(cell_resources.request(held) == {"mem_mb": 448, "runtime": 11} and
          " MinMemoryNode=448M " in asked and " TimeLimit=00:11:00 " in asked,
          f"the job asked for its cell's memory and time ({asked[:0] or re.findall(r'MinMemoryNode=[^ ]+|TimeLimit=[^ ]+', asked)})")

    start = time.monotonic()
    second = run_sweep(command, env=dict(os.environ, NCUBE_SIMULATE=str(wrapper)))
    print(f"     second cluster run: {time.monotonic() - start:.1f} s", flush=True)
    check("3 to run" in second.stdout and second.returncode == 4,
          f"the same command runs the cancelled, the failed and the over-memory cell again "
          f"({second.returncode}: {second.stdout.splitlines()[:1]})")
    check(results.mismatch(results.read(cluster_dir / held.file), held) is None,
          "the cancelled cell is finished now")
    same = [c.file for c in cells if (cluster_dir / c.file).exists() and
            without_host_fields(cluster_dir / c.file, cluster_dir) ==
            without_host_fields(local_dir / c.file, local_dir)]
    check(len(same) == CELLS, f"the cluster's result files are the local run's byte for byte "
                              f"apart from host fields ({len(same)} of {CELLS})")
    for cell in [c for c in cells if c.file not in same][:1]:   # what differs, for the log
        if not (cluster_dir / cell.file).exists():
            print(f"     {cell.file}: no cluster result")
            continue
        print("".join(list(difflib.unified_diff(
            without_host_fields(local_dir / cell.file, local_dir).splitlines(True),
            without_host_fields(cluster_dir / cell.file, cluster_dir).splitlines(True)))[:40]))
    if failures:
        print(f"{len(failures)} check(s) failed")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
