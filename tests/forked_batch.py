#!/usr/bin/python3
"""Runs a script test's batch of short ./simulate cases in one process, each forked from
build/simulate_server (tests/robustness/forked_runs.py) rather than started anew: a new
./simulate spends about 85 ms of CPU before its main, most of a refusal's or a
--platform-nodes count's cost. Without a server beside SIMULATE (another build, none built, or
one older than the libraries), each case is started anew under the same limits.

    /usr/bin/python3 tests/forked_batch.py SIMULATE CASES

CASES holds one JSON object a line: {"args": [...] (argv[1:]), "stdout": PATH or null,
"stderr": PATH, "as_kib": N (address-space limit, as ulimit -v; default none),
"timeout": SECONDS (default 600)}; each case runs in this process's folder and environment, in
order, one at a time. Prints one line a case: its exit code, 124 when it ran past its timeout
(as timeout(1) says; the case's session is then killed), minus the signal when killed by one.
The binary's own start-up is tried by the suite's other tests (tests/cli_test.sh and the
script tests that run build/simulate)."""
import json
import os
import signal
import subprocess
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent / "robustness"))
import forked_runs  # noqa: E402

NO_LIMIT = 1 << 50   # bytes: RLIMIT_AS as good as unlimited


def forked(simulate, case, stdout):
    run = forked_runs.Run(simulate, case["args"], cwd=os.getcwd(), env=os.environ,
                          as_bytes=case.get("as_kib", NO_LIMIT >> 10) << 10,
                          capture_stdout=stdout is not None)
    if not run.wait(case.get("timeout", 600)):
        os.killpg(run.pid, signal.SIGKILL)
        run.wait()
        code = 124
    else:
        code = run.code
    return code, run.stdout, run.stderr


def started(simulate, case, stdout):
    limits = ["/usr/bin/prlimit", "--as=%d" % (case.get("as_kib", NO_LIMIT >> 10) << 10), "--"]
    process = subprocess.Popen([*limits, simulate, *case["args"]], stdin=subprocess.DEVNULL,
                               stdout=subprocess.PIPE if stdout else subprocess.DEVNULL,
                               stderr=subprocess.PIPE, start_new_session=True)
    try:
        out, err = process.communicate(timeout=case.get("timeout", 600))
        code = process.returncode
    except subprocess.TimeoutExpired:
        os.killpg(process.pid, signal.SIGKILL)
        out, err = process.communicate()
        code = 124
    return code, out or b"", err


def main():
    import argparse
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("simulate", help="build/simulate (its server beside it is used when current)")
    parser.add_argument("cases", help="the cases, one JSON object a line (above)")
    args = parser.parse_args()
    simulate = args.simulate
    run = forked if forked_runs.server_binary(simulate) else started
    for line in Path(args.cases).read_text().splitlines():
        case = json.loads(line)
        code, out, err = run(simulate, case, case.get("stdout"))
        if case.get("stdout"):
            Path(case["stdout"]).write_bytes(out)
        Path(case["stderr"]).write_bytes(err)
        print(code, flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
