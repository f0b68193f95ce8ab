#!/usr/bin/python3
"""Tries ./simulate on malformed scenes, bad option sets, every numeric option with special
values and its range's ends, output-path cases and bad machine
files (tests/robustness/cases.py), then on every cell of the threat model
(tests/robustness/threat_model.py: every input and output x every kind of path and hostile
content), and tabulates the outcomes.

Usage: run.py SIMULATE [--root REPO] [--timeout S] [--cell-timeout S] [--jobs N]
              [--memory-mb MB] [--only cases|options|files|threats|reads|writes]
              [--list] [--strict]

Each run gets a wall-clock timeout and an address-space limit (ulimit -v), so no input can
hang or exhaust the machine running the script. Outcomes:
  clean error     exit 2 as expected: a message on stderr of at most 2 lines and 2000 bytes,
                  no output file left, inputs unchanged
  clean other     the expected exit 0 (sane result file), 3 (out of memory) or 5 (an output
                  could not be written), with the same checks
  crash/signal    killed by a signal (abort, segmentation fault, ...)
  hang/timeout    still running at the timeout
  wrong exit      any other exit code than expected
  bad output      the expected exit code, but an output or temporary file left behind, an input changed, a
                  message too long, or a result file with status other than expected,
                  null or non-finite numbers, or radiosities that differ from the reference
Each group of cases runs in a folder of its own, its cases one after another, --jobs groups and
threat-model cells at once. The threat model's cells run in folders of their own, each with
--cell-timeout; a cell is clean or not clean (threat_cases.run_cell says why), and the
table counts them by the issue's classes and by input or output. Cells listed in
known_open.KNOWN_OPEN are reported, not failed (--strict fails on entries that are now clean).
Exit status: 0 when every case and every cell not known open is clean, 1 otherwise (ctest).
"""

import sys  # noqa: E402
from pathlib import Path  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "analysis"))
from ncube.interpreter import use_project_python  # noqa: E402

use_project_python()   # Debian's /usr/bin/python3 (README.md, "Use")

import argparse
import concurrent.futures
import hashlib
import json
import math
import os
import signal
import stat
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import cases as case_list  # noqa: E402
import forked_runs  # noqa: E402
import known_open  # noqa: E402
import threat_cases  # noqa: E402
import threat_model  # noqa: E402

EXIT = {"error": 2, "ok": 0, "help": 0, "oom": 3, "write": 5}
COLUMNS = ["clean error", "clean other", "crash/signal", "hang/timeout", "wrong exit", "bad output"]


def digest(path):
    try:
        return hashlib.sha256(Path(path).read_bytes()).hexdigest()
    except OSError:
        return None


def numbers_finite(value):
    if value is None:
        return False
    if isinstance(value, float):
        return math.isfinite(value)
    if isinstance(value, dict):
        return all(numbers_finite(v) for v in value.values())
    if isinstance(value, list):
        return all(numbers_finite(v) for v in value)
    return True


def check_result(case, results):
    """Problems with the result file of a run that exited as expected."""
    outputs = case.get("outputs", [])
    json_out = next((p for a, p in zip(case["args"], case["args"][1:]) if a == "--json"), None)
    if case["expect"] not in ("ok", "oom"):
        return [f"left {p}" for p in outputs if Path(p).exists()]
    if case["expect"] == "ok":
        missing = [f"missing {p}" for p in outputs if not Path(p).exists()]
        if missing:
            return missing
    if not json_out or case.get("kinds") is not None:
        return []
    try:
        result = json.loads(Path(json_out).read_text())
    except (OSError, ValueError) as error:
        return [f"result file unreadable: {error}"]
    problems = []
    want = "ok" if case["expect"] == "ok" else "out_of_memory"
    if result.get("status") != want:
        problems.append(f"status {result.get('status')}")
    # The one documented null of a sound result: no mean seconds per iteration without
    # iterations (docs/result-format.md).
    checked = dict(result)
    if checked.get("iterations") == 0 and checked.get("seconds_per_iteration") is None:
        checked.pop("seconds_per_iteration")
    if not numbers_finite(checked):
        problems.append("null or non-finite numbers in the result file")
    reference = results.get(case.get("same_as"))
    if reference and case["expect"] == "ok":
        for a, b in zip(reference.get("patch_radiosity", []), result.get("patch_radiosity", [])):
            if any(x is None or y is None or abs(x - y) > 1e-6 * (1 + abs(x)) for x, y in zip(a, b)):
                problems.append("radiosities differ from " + case["same_as"])
                break
    if case["expect"] == "ok":
        results[case["name"]] = result
    return problems


