"""The one progress line of a running sweep (docs/sweeps.md, "Running"): the cells done of all
to run, the failed ones, the time spent and an estimate of the rest. On a terminal it is one
line rewritten in place every second; elsewhere (a pipe, a file, a CI log) a plain line when
the count changes, at most one every PLAIN_SECONDS, and the last. A cell counts as done when
its result file is there (a cell's file appears only verified: ncube.run_cell)."""
import sys
import threading
import time
from pathlib import Path

PLAIN_SECONDS = 30


def duration(seconds):
    seconds = int(round(seconds))
    if seconds < 60:
        return f"{seconds} s"
    if seconds < 3600:
        return f"{seconds // 60} min {seconds % 60:02d} s"
    return f"{seconds // 3600} h {seconds // 60 % 60:02d} min"


def line(done, total, failed, elapsed, final=False):
    """`sweep: 3 of 14 cells done, 0 failed, 12 s, about 44 s left`."""
    text = f"sweep: {done} of {total} cells done, {failed} failed, {duration(elapsed)}"
    left = total - done - failed
    if left <= 0 and not final:
        text += "; the tables and plots"
    elif done and left > 0:
        text += f", about {duration(elapsed / done * left)} left"
    elif left > 0:
        text += ", the estimate after the first cell"
    return text


class Progress:
    """Counts the result files of `cells` (paths under `results_dir`) appearing; `failed` is a
    function giving the number of cells failed so far (ncube.outcome.SnakemakeMessages)."""

    def __init__(self, results_dir, files, failed, stream=None):
        self.files = [Path(results_dir) / f for f in files]
        self.failed = failed
        self.stream = stream or sys.stdout
        self.terminal = self.stream.isatty()
        self.start = time.monotonic()
        self.lock = threading.Lock()
        self.shown = None          # the text on the terminal's current line
        self.said = (None, 0.0)    # the plain line's counts last said and when
        self.stopped = threading.Event()
        self.thread = threading.Thread(target=self._tick, daemon=True)

    def counts(self):
        done = sum(f.exists() for f in self.files)
        return done, len(self.files), min(self.failed(), len(self.files) - done)

    def _tick(self):
        while not self.stopped.wait(1.0):
            self.update()

    def update(self, final=False):
        done, total, failed = self.counts()
        now = time.monotonic()
        text = line(done, total, failed, now - self.start, final)
        with self.lock:
            if self.terminal:
                self.stream.write("\r" + text + "\x1b[K" + ("\n" if final else ""))
                self.shown = None if final else text
            elif final or ((done, failed) != self.said[0] and now - self.said[1] >= PLAIN_SECONDS):
                self.stream.write(text + "\n")
                self.said = ((done, failed), now)
            self.stream.flush()

    def show(self, text):
        """Writes a message (a failed cell's) to stderr without breaking the progress line."""
        with self.lock:
            if self.terminal and self.shown:
                self.stream.write("\r\x1b[K")
                self.stream.flush()
            sys.stderr.write(text)
            sys.stderr.flush()
            if self.terminal and self.shown:
                self.stream.write(self.shown)
                self.stream.flush()

    def begin(self):
        self.said = ((0, 0), time.monotonic())   # the first plain line after PLAIN_SECONDS
        if self.terminal:
            self.update()
        self.thread.start()

    def end(self):
        self.stopped.set()
        self.thread.join(timeout=5)
        self.update(final=True)
