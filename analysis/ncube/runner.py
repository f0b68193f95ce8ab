"""Runs sweeps through Snakemake (docs/sweeps.md): two local cores by default, a Slurm cluster
with --slurm (sbatch through Snakemake's generic cluster mode), any other cluster with --cluster
or a Snakemake profile.

usage: experiments/sweep SWEEP.yaml [SWEEP.json ...] [--results DIR] [--cores N]
                         [--slurm | --profile DIR | --cluster CMD] [--jobs N] [--check]
                         [-- more snakemake arguments]

Every sweep file is validated first (exit 2 with the file, cell and key at the first error).
The cells of all sweeps go to DIR/cells/ (traced ones to DIR/traced/), named after their
identity, so a cell in several sweeps runs once; DIR/sweeps/<name>/ gets each sweep's CSV and
plots. Interrupt it (Ctrl-C, SIGTERM) and run it again: finished cells are kept, the running
ones are stopped with their simulations and start again. A failure ends with one plain line
saying what happened and what to do, and an exit code (ncube.outcome, docs/sweeps.md); the last
line names the tables this run wrote."""
import argparse
import base64
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from . import (cell_resources, outcome, output_file, paths, progress, results, shell_words,
               slurm_status, summary)
from .sweep import SweepError, load_all

SNAKEFILE = paths.EXPERIMENTS / "Snakefile"
SNAKEMAKE = "/usr/bin/snakemake"


def write_plan(sweeps, results_dir, pending, rerun_finished=False):
    """The plan Snakemake reads: every sweep with its cells, the result files of the cells to
    run ("pending"; the Snakefile's cell rules make only those) and whether a cell's job may
    replace a finished result (only when Snakemake is told to force reruns)."""
    plan = results_dir / "plan.json"
    text = json.dumps({"sweeps": [s.to_dict() for s in sweeps],
                       "pending": [c.file for c in pending],
                       "resources": {c.file: cell_resources.request(c)
                                     for s in sweeps for c in s.cells},
                       "rerun_finished": rerun_finished}, indent=1) + "\n"
    output_file.write(plan, text)
    return plan


def discard_unfinished(cells, results_dir="."):
    """A result file counts as done only when it is complete and belongs to its cell: any
    other file at a cell's name is moved aside (to <name>.rejected) so the cell runs again."""
    rejected = []
    for cell in cells:
        path = Path(results_dir) / cell.file
        if not path.exists():
            continue
        problem = results.mismatch(results.read(path), cell)
        if problem is None and cell.trace:
            problem = results.trace_mismatch(Path(results_dir) / cell.trace_file)
        if problem:
            os.replace(path, path.with_name(path.name + ".rejected"))
            rejected.append((cell.file, problem))
    for file, problem in rejected:
        print(f"sweep: {file} is not a finished result of its cell ({problem}): it runs again",
              file=sys.stderr)
    return rejected


def adopt_legacy_names(cells, results_dir="."):
    """A result written under a cell's former name (the scene, R and V only:
    ncube.cell_names.legacy_file) gets the cell's present name when none is there, its trace
    too; discard_unfinished then checks it as any other. So a results folder of an earlier
    version goes on where it stopped, and nothing is run again for the new names."""
    adopted = 0
    for cell in cells:
        old, new = Path(results_dir) / cell.legacy_file, Path(results_dir) / cell.file
        if old == new or new.exists() or not old.exists():
            continue
        if cell.trace:
            old_trace = old.with_name(old.name[:-len(".json")] + ".trace.json")
            if old_trace.exists():
                os.replace(old_trace, Path(results_dir) / cell.trace_file)
        os.replace(old, new)
        adopted += 1
    if adopted:
        print(f"sweep: {adopted} result file(s) of an earlier naming renamed to their cells' "
              f"present names (docs/sweeps.md, \"A cell's identity\")", file=sys.stderr)
    return adopted