KIND_TESTS = {"link": os.path.islink, "char": lambda p: stat.S_ISCHR(os.lstat(p).st_mode),
              "fifo": lambda p: stat.S_ISFIFO(os.lstat(p).st_mode),
              "socket": lambda p: stat.S_ISSOCK(os.lstat(p).st_mode),
              "folder": lambda p: os.path.isdir(p) and not os.path.islink(p),
              "file": lambda p: os.path.isfile(p) and not os.path.islink(p)}


def kind_problems(case, code):
    """A path replaced by something else, or an output missing from where it should be."""
    problems = [f"{p} is no longer a {kind}" for p, kind in case.get("kinds", {}).items()
                if not (os.path.lexists(p) and KIND_TESTS[kind](p))]
    if code == 0:
        for p in case.get("written", []):
            if not os.path.isfile(p) or Path(p).read_bytes() in (b"", b"old"):
                problems.append(f"{p} was not written")
    return problems


def drain(path, received):
    with open(path, "rb") as f:
        received.append(len(f.read()))


def forked_case(simulate, case, timeout, memory_bytes):
    """(exit code or None when still running at `timeout`, stderr bytes) of one case, forked
    from build/simulate_server (forked_runs.py): stdout to /dev/null, a session of its own, and
    with a file-size limit SIGXFSZ ignored as below."""
    run = forked_runs.Run(simulate, case["args"], cwd=os.getcwd(), env=os.environ,
                          as_bytes=memory_bytes, fsize_bytes=case.get("fsize", 0),
                          ignore_xfsz=bool(case.get("fsize")))
    if not run.wait(timeout):
        os.killpg(run.pid, signal.SIGKILL)
        run.wait()
        return None, run.stderr
    return run.code, run.stderr


def started_case(simulate, case, timeout, memory_bytes):
    """The same, ./simulate started anew (a build without the server)."""
    # The limits set by util-linux's prlimit, which then execs the program: no preexec_fn, so
    # the run is spawned without a fork of this process (a fork of a Python with threads and
    # tens of MB cost more CPU than many a refusal it runs). With a file-size limit, SIGXFSZ
    # stays ignored as Python leaves it (restore_signals off): writes fail with EFBIG instead.
    limits = ["/usr/bin/prlimit", f"--as={memory_bytes}", "--core=0"]
    if case.get("fsize"):
        limits.append(f"--fsize={case['fsize']}")
    process = subprocess.Popen([*limits, "--", simulate, *case["args"]], stdout=subprocess.DEVNULL,
                               stderr=subprocess.PIPE, start_new_session=True,
                               restore_signals=not case.get("fsize"))
    try:
        _, stderr = process.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        os.killpg(process.pid, signal.SIGKILL)
        process.communicate()
        return None, b""
    return process.returncode, stderr


