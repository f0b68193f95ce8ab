#!/usr/bin/python3
"""The trace (--trace; docs/result-format.md, "The trace") and the message log name what
happens: every slice carries its iteration (and shooter once known), every send and receive
its message kind, peer and modeled bytes. Checked against the result file of the same run,
which counts them independently (NodeStats): each node's sends and bytes in the trace are its
messages_sent and bytes_sent; every send from a to b of a kind is received by b from a, with the
same bytes; the shooter of iteration k at the radiosity processors is the result's k-th shooter;
every slice's time adds up to the node's compute, overhead and waiting seconds. The windows
(--trace-iterations, --trace-nodes) keep exactly the full trace's events that fall inside them;
bad windows are exit 2. The message log (--log=ncube_messages.thresh:debug) names the kinds.

Usage: NCUBE_SIMULATE=build/simulate /usr/bin/python3 tests/trace_test.py"""
import collections
import json
import os
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
SIMULATE = os.environ["NCUBE_SIMULATE"]
KINDS = {"candidate", "shooter", "stop", "points", "answers", "patches", "increments",
         "elements", "credit", "histogram", "selection", "pixels"}
failures = []


def check(condition, what):
    print(("ok   " if condition else "FAIL ") + what, flush=True)
    if not condition:
        failures.append(what)


def run(*args, folder):
    return subprocess.run([SIMULATE, *args], cwd=folder, capture_output=True, text=True,
                          timeout=120, env=dict(os.environ, NCUBE_ROOT=str(ROOT)))


def traced(folder, name, *args):
    """A run's trace and result file."""
    done = run("scene0.json", *args, "--trace", f"{name}.trace", "--json", f"{name}.json",
               "--quiet", folder=folder)
    assert done.returncode == 0, done.stderr
    return (json.loads((Path(folder) / f"{name}.trace").read_text())["traceEvents"],
            json.loads((Path(folder) / f"{name}.json").read_text()))


def check_run(trace, result, what):
    slices = [e for e in trace if e["ph"] == "X"]
    check(all("iteration" in e["args"] or e["args"].get("phase") == "render" for e in slices),
          f"{what}: every slice has its iteration (or the rendering phase)")
    messages = [e for e in slices if e["cat"] in ("overhead", "wait")]
    check(all(e["args"].get("message") in KINDS and isinstance(e["args"].get("bytes"), int)
              for e in messages if e["cat"] == "overhead"),
          f"{what}: every send and receive names its kind and bytes")
    sends = [e for e in messages if e["name"].startswith("send ")]
    receives = [e for e in messages if e["name"].startswith("receive ")]
    check(all(e["name"] == "send " + e["args"]["message"] and "to" in e["args"] for e in sends)
          and all(e["name"] == "receive " + e["args"]["message"] and "from" in e["args"]
                  for e in receives),
          f"{what}: a send is named by its kind and names its receiver, a receive its sender")
    for node in result["nodes"]:
        mine = [e for e in sends if e["tid"] == node["node"]]
        got = [e for e in receives if e["tid"] == node["node"]]
        if (len(mine) != node["messages_sent"] or sum(e["args"]["bytes"] for e in mine) != node["bytes_sent"]
                or len(got) != node["messages_received"]):
            check(False, f"{what}: node {node['node']}: {len(mine)} sends of "
                  f"{sum(e['args']['bytes'] for e in mine)} bytes, {len(got)} receives in the trace; "
                  f"the result file: {node['messages_sent']}, {node['bytes_sent']}, {node['messages_received']}")
            break
        for cat, field in (("compute", "compute_seconds"), ("overhead", "overhead_seconds"),
                           ("wait", "waiting_seconds")):
            durations = [e["dur"] for e in slices if e["tid"] == node["node"] and e["cat"] == cat]
            seconds = sum(durations) / 1e6
            # Each slice is written to the nanosecond.
            if abs(seconds - node[field]) > 1e-9 * (len(durations) + 1) + 1e-12 * node[field]:
                check(False, f"{what}: node {node['node']}: {cat} slices add up to {seconds} s, "
                      f"the result file's {field} is {node[field]}")
                break
    else:
        check(True, f"{what}: each node's sends, bytes, receives and seconds are the result file's")
    pairs = lambda events, me, peer: collections.Counter(
        (e["tid"] if me else e["args"][peer], e["args"][peer] if me else e["tid"],
         e["args"]["message"], e["args"]["bytes"]) for e in events)
    check(pairs(sends, True, "to") == collections.Counter(
              (e["args"]["from"], e["tid"], e["args"]["message"], e["args"]["bytes"]) for e in receives),
          f"{what}: every message sent is received by its receiver, kind and bytes alike")
    radiosity = {n["node"] for n in result["nodes"] if n["role"] == "radiosity"}
    shot = {(e["args"]["iteration"], e["args"]["shooter"]) for e in slices
            if e["tid"] in radiosity and "shooter" in e["args"]}
    expected = {(k + 1, patch) for k, patch in enumerate(result["shooters"])}
    check(shot == expected, f"{what}: the shooter of iteration k is the result's k-th shooter")
    check(max(e["args"].get("iteration", 0) for e in slices) == result["iterations"] + 1,
          f"{what}: the pass that ends the run is iteration {result['iterations'] + 1}")


