"""Computes one cell of a sweep: the job Snakemake runs (locally or on a cluster node).

usage: python3 -m ncube.run_cell PLAN CELL_FILE     (in the results folder)

Runs ./simulate into temporary names, checks that the result is complete and belongs to the
cell (ncube.results.mismatch), and only then gives it its final name: a killed job leaves no
file that could be taken as done. A cell whose verified result is already there is not run
again (a job a scheduler starts twice). The simulation dies with this job (it is told so by the
kernel, prctl PR_SET_PDEATHSIG), so a killed sweep leaves no simulation running.

For the tests, NCUBE_TEST_PAUSE="POINT:CELL_FILE[,POINT:CELL_FILE...]" with
NCUBE_TEST_PAUSE_DIR=DIR stops a cell's job at a chosen instant until it is killed: it writes
DIR/POINT (holding the cell's file) and waits. The points, in order: "started" (the simulation
runs), "verified" (its result checked, still under the temporary name), "written" (the result
has its final name; the job has not exited, so Snakemake has not recorded it)."""
import ctypes
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

from . import input_file, output_file, paths, results
from .sweep import Cell, protect_plan_inputs

PR_SET_PDEATHSIG = 1


def _die_with_parent():
    ctypes.CDLL(None, use_errno=True).prctl(PR_SET_PDEATHSIG, signal.SIGTERM)


def find_cell(plan_path, cell_file):
    """The cell, and whether it may replace a finished result (reruns forced)."""
    try:
        plan = input_file.read_json(plan_path, "sweep plan", input_file.SCENE_FILE_BYTES)
    except input_file.InputFileError as e:
        raise SystemExit(f"run_cell: {e}") from None
    protect_plan_inputs(plan_path, plan)
    for sweep in plan["sweeps"]:
        for cell in sweep["cells"]:
            if cell["file"] == cell_file:
                return Cell.from_dict(cell), plan.get("rerun_finished", False)
    raise SystemExit(f"run_cell: {cell_file} is not a cell of {plan_path}")


def pause_for_test(point, cell):
    """The tests' hook (module docstring): returns at once unless this point of this cell is
    asked for; then waits for the signal that stops the job."""
    asked = os.environ.get("NCUBE_TEST_PAUSE", "")
    if f"{point}:{cell.file}" not in asked.split(","):
        return
    output_file.write(Path(os.environ["NCUBE_TEST_PAUSE_DIR"]) / point, cell.file + "\n")
    while True:
        time.sleep(3600)


def finished(cell, results_dir):
    """Whether the cell's verified result (and trace, for a traced cell) is there."""
    if results.mismatch(results.read(results_dir / cell.file), cell) is not None:
        return False
    return not cell.trace or results.trace_mismatch(results_dir / cell.trace_file) is None


def run(cell, results_dir=".", rerun_finished=False):
    results_dir = Path(results_dir).resolve()   # absolute paths in the command line
    final = results_dir / cell.file
    if not rerun_finished and finished(cell, results_dir):
        print(f"run_cell: {cell.file} is already a finished result of its cell: not run again",
              file=sys.stderr)
        return 0
    final.parent.mkdir(parents=True, exist_ok=True)
    temporary = final.with_name(final.name + ".running")
    trace_final = results_dir / cell.trace_file if cell.trace else None
    trace_temporary = trace_final.with_name(trace_final.name + ".running") if cell.trace else None
    command = cell.command(temporary, trace_temporary)
    child = subprocess.Popen(command, env=paths.simulate_environment(), stdout=subprocess.DEVNULL,
                             stderr=subprocess.PIPE, text=True, preexec_fn=_die_with_parent)

    def stop(signum, _frame):
        child.terminate()
        child.wait()
        for path in (temporary, trace_temporary):
            if path:
                path.unlink(missing_ok=True)
        sys.exit(128 + signum)

    signal.signal(signal.SIGTERM, stop)
    signal.signal(signal.SIGINT, stop)
    pause_for_test("started", cell)
    _, stderr = child.communicate()
    if child.returncode not in (0, 3):   # 3: out of memory, a finished cell
        sys.stderr.write(f"run_cell: {cell.file}: simulate exited with {child.returncode}:\n"
                         f"{stderr}  command: {' '.join(map(str, command))}\n")
        return 1
    problem = results.mismatch(results.read(temporary), cell)
    if problem is None and cell.trace and child.returncode == 0:
        problem = results.trace_mismatch(trace_temporary)
    if problem:
        sys.stderr.write(f"run_cell: {cell.file}: the result does not belong to the cell: {problem}\n")
        return 1
    pause_for_test("verified", cell)
    if cell.trace and trace_temporary.exists():
        output_file.move(trace_temporary, trace_final)
    elif cell.trace:   # out of memory: no timeline; an empty one marks the cell done
        output_file.write(trace_final, '{"traceEvents": []}\n')
    output_file.move(temporary, final)
    pause_for_test("written", cell)
    return 0


def main():
    plan, cell_file = sys.argv[1], sys.argv[2]
    cell, rerun_finished = find_cell(plan, cell_file)
    return run(cell, rerun_finished=rerun_finished)


if __name__ == "__main__":
    sys.exit(main())