def run_case(simulate, case, timeout, memory_bytes, results, work):
    for p in case.get("outputs", []):
        if Path(p).is_file():
            Path(p).unlink()
    for path, content in case.get("files", {}).items():
        Path(path).write_bytes(content)
    before = {str(p): digest(p) for p in case.get("inputs", [])}

    if case.get("memory_mb"):
        memory_bytes = case["memory_mb"] << 20

    received, reader = [], None
    if case.get("reader"):
        reader = threading.Thread(target=drain, args=(case["reader"], received), daemon=True)
        reader.start()
    start = time.monotonic()
    if forked_runs.server_binary(simulate):
        code, stderr = forked_case(simulate, case, timeout, memory_bytes)
    else:
        code, stderr = started_case(simulate, case, timeout, memory_bytes)
    if code is None:
        return "hang/timeout", f"still running after {timeout} s", time.monotonic() - start
    seconds = time.monotonic() - start
    if reader:
        reader.join(timeout=5)
        if code == 0 and not received:
            return "bad output", "nothing reached the FIFO's reader", seconds
    message = stderr.decode(errors="replace")
    if code < 0:
        return "crash/signal", f"signal {-code}: {message[:200]!r}", seconds
    if code != EXIT[case["expect"]]:
        left = [str(p) for p in case.get("outputs", []) if Path(p).exists()]
        return ("wrong exit", f"exit {code}, expected {EXIT[case['expect']]}: {message[:200]!r}" +
                (f" (left {', '.join(left)})" if code != 0 and left else ""), seconds)
    problems = check_result(case, results) + kind_problems(case, code)
    stray = [str(p) for p in Path(work).rglob("*.partial*")]
    for p in stray:
        Path(p).unlink()
    problems += [f"left temporary file {p}" for p in stray]
    problems += [f"changed input {p}" for p, d in before.items() if digest(p) != d]
    if code != 0 and (not message.strip() or len(message.splitlines()) > 2 or len(message) > 2000):
        problems.append(f"message of {len(message.splitlines())} lines, {len(message)} bytes")
    if code != 0 and case.get("names") and case["names"] not in message:
        problems.append(f"the message does not name {case['names']}")
    if problems:
        return "bad output", "; ".join(problems), seconds
    return ("clean error" if case["expect"] == "error" else "clean other"), message.strip()[:200], seconds


def run_group(args, group):
    """The cases of one group (one folder), one after another: [(case, outcome, detail, s)]."""
    results = {}
    return [(case, *run_case(args.simulate, case, args.timeout, args.memory_mb << 20, results,
                             case["work"])) for case in group]


def threat_table(outcomes, title, key):
    """Rows by `key` of a cell: cells, clean, not clean, of which known open."""
    rows = {}
    for cell, clean, _detail, is_open in outcomes:
        row = rows.setdefault(key(cell), [0, 0, 0, 0])
        row[0] += 1
        row[1 if clean else 2] += 1
        row[3] += (not clean) and is_open
    lines = [f"| {title} | cells | clean | not clean | of them known open |",
             "|---|---|---|---|---|"]
    total = [0, 0, 0, 0]
    for name, row in rows.items():
        lines.append(f"| {name} | " + " | ".join(map(str, row)) + " |")
        total = [a + b for a, b in zip(total, row)]
    lines.append("| all | " + " | ".join(map(str, total)) + " |")
    return "\n".join(lines)


# The ids of the threat model's cells left to the other part (--only reads or writes).
OTHER_PART = set()


def run_threats(args, work, pool):
    """Submits every cell of the threat model to `pool`; returns the futures by cell."""
    root, simulate = Path(args.root).resolve(), Path(args.simulate).resolve()
    futures = {}
    for cell in threat_model.cells(simulate):
        if (args.only == "reads" and cell.direction == "write") or \
                (args.only == "writes" and cell.direction != "write"):
            OTHER_PART.add(cell.id)
            continue
        futures[pool.submit(threat_cases.run_cell, cell, Path(work), root, simulate,
                            args.cell_timeout * threat_model.time_factor(cell),
                            args.memory_mb << 20)] = cell
    return futures