with tempfile.TemporaryDirectory() as folder:
    full, result = traced(folder, "full", "--R", "2", "--V", "1", "--iterations", "3")
    check_run(full, result, "R=2 V=1")
    check(any(e["name"] == "send points" for e in full) and any(e["name"] == "receive answers" for e in full),
          "R=2 V=1: the points go to the visibility processors and the answers come back")
    balanced, result_b = traced(folder, "balanced", "--R", "4", "--iterations", "3", "--subdivide",
                                "--balance", "--balance-threshold", "0")
    check_run(balanced, result_b, "R=4 with subdivision and balancing")
    check(sum(e["name"] == "send patches" for e in balanced) == result_b["transfers"]["messages"] > 0,
          "R=4 balanced: the trace's patch sends are the result file's transfer messages")
    rendered, result_r = traced(folder, "rendered", "--R", "4", "--iterations", "2", "--render-parallel",
                                "blocks", "--image-width", "32", "--image-height", "32")
    check(any(e["args"].get("phase") == "render" and e["name"] == "send pixels" for e in rendered),
          "the rendering phase's slices say so, and its messages are named")

    # The windows keep exactly the full trace's events inside them, and nothing else.
    def window(name, *args):
        return traced(folder, name, "--R", "2", "--V", "1", "--iterations", "3", *args)[0]
    meta = lambda events: [e for e in events if e["ph"] == "M"]
    second = window("second", "--trace-iterations", "2:2")
    check([e for e in second if e["ph"] == "X"]
          == [e for e in full if e["ph"] == "X" and e["args"].get("iteration") == 2]
          and len(second) > len(meta(full)),
          "--trace-iterations 2:2 keeps the full trace's events of iteration 2, all of them")
    later = window("later", "--trace-iterations", "3:")
    check([e for e in later if e["ph"] == "X"]
          == [e for e in full if e["ph"] == "X" and e["args"].get("iteration", -1) >= 3],
          "--trace-iterations 3: keeps iterations 3 on")
    nodes = window("nodes", "--trace-nodes", "1,3")
    check(nodes == [e for e in full if e["tid"] in (1, 3)] and {e["tid"] for e in nodes} == {1, 3},
          "--trace-nodes 1,3 keeps nodes 1 and 3, names included")
    beyond = run("scene0.json", "--R", "2", "--V", "1", "--iterations", "3", "--trace-nodes", "1,3-5",
                 "--trace", "beyond.trace", "--quiet", folder=folder)
    check(beyond.returncode == 2 and "node 5" in beyond.stderr and len(beyond.stderr.splitlines()) == 1
          and not (Path(folder) / "beyond.trace").exists(),
          "--trace-nodes 1,3-5 on a 4-node run: exit 2, one line naming node 5, no trace")
    both = window("both", "--trace-nodes", "0", "--trace-iterations", "1")
    check(both == [e for e in full if e["tid"] == 0 and e.get("args", {}).get("iteration", 1) == 1],
          "both windows at once keep what is in both")
    for args in (["--trace-iterations", "3:1"], ["--trace-iterations", "x"], ["--trace-iterations", "-1"],
                 ["--trace-iterations", "01"], ["--trace-nodes", "1-"], ["--trace-nodes", "2,,3"],
                 ["--trace-nodes", "5-2"]):
        done = run("scene0.json", "--iterations", "1", "--trace", "bad.trace", *args, folder=folder)
        check(done.returncode == 2 and not (Path(folder) / "bad.trace").exists()
              and done.stderr.count("\n") <= 2,
              f"{' '.join(args)}: exit 2, one message, no trace ({done.returncode}: {done.stderr.strip()!r})")
    done = run("scene0.json", "--iterations", "1", "--trace-nodes", "0", folder=folder)
    check(done.returncode == 2 and "--trace" in done.stderr, "--trace-nodes without --trace: exit 2")

    # The message log names the kinds.
    done = run("scene0.json", "--R", "2", "--V", "1", "--iterations", "1",
               "--log=ncube_messages.thresh:debug", folder=folder)
    log = done.stderr
    check(done.returncode == 0 and "node 0 -> node 1: points," in log and ": answers" in log
          and " kind " not in log, "the message log names kinds (points, answers), no numbers")

if failures:
    print(f"{len(failures)} failures", file=sys.stderr)
    sys.exit(1)
