"""How a sweep ends (docs/sweeps.md, "When a sweep stops"): its exit codes, the one plain line
for each way it can fail, the results folder held by one sweep at a time, and Snakemake's
messages passed on without the tracebacks of its logging."""
import errno
import fcntl
import os
import signal
import sys
import threading
from pathlib import Path

# Exit codes of experiments/sweep (and experiments/reproduce), as ./simulate's where they mean
# the same thing (docs/cli.md).
OK = 0
BAD_INPUT = 2            # a sweep file refused, or --slurm and the cluster does not answer
CELLS_FAILED = 4         # one or more cells failed; the others finished
NOT_WRITTEN = 5          # the results folder cannot be written (its file system is full, ...)
INTERNAL = 7             # Snakemake failed for another reason
FOLDER_IN_USE = 8        # another sweep runs on the same results folder
# Interrupted by a signal: 128 + its number (130 for Ctrl-C, 143 for SIGTERM).

LOW_SPACE = 1 << 20      # below this many free bytes, a failure is taken for a full disk
LOCK_FILE = ".sweep.lock"


def say(line):
    print(f"sweep: {line}", file=sys.stderr, flush=True)


def hold_folder(results_dir):
    """Holds the results folder for this sweep until the process ends (killed too: the kernel
    releases the lock). Returns the lock's file, or None with the plain line said when another
    sweep holds it: its jobs read the folder's plan, which this one must not overwrite."""
    stream = open(Path(results_dir) / LOCK_FILE, "a+")
    try:
        fcntl.flock(stream, fcntl.LOCK_EX | fcntl.LOCK_NB)
    except BlockingIOError:
        stream.seek(0)
        holder = stream.read().strip() or "unknown"
        stream.close()
        say(f"{results_dir} is in use by another sweep (process {holder}): wait for it to end "
            f"or stop it, then run this command again")
        return None
    stream.truncate(0)
    stream.write(f"{os.getpid()}\n")
    stream.flush()
    return stream


def free_bytes(folder):
    folder = Path(folder)
    while not folder.exists() and folder != folder.parent:   # not made: its file system
        folder = folder.parent
    status = os.statvfs(folder)
    return status.f_bavail * status.f_frsize


def is_full(error):
    return isinstance(error, OSError) and error.errno in (errno.ENOSPC, errno.EDQUOT)


def say_full(results_dir):
    say(f"the file system of {results_dir} is full ({free_bytes(results_dir) // 1024} KiB "
        f"free): finished cells are kept; free some space and run the same command again")
    return NOT_WRITTEN


def say_interrupted(signum):
    say(f"interrupted ({signal.Signals(signum).name}): the running cells were stopped; "
        f"finished cells are kept; run the same command again to go on")
    return 128 + signum


class SnakemakeMessages:
    """Snakemake's messages (and its jobs'), as they come: all into `log` (a binary stream, the
    results folder's logs/snakemake.log) and, with `verbose`, on to stderr; without it only a
    cell job's own failure (from its "run_cell:" line to its "  command:" line) reaches stderr,
    the progress line saying the rest (ncube.progress). Never shown: the "--- Logging error
    ---" blocks Python's logging prints when Snakemake cannot write its own log (a full disk),
    which say nothing the plain line at the end does not. Notes what the failure classes need
    (a lock refusal, a full file system) and counts the cell jobs that failed."""

    FAILED_CELL = ("Error in rule cell:", "Error in rule traced_cell:")

    def __init__(self, stream, log=None, verbose=True, show=None):
        self.stream = stream
        self.log = log
        self.verbose = verbose
        self.show = show or self._write
        self.locked = False
        self.full = False
        self.failed_cells = 0
        self.thread = threading.Thread(target=self._pass_on, daemon=True)
        self.thread.start()

    @staticmethod
    def _write(text):
        sys.stderr.write(text)
        sys.stderr.flush()

    def _pass_on(self):
        dropping = False
        job_failure = False
        for line in iter(self.stream.readline, b""):
            text = line.decode(errors="replace")
            if "No space left on device" in text or "Disk quota exceeded" in text:
                self.full = True
            if "Directory cannot be locked" in text:
                self.locked = True
            # Snakemake's lines and the jobs' share one pipe: a job's line may start inside one
            # of Snakemake's ("Error in rule cell:run_cell: ..."), so both are looked for anywhere.
            self.failed_cells += sum(text.count(mark) for mark in self.FAILED_CELL)
            if text.startswith("--- Logging error ---"):
                dropping = True
            if self.log is not None:
                try:
                    self.log.write(line)
                    self.log.flush()
                except OSError:   # a full disk: the plain line at the end says so
                    self.full = True
            shown = text
            if "run_cell:" in text and not job_failure:
                job_failure = True
                shown = text if self.verbose else text[text.index("run_cell:"):]
            if not dropping and (self.verbose or job_failure):
                self.show(shown)
            if text.startswith("  command:"):
                job_failure = False
            elif dropping and text.startswith("Arguments:"):   # the block's last line
                dropping = False

    def wait(self):
        self.thread.join(timeout=30)


def snakemake_log(results_dir):
    """The log of the last run: everything Snakemake and its jobs said (logs/snakemake.log,
    ncube.runner), else Snakemake's own; None when there is none."""
    ours = Path(results_dir) / "logs" / "snakemake.log"
    if ours.exists():
        return ours
    logs = sorted((Path(results_dir) / ".snakemake" / "log").glob("*.snakemake.log"))
    return logs[-1] if logs else None


def failed(status, messages, results_dir, missing, total=None):
    """Says what happened when Snakemake ended with `status` != 0 and returns the exit code;
    `missing` are the result files of the cells without a finished result, of `total` cells."""
    log = snakemake_log(results_dir)
    if messages.locked:
        say(f"{results_dir} is locked by another Snakemake run on it: wait for it to end; if "
            f"none runs (it was killed), run this command again with -- --unlock, then without")
        return FOLDER_IN_USE
    if messages.full or free_bytes(results_dir) < LOW_SPACE:
        return say_full(results_dir)
    if missing:
        shown = ", ".join(missing[:5])
        if len(missing) > 5:
            shown += f" and {len(missing) - 5} more"
        kept = ("no cell finished" if total is not None and len(missing) >= total
                else "the other cells finished and are kept")
        say(f"{len(missing)} cell(s) failed: {shown}; their messages are above and in {log}; "
            f"{kept}; fix the cause and run the same command again")
        return CELLS_FAILED
    say(f"Snakemake failed (exit {status}): see its messages in {log}")
    return INTERNAL


def tables_written(before, tables):
    """The tables this run wrote: those there now and changed since `before` (path -> mtime)."""
    written = []
    for path in tables:
        try:
            stamp = path.stat().st_mtime_ns
        except OSError:
            continue
        if before.get(path) != stamp:
            written.append(path)
    return written


def stamps(paths_):
    found = {}
    for path in paths_:
        try:
            found[path] = path.stat().st_mtime_ns
        except OSError:
            pass
    return found


def final_line(wall, written):
    """The last line: only the tables this run wrote (cells are counted above)."""
    tables = ", ".join(map(str, written)) if written else "no table"
    spent = "" if wall is None else f"{wall:.1f} s wall time; "
    print(f"sweep: {spent}written: {tables}", flush=True)


class Interrupted(Exception):
    """The sweep was stopped by a signal; its jobs are stopped already."""

    def __init__(self, signum):
        super().__init__(signum)
        self.signum = signum