def report_threats(args, futures):
    """Prints the threat model's tables and its unclean cells; returns the number of failures."""
    outcomes, skipped = [], 0
    for future, cell in futures.items():
        try:
            result = future.result()
        except OSError as error:   # the cell could not even start (the binary being rebuilt)
            result = (False, f"could not run: {error}", 0.0)
        if result is None:
            skipped += 1
            continue
        clean, detail, seconds = result
        outcomes.append((cell, clean, detail, cell.id in known_open.KNOWN_OPEN))
        if args.list:
            print(f"{'clean' if clean else 'NOT CLEAN':9} {seconds:6.2f}s  {cell.id:60} "
                  f"{detail[:150]}")
    outcomes.sort(key=lambda o: o[0].id)
    print()
    print(threat_table(outcomes, "threat model: class", lambda c: c.klass))
    print()
    print(threat_table(outcomes, "threat model: input or output", lambda c: (
        ("read " if c.direction != "write" else "write ") + c.surface.id)))
    if skipped:
        print(f"skipped {skipped} cells: character devices need root (mknod)")
    failures = 0
    for cell, clean, detail, is_open in outcomes:
        if not clean:
            print(f"{'OPEN' if is_open else 'FAIL'} [{cell.klass}] {cell.id}: {detail[:300]}")
            failures += not is_open
    unclean = {o[0].id for o in outcomes if not o[1]}
    stale = [i for i in known_open.KNOWN_OPEN if i not in unclean and i not in OTHER_PART]
    for cell_id in stale:
        print(f"now clean: {cell_id!r}: remove it from tests/robustness/known_open.py")
    return failures + (len(stale) if args.strict else 0)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("simulate")
    parser.add_argument("--root", default=str(Path(__file__).resolve().parents[2]))
    parser.add_argument("--timeout", type=float, default=10.0, help="seconds per run")
    parser.add_argument("--cell-timeout", type=float, default=6.0,
                        help="seconds per run of a threat-model cell")
    parser.add_argument("--jobs", type=int, default=3,
                        help="groups of cases and threat-model cells at once (a hanging cell "
                             "takes no CPU)")
    parser.add_argument("--memory-mb", type=int, default=1024, help="address-space limit per run")
    parser.add_argument("--only", choices=("cases", "options", "files", "threats", "reads", "writes"),
                        help="run one part only (options, files: the cases of the command line's "
                             "words, of the files a run reads; reads, writes: the threat model's "
                             "cells that read, or write, a file)")
    parser.add_argument("--list", action="store_true", help="print every case and its outcome")
    parser.add_argument("--strict", action="store_true",
                        help="also fail on known_open.py entries that are now clean")
    args = parser.parse_args()
    # Absolute: the cases run in folders of their own (a relative path named another file there).
    args.simulate = str(Path(args.simulate).resolve())
    os.environ["NCUBE_ROOT"] = args.root
    failures = []
    with tempfile.TemporaryDirectory() as work, tempfile.TemporaryDirectory() as cells_work, \
            concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        cases = (case_list.all_cases(args.root, work, args.simulate,
                                     args.only if args.only in case_list.PARTS else None)
                 if args.only in (None, "cases", *case_list.PARTS) else [])
        by_folder = {}
        for case in cases:
            by_folder.setdefault(case["work"], []).append(case)
        # The biggest groups first: each group runs its cases one after another.
        groups = [pool.submit(run_group, args, group)
                  for group in sorted(by_folder.values(), key=len, reverse=True)]
        futures = (run_threats(args, cells_work, pool)
                   if args.only in (None, "threats", "reads", "writes") else {})
        outcomes = {id(case): outcome for group in groups for case, *outcome in group.result()}
        table = {}
        for case in cases:
            outcome, detail, seconds = outcomes[id(case)]
            row = table.setdefault(case["group"], dict.fromkeys(COLUMNS, 0))
            row[outcome] += 1
            if args.list:
                print(f"{case['group']:10} {outcome:13} {seconds:6.2f}s  {case['name'][:60]:60} "
                      f"{detail[:150]}")
            if outcome not in ("clean error", "clean other"):
                failures.append((case, outcome, detail))
        if cases:
            print("| inputs | tried | " + " | ".join(COLUMNS) + " |")
            print("|---|---|" + "---|" * len(COLUMNS))
            totals = dict.fromkeys(COLUMNS, 0)
            for group, row in table.items():
                print(f"| {group} | {sum(row.values())} | " + " | ".join(str(row[c]) for c in COLUMNS) + " |")
                for c in COLUMNS:
                    totals[c] += row[c]
            print(f"| all | {sum(totals.values())} | " + " | ".join(str(totals[c]) for c in COLUMNS) + " |")
            for case, outcome, detail in failures:
                print(f"FAIL [{case['group']}] {case['name'][:80]}: {outcome}: {detail[:300]}")
        threat_failures = report_threats(args, futures) if futures else 0
    return 1 if failures or threat_failures else 0


if __name__ == "__main__":
    sys.exit(main())