def cells_to_run(sweeps, results_dir, rerun_all=False):
    """The sweep's own decision of what runs, made from the result files before Snakemake
    starts: a cell runs unless its verified result file is there (discard_unfinished moves any
    other file aside first). A cell that is not to run is no job's output, so Snakemake's own
    bookkeeping (an incomplete mark left by a stop at any instant, a touch, the deletion of a
    failed job's outputs) can neither run it again nor delete its file. A sweep's table is made
    again when one of its cells has no result. `rerun_all` (Snakemake's --forceall or
    --forcerun asked for) hands every cell to Snakemake, which then decides."""
    cells = list({c.id: c for s in sweeps for c in s.cells}.values())
    adopted = adopt_legacy_names(cells, results_dir)
    discard_unfinished(cells, results_dir)
    missing = {c.file for c in cells if not (Path(results_dir) / c.file).exists()}
    for sweep in sweeps:
        folder = Path(results_dir) / "sweeps" / sweep.name
        # The table is made again when a cell has no result, when the answer (summary.md) is
        # missing (a folder of an earlier version) or when results were renamed (its file column).
        if any(c.file in missing for c in sweep.cells) or adopted or \
                not (folder / "summary.md").exists():
            (folder / "cells.csv").unlink(missing_ok=True)
    return [c for c in cells if rerun_all or c.file in missing]


FORCING = ("-F", "--forceall", "-R", "--forcerun")


def dry_run(snakemake_arguments):
    """Snakemake asked only to say what it would do: no answer (no cell ran)."""
    return any(a in ("-n", "--dry-run", "--dryrun") for a in snakemake_arguments)


def forces_reruns(snakemake_arguments):
    return any(a in FORCING or a.startswith("--forcerun=") for a in snakemake_arguments)


def snakemake_command(plan, results_dir, args):
    # Which cells run is decided before (cells_to_run); Snakemake's own bookkeeping only
    # concerns the cells to run and the tables. --ignore-incomplete: a cell's file appears only
    # verified (ncube.run_cell), so an incomplete mark Snakemake left on one is no reason to
    # refuse the folder. --keep-incomplete: a job stopped between giving its verified file the
    # final name and exiting keeps that file (Snakemake deletes the outputs of every job it sees
    # fail, and a stopped job is one); the next run then finds the cell finished.
    # --rerun-triggers mtime with no declared inputs: the identity in the file name decides.
    # The plan is named relative to the results folder, Snakemake's working folder: a path in
    # --config is parsed by Snakemake (a newline in it would be lost), and the folder is named
    # once, by --directory.
    command = [SNAKEMAKE, "--snakefile", str(SNAKEFILE), "--directory", str(results_dir),
               "--config", f"plan={plan.relative_to(results_dir)}", "--ignore-incomplete", "--keep-incomplete",
               "--rerun-triggers", "mtime",
               "--keep-going", "--cores", str(args.cores)]
    if args.slurm:
        command += slurm_arguments(results_dir) + ["--jobs", str(args.jobs)]
    if args.profile:
        command += ["--profile", str(args.profile)]
    if args.cluster:
        command += ["--cluster", args.cluster, "--jobs", str(args.jobs)]
    return command + args.snakemake


SLURM_LOGS = Path("logs") / "slurm"
# Snakemake writes a job's folder into its job script as '...\n...' (tests/sweep_shell_words_test.py),
# which a shell reads as a backslash and an n: such a results folder is refused up front.
CONTROL_CHARACTER = re.compile(r"[\x00-\x1f\x7f]")
# Snakemake's cluster modes run '<submit command> "<job script>"' through a shell, the job script
# inside the results folder: there the characters a shell reads inside double quotes would run.
CLUSTER_UNSAFE = re.compile(r'["$`\\]')


