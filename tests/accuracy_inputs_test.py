#!/usr/bin/python3
"""analysis/ncube/accuracy.py as a real tool (issue 37, item 5; its docstring): every malformed
or hostile input is exit 2 with one line on stderr naming the file and what is wrong, never a
traceback, a hang or gigabytes of memory; values NaN, infinite, negative or out of range are
refused; a black reference element has no relative error (null in --json, left out of the RMS);
--json never lands on an input (exit 2, the input unchanged) and a failed write is exit 5.
Called as: accuracy_inputs_test.py SIMULATE REPO_ROOT"""
import json
import os
import subprocess
import sys
import tempfile
from pathlib import Path

root = Path(sys.argv[2])
sys.path.insert(0, str(root / "tests"))
from accuracy_test_meshes import ply_bytes, reference  # noqa: E402

TOOL = ["/usr/bin/python3", str(root / "analysis" / "ncube" / "accuracy.py")]
failures = []


def check(condition, what):
    print(("ok   " if condition else "FAIL ") + what, flush=True)
    if not condition:
        failures.append(what)


def run(*arguments, timeout=20):
    try:
        return subprocess.run(TOOL + [str(a) for a in arguments], capture_output=True, text=True,
                              timeout=timeout)
    except subprocess.TimeoutExpired:
        return subprocess.CompletedProcess(arguments, "timeout", "", "timeout")


def refused(what, *arguments, code=2, says=""):
    done = run(*arguments)
    lines = done.stderr.strip().splitlines()
    check(done.returncode == code and len(lines) == 1 and "Traceback" not in done.stderr
          and says in done.stderr,
          f"{what}: exit {done.returncode}, expected {code} with one line "
          f"{('saying ' + repr(says)) if says else ''}: {done.stderr.strip()[:200]!r}")


GOOD = [(0, 0, 1.5, 1.5, 1.5), (1, 1, 3, 3, 3), (1, 2, 3, 3, 3)]
GOOD_REF = [[0, 1.0, 1.0, 1.0, 1.0], [1, 0.5, 2.0, 2.0, 2.0], [1, 0.5, 4.0, 4.0, 4.0]]

with tempfile.TemporaryDirectory() as folder:
    w = Path(folder)
    mesh, ref = w / "mesh.ply", w / "ref.json"
    mesh.write_bytes(ply_bytes(GOOD))
    ref.write_text(json.dumps(reference(GOOD_REF)))
    done = run(mesh, ref, "--json", w / "out.json")
    check(done.returncode == 0 and json.loads((w / "out.json").read_text())["element_rms"] > 0,
          f"the good case runs: {done.stderr.strip()[:200]}")

    # Files that are not files, or too much.
    os.mkfifo(w / "fifo")
    refused("a FIFO as the mesh", w / "fifo", ref, says="FIFO")
    refused("a FIFO as the reference", mesh, w / "fifo", says="FIFO")
    refused("/dev/zero as the mesh", "/dev/zero", ref, says="character device")
    refused("a folder as the reference", mesh, w, says="folder")
    refused("a missing mesh", w / "missing.ply", ref, says="missing.ply")
    # PLY headers that lie or are malformed.
    huge = mesh.read_bytes().replace(b"element vertex 9\n", b"element vertex 4000000000\n")
    (w / "huge.ply").write_bytes(huge)
    refused("a header announcing 4x10^9 vertices", w / "huge.ply", ref, says="announces")
    (w / "type.ply").write_bytes(mesh.read_bytes().replace(b"property int patch", b"property quad patch"))
    refused("an unknown property type", w / "type.ply", ref, says="header line")
    (w / "count.ply").write_bytes(mesh.read_bytes().replace(b"element face 3", b"element face x"))
    refused("a count that is not a number", w / "count.ply", ref, says="header line")
    (w / "short.ply").write_bytes(mesh.read_bytes()[:-10])
    refused("a truncated mesh", w / "short.ply", ref, says="shorter")
    (w / "text.ply").write_bytes(b"hello")
    refused("not a PLY", w / "text.ply", ref, says="not a PLY")
    # Values out of range in the mesh.
    for name, faces, says in (("NaN", [(0, 0, float("nan"), 1, 1)] + GOOD[1:], "radiosity_r"),
                              ("infinite", [(0, 0, 1, float("inf"), 1)] + GOOD[1:], "radiosity_g"),
                              ("negative", [(0, 0, 1, 1, -1.0)] + GOOD[1:], "radiosity_b"),
                              ("patch -1", [(-1, 0, 1, 1, 1)] + GOOD[1:], "patch")):
        (w / "bad.ply").write_bytes(ply_bytes(faces))
        refused(f"a {name} value in the mesh", w / "bad.ply", ref, says=says)
    # Values out of range in the reference.
    # NaN and Infinity anywhere: refused by the input gate's strict JSON, by line.
    for name, change, says in (("NaN radiosity", (0, 2, "NaN"), "NaN is not a number"),
                               ("infinite radiosity", (1, 3, "Infinity"), "Infinity is not a number"),
                               ("zero area", (2, 1, 0.0), "area"),
                               ("patch -1", (0, 0, -1), "patch"),
                               ("string area", (0, 1, "1"), "area")):
        elements = json.loads(json.dumps(GOOD_REF))
        k, field, value = change
        elements[k][field] = value
        text = json.dumps(reference(elements)).replace('"NaN"', "NaN").replace('"Infinity"', "Infinity")
        (w / "bad.json").write_text(text)
        refused(f"a {name} in the reference", mesh, w / "bad.json", says=says)
    (w / "bad.json").write_text("[" * 100000)
    refused("JSON nested 100,000 deep", mesh, w / "bad.json", says="nesting deeper")
    (w / "bad.json").write_text(json.dumps({"reference_file_version": 1, "elements": GOOD_REF}))
    refused("no self_agreement", mesh, w / "bad.json", says="self_agreement")
    (w / "bad.json").write_text(json.dumps(reference(GOOD_REF[:2])))
    refused("another scene's element count", mesh, w / "bad.json", says="elements")
    # A black reference element: no relative error, null in --json, not in the RMS.
    black = json.loads(json.dumps(GOOD_REF))
    black[0][2:] = [0.0, 0.0, 0.0]
    (w / "black.json").write_text(json.dumps(reference(black)))
    done = run(mesh, w / "black.json", "--json", w / "black-out.json", "--per-element")
    out = json.loads((w / "black-out.json").read_text()) if done.returncode == 0 else {}
    check(done.returncode == 0 and out.get("per_element", [0])[0] is None
          and "element 0 undefined" in done.stdout,
          f"a black reference element: null, 'undefined' (exit {done.returncode}: {done.stderr[:200]})")
    # --json onto an input, directly or through a link: refused, inputs unchanged.
    before = (mesh.read_bytes(), ref.read_bytes())
    (w / "link.json").symlink_to("ref.json")
    for target in (mesh, ref, w / "link.json"):
        refused(f"--json onto {target.name}", mesh, ref, "--json", target, says="is the input file")
    check((mesh.read_bytes(), ref.read_bytes()) == before, "the inputs are unchanged")
    # docs/cli.md, "Output files": a missing folder is exit 2 (as ./simulate), a folder 5.
    refused("--json into a folder that does not exist", mesh, ref, "--json", w / "no" / "out.json",
            code=2, says="does not exist")

if failures:
    print(f"{len(failures)} check(s) failed")
    sys.exit(1)
print("accuracy_inputs_test: all checks passed")
