#!/usr/bin/python3
"""The node counts the sweep library asks ./simulate for (--platform-nodes: the platform read
with every check a run makes) are kept in build/platform-nodes beside the simulator, so that a
sweep's cell jobs, each a process that reads the sweep file again, do not each start SimGrid
for every platform. Held here, each load in a process of its own, through a wrapper of the
simulator that counts its runs: asked once for a platform, not again; again after the platform
changes (and the new count is its own), after the simulator changes, after a damaged entry; a
platform ./simulate refuses is refused every time and never kept; a FIFO at an entry's name is
neither read nor written."""
import json
import os
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
failures = []


def check(condition, what):
    print(("ok   " if condition else "FAIL ") + what, flush=True)
    if not condition:
        failures.append(what)


def main():
    simulate = str(Path(sys.argv[1]).resolve())
    with tempfile.TemporaryDirectory() as scratch:
        work = Path(scratch)
        runs = work / "runs.txt"
        wrapper = work / "bin" / "simulate"
        wrapper.parent.mkdir()
        wrapper.write_text(f"#!/bin/sh\necho run >> '{runs}'\nexec '{simulate}' \"$@\"\n")
        wrapper.chmod(0o755)
        platform = work / "machine.json"
        shutil.copy(ROOT / "platforms" / "ncube2.json", platform)

        def nodes():
            """(the count or the error, how many runs of ./simulate it took), in a new process."""
            before = len(runs.read_text().splitlines()) if runs.exists() else 0
            load = subprocess.run(
                [sys.executable, "-c", "import sys; sys.path.insert(0, sys.argv[1]); "
                 "from ncube import sweep; print(sweep.platform_nodes(sys.argv[2]))",
                 str(ROOT / "analysis"), str(platform)],
                capture_output=True, text=True, env=dict(os.environ, NCUBE_SIMULATE=str(wrapper)),
                timeout=60)
            after = len(runs.read_text().splitlines()) if runs.exists() else 0
            answer = load.stdout.strip() or load.stderr.strip().splitlines()[-1]
            return answer, after - before

        check(nodes() == ("64", 1), "a platform is asked of ./simulate the first time")
        check(nodes() == ("64", 0), "and not again: its count is kept")
        cache = wrapper.parent / "platform-nodes"
        check(len(list(cache.iterdir())) == 1, "one entry, beside the simulator")
        data = json.loads(platform.read_text())
        data["parameters"]["dimension"]["value"] = 7
        platform.write_text(json.dumps(data))
        check(nodes() == ("128", 1), "a changed platform is asked again, and its own count given")
        check(nodes() == ("128", 0), "and kept")
        os.utime(wrapper, ns=(1, 1))
        check(nodes() == ("128", 1), "a changed simulator is asked again")
        for entry in cache.iterdir():
            entry.write_text("not a number\n")
        check(nodes() == ("128", 1), "a damaged entry is asked again")
        data["parameters"]["dimension"]["value"] = 99
        platform.write_text(json.dumps(data))
        count = len(list(cache.iterdir()))
        first, second = nodes(), nodes()
        check(first[1] == 1 and second[1] == 1 and "dimension" in first[0] and first == second,
              f"a platform ./simulate refuses is refused each time, asked each time ({first})")
        check(len(list(cache.iterdir())) == count, "and never kept")
        # A FIFO planted at an entry's name: read through the gate (refused), asked again, and
        # nothing written onto it (a write would wait for a reader: the load would hang).
        data["parameters"]["dimension"]["value"] = 6
        platform.write_text(json.dumps(data))
        for entry in cache.iterdir():
            entry.unlink()
        nodes()
        entry = next(cache.iterdir())
        entry.unlink()
        os.mkfifo(entry)
        check(nodes() == ("64", 1) and entry.is_fifo(),
              "a FIFO at an entry's name is asked again, not read or written")
    print(f"platform_nodes_cache_test: {len(failures)} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