def slurm_arguments(results_dir):
    """Snakemake's generic cluster mode with sbatch, a status command and scancel (not its
    built-in --slurm executor, which needs $USER and, with an account, slurmdbd accounting:
    docs/sweeps.md, "Running on a cluster"). One single-core job per cell with the cell's own
    memory and time (ncube.cell_resources); its output goes to logs/slurm/<job id>.log."""
    log = str(results_dir / SLURM_LOGS).replace("%", "%%") + "/%j.log"  # %j: sbatch's job id
    submit = ("sbatch --parsable --job-name=ncube-{rule}-{wildcards.name} --cpus-per-task=1 "
              "--mem={resources.mem_mb} --time={resources.runtime} "
              f"--chdir={shell_words.template_word(results_dir)} "
              f"--output={shell_words.template_word(log)}")
    status = (f"env PYTHONPATH={shell_words.template_word(paths.ANALYSIS)} "
              "/usr/bin/python3 -m ncube.slurm_status")
    return ["--cluster", submit, "--cluster-status", status, "--cluster-cancel", "scancel",
            "--jobscript", str(results_dir / SLURM_JOB_SCRIPT)]


SLURM_JOB_SCRIPT = Path("slurm_job.sh")
SNAKEMAKE_INCOMPLETE = Path(".snakemake") / "incomplete"   # Snakemake's own marks


def forget_ended_jobs(results_dir, pending):
    """Snakemake marks a cluster job's outputs incomplete with the job's id, and its next run
    resumes that job instead of submitting the cell again (snakemake/persistence.py, started:
    one file per output, named by the output's path in URL-safe base64, holding
    {"external_jobid": ...}): right while the job still runs (a sweep killed with kill -9),
    wrong once it has ended, when the cell would be reported failed again without running (a
    job killed over its memory or its time). The marks of the cells to run whose Slurm job has
    ended go, so that the same command runs those cells again."""
    folder = Path(results_dir) / SNAKEMAKE_INCOMPLETE
    if not folder.is_dir():
        return
    for cell in pending:
        files = [cell.file] + ([cell.trace_file] if cell.trace else [])
        marks = [folder / base64.urlsafe_b64encode(f.encode()).decode() for f in files]
        jobs = set()
        for mark in marks:
            try:
                jobs.add(str(json.loads(mark.read_text()).get("external_jobid") or ""))
            except (OSError, ValueError, AttributeError):
                continue
        running = [job for job in jobs if job and
                   (slurm_status.state(job.split(";")[0]) or ("",))[0] in slurm_status.RUNNING]
        if not running:
            for mark in marks:
                mark.unlink(missing_ok=True)


def write_job_script(results_dir, plan):
    """The template of each cell's Slurm job script (Snakemake's --jobscript, which fills in
    {properties}: the job's rule and output): ncube.cluster_job runs the cell on the node, as
    the rule's command does, where Snakemake's own template starts a Snakemake in every job
    (seconds and about 100 MB each). sbatch starts the job in the results folder (--chdir); the
    status command, not the script's exit code alone, tells Snakemake how it ended."""
    text = ("#!/bin/sh\n# properties = {properties}\n"
            f"PYTHONPATH={shell_words.template_word(paths.ANALYSIS)} exec /usr/bin/python3 -m "
            f"ncube.cluster_job \"$0\" "
            f"{shell_words.template_word(Path(plan).relative_to(results_dir))}\n")
    output_file.write(Path(results_dir) / SLURM_JOB_SCRIPT, text)


SNAKEMAKE_LOG = Path("logs") / "snakemake.log"
SNAKEMAKE_LOCKS = Path(".snakemake") / "locks"   # Snakemake's own, in its working folder


