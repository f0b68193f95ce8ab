#!/usr/bin/env python3
"""The error measure (analysis/ncube/accuracy.py, docs/accuracy.md) on hand-made solutions
with answers worked out by hand, and on ./simulate's own meshes: a mesh against a reference
made from itself is exact, its faces are the reference's elements (areas from the faces'
corners), and a mesh of another grid is refused (exit 2).

usage: accuracy_test.py SIMULATE SOURCE_DIR"""
import math
import subprocess
import sys
import tempfile
from pathlib import Path

simulate, root = sys.argv[1], Path(sys.argv[2])
sys.path.insert(0, str(root / "analysis"))
from ncube import accuracy  # noqa: E402

sys.path.insert(0, str(root / "tests"))
from accuracy_test_meshes import ply_bytes, reference  # noqa: E402

failures = []


def check(condition, what):
    if not condition:
        failures.append(what)


def near(a, b, what, tolerance=1e-12):
    check(abs(a - b) <= tolerance * max(1.0, abs(b)), f"{what}: {a!r}, expected {b!r}")


with tempfile.TemporaryDirectory() as folder:
    folder = Path(folder)
    # Patch 0: one element of area 1; patch 1: two of area 1/2. Grey, so Y = the value.
    mesh = folder / "hand.ply"
    mesh.write_bytes(ply_bytes([(0, 0, 1.5, 1.5, 1.5), (1, 1, 3, 3, 3), (1, 2, 3, 3, 3)]))
    ref = reference([[0, 1.0, 1, 1, 1], [1, 0.5, 2, 2, 2], [1, 0.5, 4, 4, 4]])
    result = accuracy.compare(accuracy.solution_from_ply(mesh), ref)
    # Symmetric differences (Y - T) / ((Y + T) / 2): 0.5 / 1.25, 1 / 2.5, -1 / 3.5 on areas 1,
    # 1/2, 1/2 (no patch emits: the floor 1 % of the mean 2, every element kept).
    near(result["element_rms"], math.sqrt((0.16 + 0.5 * 0.16 + 0.5 / 3.5 ** 2) / 2), "element_rms")
    # Patches: 1.5 against 1 and 3 against 3.
    near(result["patch_max"], 0.4, "patch_max")
    check(result["worst_patch"] == 0, f"worst_patch {result['worst_patch']}")
    near(result["patch_rms"], math.sqrt(0.16 / 2), "patch_rms")
    near(result["per_element"][2], -1 / 3.5, "per_element[2]")
    near(result["per_patch"][1], 0.0, "per_patch[1]")
    # Luminance is Rec. 709's: off by 0.5, 1 and 2 in red, green and blue on a white
    # reference of Y = 1: Y = 1 + 0.2126 x 0.5 + 0.7152 + 0.0722 x 2.
    mesh.write_bytes(ply_bytes([(0, 0, 1.5, 2, 3)]))
    result = accuracy.compare(accuracy.solution_from_ply(mesh), reference([[0, 2.0, 1, 1, 1]]))
    y = 1 + 0.2126 * 0.5 + 0.7152 + 0.0722 * 2
    near(result["element_rms"], (y - 1) / ((y + 1) / 2), "luminance weights")
    # A reference of another element count or other patches is refused.
    for wrong in ([[0, 2.0, 1, 1, 1], [0, 1.0, 1, 1, 1]], [[1, 2.0, 1, 1, 1]]):
        try:
            accuracy.compare(accuracy.solution_from_ply(mesh), reference(wrong))
            failures.append(f"reference {wrong} accepted")
        except accuracy.AccuracyError:
            pass

    # ./simulate's own mesh: its faces in element order, areas as the reference's.
    cornell = folder / "cornell.ply"
    subprocess.run([simulate, str(root / "scenes/cornell-box.json"), "--iterations", "5",
                    "--quiet", "--mesh", str(cornell)], check=True)
    ply = accuracy.read_ply(cornell)
    committed = accuracy.read_reference(root / "analysis/reference/cornell-box.json")
    check(len(ply["face"]) == len(committed["elements"]),
          f"{len(ply['face'])} faces, the reference has {len(committed['elements'])} elements")
    for face, element in zip(ply["face"], committed["elements"]):
        corners = [ply["vertex"][i] for i in face["vertex_indices"]]
        p = [(c["x"], c["y"], c["z"]) for c in corners]
        normal = [0.0, 0.0, 0.0]   # Newell: twice the area vector
        for a, b in zip(p, p[1:] + p[:1]):
            normal[0] += (a[1] - b[1]) * (a[2] + b[2])
            normal[1] += (a[2] - b[2]) * (a[0] + b[0])
            normal[2] += (a[0] - b[0]) * (a[1] + b[1])
        area = 0.5 * math.sqrt(sum(c * c for c in normal))
        if abs(area - element[1]) > 1e-9 * element[1] or face["patch"] != element[0]:
            failures.append(f"face {face['element']}: patch {face['patch']} area {area}, the "
                            f"reference's element: patch {element[0]} area {element[1]}")
            break
    itself = reference([[f["patch"], e[1], f["radiosity_r"], f["radiosity_g"], f["radiosity_b"]]
                        for f, e in zip(ply["face"], committed["elements"])])
    result = accuracy.compare(accuracy.solution_from_ply(cornell), itself)
    check(result["element_rms"] == 0 and result["patch_max"] == 0, f"self: {result['element_rms']}")
    # The command: a mesh with --subdivide, or another scene's, is exit 2 with one line.
    subdivided = folder / "subdivided.ply"
    subprocess.run([simulate, str(root / "scenes/cornell-box.json"), "--iterations", "5",
                    "--subdivide", "--quiet", "--mesh", str(subdivided)], check=True)
    scene0 = folder / "scene0.ply"
    subprocess.run([simulate, str(root / "scenes/scene0.json"), "--iterations", "2",
                    "--quiet", "--mesh", str(scene0)], check=True)
    for bad in (subdivided, scene0):
        run = subprocess.run(["/usr/bin/python3", str(root / "analysis/ncube/accuracy.py"),
                              str(bad), str(root / "analysis/reference/cornell-box.json")],
                             capture_output=True, text=True)
        check(run.returncode == 2 and run.stderr.count("\n") == 1
              and run.stderr.startswith("accuracy: "),
              f"{bad.name}: exit {run.returncode}, {run.stderr!r}")
    run = subprocess.run(["/usr/bin/python3", str(root / "analysis/ncube/accuracy.py"),
                          str(cornell), str(root / "analysis/reference/cornell-box.json")],
                         capture_output=True, text=True)
    check(run.returncode == 0 and run.stdout.startswith("element RMS "),
          f"the command: exit {run.returncode}, {run.stdout!r} {run.stderr!r}")

for failure in failures:
    print("FAIL:", failure)
print("accuracy_test:", "FAILED" if failures else "passed")
sys.exit(1 if failures else 0)