def run_snakemake(command, results_dir=None, pending=(), verbose=True):
    """Runs Snakemake in its own process group; a signal to this process stops the group, so
    no job and no simulation outlives the sweep (then outcome.Interrupted is raised). Returns
    Snakemake's exit status and its messages (outcome.SnakemakeMessages). Everything Snakemake
    and its jobs say goes to <results>/logs/snakemake.log (written under a temporary name, put
    in place by the output rule at the end); the terminal gets it too with `verbose`, else one
    progress line (ncube.progress) over the result files of `pending` and a failed cell's own
    message."""
    log_stream = log_temporary = None
    if results_dir is not None:
        (Path(results_dir) / SNAKEMAKE_LOG.parent).mkdir(parents=True, exist_ok=True)
        descriptor, log_temporary = tempfile.mkstemp(prefix=SNAKEMAKE_LOG.name + ".partial-",
                                                     dir=Path(results_dir) / SNAKEMAKE_LOG.parent)
        log_stream = os.fdopen(descriptor, "wb")
    process = subprocess.Popen(command, start_new_session=True, stdout=subprocess.PIPE,
                               stderr=subprocess.STDOUT)
    shown = None if verbose or not pending else progress.Progress(results_dir, pending,
                                                   lambda: messages.failed_cells)
    messages = outcome.SnakemakeMessages(process.stdout, log_stream, verbose,
                                         shown.show if shown else None)
    if shown:
        shown.begin()

    def keep_log():
        if shown:
            shown.end()
        if log_stream is not None:
            log_stream.close()
            try:
                output_file.move(log_temporary, Path(results_dir) / SNAKEMAKE_LOG)
            except OSError:   # a full disk: said by the plain line; the partial log stays
                pass

    def ended():
        """Whether Snakemake has exited, its status left for Popen to collect. Not Popen.poll:
        this runs in a signal handler that may have interrupted process.wait(), which holds the
        lock poll needs, and poll then says "running" until the grace is over."""
        try:
            return os.waitid(os.P_PID, process.pid,
                             os.WEXITED | os.WNOHANG | os.WNOWAIT) is not None
        except ChildProcessError:   # already collected
            return True

    def stop(signum, _frame):
        for sig, grace in ((signal.SIGTERM, 10.0), (signal.SIGKILL, 0.0)):
            try:
                os.killpg(process.pid, sig)
            except ProcessLookupError:
                break
            deadline = time.monotonic() + grace
            while not ended() and time.monotonic() < deadline:
                time.sleep(0.1)
        # Jobs of the group may outlive Snakemake itself by a moment.
        try:
            os.killpg(process.pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
        messages.wait()
        keep_log()
        # A Snakemake stopped in the middle of a job's ending (or killed after the grace) can
        # leave its lock behind, and the next run would refuse the folder. The lock is this
        # run's own (no other sweep holds the folder while this one runs: hold_folder), so it
        # goes, as Snakemake's --unlock removes it (its locks folder, snakemake/persistence.py,
        # cleanup_locks) without a second Snakemake started for it (seconds after a Ctrl-C).
        if results_dir is not None:
            shutil.rmtree(Path(results_dir) / SNAKEMAKE_LOCKS, ignore_errors=True)
        raise outcome.Interrupted(signum)

    signal.signal(signal.SIGINT, stop)
    signal.signal(signal.SIGTERM, stop)
    status = process.wait()
    messages.wait()
    keep_log()
    return status, messages


def bounded(low, high):
    """An argparse type: a whole number in [low, high] (argparse says which option, and exits 2)."""
    def whole_number(text):
        try:
            value = int(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"{text!r} is not a whole number") from None
        if not low <= value <= high:
            raise argparse.ArgumentTypeError(f"{value} is not in {low}..{high}")
        return value
    return whole_number


def not_written(error, results_dir):
    """The plain line and exit code of the runner's own writes failing."""
    if isinstance(error, output_file.OutputIsInputError):   # as ./simulate: a bad output path
        outcome.say(str(error))
        return 2
    if outcome.is_full(error):
        return outcome.say_full(results_dir)
    outcome.say(f"{error.filename or results_dir}: cannot be written: {error.strerror or error}")
    return outcome.NOT_WRITTEN


# How long the cluster may take to answer `sinfo` before --slurm gives up (a busy controller
# answers in well under a second; one that is down makes sinfo retry for its MessageTimeout).
SLURM_ANSWER_SECONDS = 5


def slurm_answers():
    """None when the Slurm cluster answers `sinfo`, else why not (one line)."""
    try:
        answer = subprocess.run(["sinfo", "--noheader", "--format=%P"], capture_output=True,
                                text=True, timeout=SLURM_ANSWER_SECONDS, check=False)
    except FileNotFoundError:
        return "sinfo is not installed (Debian: slurm-client)"
    except subprocess.TimeoutExpired:
        return f"sinfo did not answer in {SLURM_ANSWER_SECONDS} s"
    if answer.returncode != 0:
        lines = [line for line in answer.stderr.splitlines() if line.strip()]
        return lines[-1] if lines else f"sinfo exited {answer.returncode}"
    return None


HELP = """Runs the cells of sweep files (YAML or JSON: docs/sweeps.md) through Snakemake: on two
local cores by default, on a Slurm cluster with --slurm, on any other cluster with --cluster or
a Snakemake profile. Every file is checked first; nothing is written when one is refused."""

HELP_END = """Results go to the folder given by --results, by default ./results (in the current folder):
  RESULTS/cells/            one result file per cell, named after the cell and its identity
  RESULTS/sweeps/NAME/      summary.md and summary.csv (the answer), cells.csv, the plots
  RESULTS/logs/snakemake.log  everything Snakemake and the cells' jobs said (--verbose: shown)
At the end the terminal shows each sweep's answer: its cells sorted by the measure, the best
of each series marked. Run the same command again to go on after a stop: finished cells are
kept. Exit codes: 0 done, 2 a sweep file refused, 4 a cell failed, 5 the results folder not
writable, 7 Snakemake failed, 8 the folder in use, 128 + N stopped by signal N.
After "--", arguments go to Snakemake itself (e.g. -- --dry-run)."""


def main(argv=None):
    """experiments/sweep; a closed standard output (`--check | head`) ends it quietly, as a
    closed pipe ends any command: exit 128 + SIGPIPE, no traceback."""
    try:
        return run(argv)
    except BrokenPipeError:
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 128 + signal.SIGPIPE


def simulator_missing():
    """Why the cells could not run ./simulate (its binary not built, or $NCUBE_SIMULATE not
    a program), else None: said once, before Snakemake starts a job per cell."""
    binary = Path(paths.simulate_binary())
    if binary == paths.ROOT / "simulate":   # the wrapper runs build/simulate
        binary = paths.ROOT / "build" / "simulate"
    if binary.is_file() and os.access(binary, os.X_OK):
        return None
    return (f"{binary} is not built (cmake -S . -B build -DCMAKE_BUILD_TYPE=Release && cmake "
            f"--build build -j2)" if binary.parent == paths.ROOT / "build" else
            f"NCUBE_SIMULATE={binary} is not a program")


def run(argv=None):
    parser = argparse.ArgumentParser(
        prog="experiments/sweep", description=HELP, epilog=HELP_END,
        formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("sweeps", nargs="+", type=Path, help="sweep files (YAML or JSON)")
    parser.add_argument("--results", type=Path, default=Path("results"),
                        help="results folder (default: ./results, in the current folder)")
    parser.add_argument("--cores", type=bounded(1, 1024), default=2,
                        help="local cores, 1 to 1024 (default 2)")
    parser.add_argument("--slurm", action="store_true", help="submit the cells to Slurm")
    parser.add_argument("--profile", type=Path, help="a Snakemake profile")
    parser.add_argument("--cluster", help="generic cluster mode: the submit command")
    parser.add_argument("--jobs", type=bounded(1, 100_000), default=100,
                        help="cluster jobs at once, 1 to 100000 (default 100)")
    parser.add_argument("--check", action="store_true", help="validate and list the cells only")
    parser.add_argument("--verbose", action="store_true",
                        help="show Snakemake's messages as they come (else: one progress line; "
                             "they are in RESULTS/logs/snakemake.log)")
    argv = sys.argv[1:] if argv is None else argv
    extra = []
    if "--" in argv:
        extra = argv[argv.index("--") + 1:]
        argv = argv[:argv.index("--")]
    args = parser.parse_args(argv)
    args.snakemake = extra
    try:
        sweeps = load_all(args.sweeps)
    except SweepError as e:
        print(f"sweep: {e}", file=sys.stderr)
        return 2
    cells = {c.id: c for s in sweeps for c in s.cells}
    if args.check:
        for sweep in sweeps:
            print(f"{sweep.name}: {len(sweep.cells)} cells, measure {sweep.measure}")
            for cell in sweep.cells:
                print(f"  {cell.file}  ({cell.label})")
        sys.stdout.flush()   # a closed pipe raises here, not at the interpreter's exit
        return 0
    if args.slurm:   # before any file is written or any job submitted
        why = slurm_answers()
        if why:
            outcome.say(f"--slurm: the Slurm cluster does not answer ({why}); nothing submitted; "
                        f"is SLURM_CONF set? (a one-node cluster to try it: docs/sweeps.md, "
                        f"\"Trying --slurm on this machine\")")
            return outcome.BAD_INPUT
    if os.environ.get("NCUBE_SIMULATE"):   # the jobs run in the results folder
        os.environ["NCUBE_SIMULATE"] = os.path.abspath(os.environ["NCUBE_SIMULATE"])
    results_dir = args.results.resolve()
    if CONTROL_CHARACTER.search(str(results_dir)):
        print(f"sweep: --results {str(results_dir)!r}: a results folder's path may not hold a "
              f"control character (a newline, a tab): Snakemake's job scripts cannot carry it",
              file=sys.stderr)
        return 2
    if (args.slurm or args.cluster or args.profile) and CLUSTER_UNSAFE.search(str(results_dir)):
        print(f"sweep: --results {str(results_dir)!r}: with a cluster, a results folder's path may "
              f"not hold \" $ ` or \\ (Snakemake hands each job script's path, inside it, to a "
              f"shell in double quotes); choose another folder", file=sys.stderr)
        return 2
    try:
        results_dir.mkdir(parents=True, exist_ok=True)
        if args.slurm:   # sbatch does not make the folder of a job's output
            (results_dir / SLURM_LOGS).mkdir(parents=True, exist_ok=True)
        held = outcome.hold_folder(results_dir)
        if held is None:
            outcome.final_line(None, [])
            return outcome.FOLDER_IN_USE
        forced = forces_reruns(args.snakemake)
        pending = cells_to_run(sweeps, results_dir, forced)
        missing = simulator_missing() if pending and not dry_run(args.snakemake) else None
        if missing:   # before the plan: every cell would fail the same way
            outcome.say(f"{len(pending)} cells to run, and {missing}; nothing run")
            return outcome.BAD_INPUT
        plan = write_plan(sweeps, results_dir, pending, forced)
        if args.slurm:
            write_job_script(results_dir, plan)
            forget_ended_jobs(results_dir, pending)
    except OSError as e:
        code = not_written(e, results_dir)
        outcome.final_line(None, [])
        return code
    done = sum((results_dir / c.file).exists() for c in cells.values())
    print(f"sweep: {len(sweeps)} sweep(s), {len(cells)} distinct cells, {done} with a finished "
          f"result file in {results_dir}, " +
          ("reruns forced" if forced else f"{len(pending)} to run"), flush=True)
    tables = [results_dir / "sweeps" / s.name / name for s in sweeps
              for name in ("cells.csv", "summary.csv", "summary.md")]
    before = outcome.stamps(tables)
    states_before = slurm_status.states_size(results_dir)
    start = time.monotonic()
    try:
        status, messages = run_snakemake(snakemake_command(plan, results_dir, args), results_dir,
                                         [c.file for c in pending],
                                         args.verbose or dry_run(args.snakemake))
        code = outcome.OK
        if status != 0:   # a cell's file appears only verified: existing means finished
            missing = [c.file for c in cells.values() if not (results_dir / c.file).exists()]
            slurm_status.report(results_dir, missing,
                                {c.file: cell_resources.request(c) for c in cells.values()},
                                states_before, outcome.say)
            code = outcome.failed(status, messages, results_dir, missing, len(cells))
        if code in (outcome.OK, outcome.CELLS_FAILED) and not dry_run(args.snakemake):
            for sweep in sweeps:   # the answer; with failed cells, the summary and plots too
                summary.conclude(sweep, results_dir)
    except outcome.Interrupted as stop:
        code = outcome.say_interrupted(stop.signum)
    except OSError as e:
        code = not_written(e, results_dir)
    outcome.final_line(time.monotonic() - start, outcome.tables_written(before, tables))
    return code

if __name__ == "__main__":
    sys.exit(main())
