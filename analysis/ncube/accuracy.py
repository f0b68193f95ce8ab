#!/usr/bin/python3
"""The accuracy of an element solution against the reference (docs/accuracy.md).

usage: analysis/ncube/accuracy.py SOLUTION.ply REFERENCE.json [--per-patch] [--per-element]
                                  [--json OUT]

SOLUTION.ply is ./simulate's --mesh of a run without --subdivide (its faces are the scene's
elements in order, each with its raw radiosity as doubles: src/models/solution_mesh.h);
REFERENCE.json is build/reference_solution's file of the same scene. Luminance is Rec. 709's,
as the simulator's (src/scene/scene.cpp: Y = 0.2126 R + 0.7152 G + 0.0722 B). The measures:

* element_rms: the area-weighted RMS of the elements' relative errors,
  r_e = (Y_e - Yref_e) / Yref_e, sqrt(sum_e A_e r_e^2 / sum_e A_e) over elements with
  Yref_e > 0 (normalising by the reference's own RMS instead would let the light, about 100
  times brighter than the walls and exact, hide every other error);
* patch_rms: the same over patches, a patch's luminance being the area-weighted mean of its
  elements' (the result file's patch_radiosity);
* patch_max: the largest relative patch error |Y_p - Yref_p| / Yref_p (patches with
  Yref_p > 0), and worst_patch, its index;
* per element and per patch (--per-element, --per-patch): (Y - Yref) / Yref.

Exit codes: 0, 2 (a file unreadable or not of the same scene's elements)."""

import sys  # noqa: E402
from pathlib import Path  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "analysis"))
from ncube.interpreter import use_project_python  # noqa: E402

use_project_python()   # Debian's /usr/bin/python3 (README.md, "Use")

import argparse
import json
import math
import struct
import sys

LUMINANCE = (0.2126, 0.7152, 0.0722)

_TYPES = {"char": "b", "uchar": "B", "short": "h", "ushort": "H", "int": "i", "uint": "I",
          "float": "f", "double": "d", "int8": "b", "uint8": "B", "int16": "h", "uint16": "H",
          "int32": "i", "uint32": "I", "float32": "f", "float64": "d"}


class AccuracyError(Exception):
    pass


def luminance(rgb):
    return sum(w * c for w, c in zip(LUMINANCE, rgb))


def read_ply(path):
    """The faces of a binary little-endian PLY as dicts of their scalar properties (and
    'vertex_indices'), and the vertices likewise."""
    try:
        with open(path, "rb") as f:
            data = f.read()
    except OSError as e:
        raise AccuracyError(f"{path}: cannot read: {e.strerror}") from None
    end = data.find(b"end_header\n")
    if not data.startswith(b"ply\n") or end < 0:
        raise AccuracyError(f"{path}: not a PLY file")
    elements = []
    for line in data[:end].decode("ascii", "replace").splitlines():
        words = line.split()
        if words[:1] == ["format"] and words[1] != "binary_little_endian":
            raise AccuracyError(f"{path}: format {words[1]}: only binary_little_endian is read")
        if words[:1] == ["element"]:
            elements.append((words[1], int(words[2]), []))
        elif words[:1] == ["property"]:
            if words[1] == "list":
                elements[-1][2].append((words[4], _TYPES[words[2]], _TYPES[words[3]]))
            else:
                elements[-1][2].append((words[2], _TYPES[words[1]], None))
    offset = end + len(b"end_header\n")
    out = {}
    try:
        for name, count, properties in elements:
            rows = []
            for _ in range(count):
                row = {}
                for prop, kind, item in properties:
                    if item is None:
                        (row[prop],) = struct.unpack_from("<" + kind, data, offset)
                        offset += struct.calcsize(kind)
                    else:
                        (n,) = struct.unpack_from("<" + kind, data, offset)
                        offset += struct.calcsize(kind)
                        row[prop] = list(struct.unpack_from(f"<{n}{item}", data, offset))
                        offset += n * struct.calcsize(item)
                rows.append(row)
            out[name] = rows
    except struct.error:
        raise AccuracyError(f"{path}: shorter than its header says") from None
    return out


def solution_from_ply(path):
    """[(patch, (r, g, b))] per face in the mesh's order."""
    ply = read_ply(path)
    faces = ply.get("face", [])
    needed = {"patch", "element", "radiosity_r", "radiosity_g", "radiosity_b"}
    if not faces or not needed <= set(faces[0]):
        raise AccuracyError(f"{path}: no faces with patch, element and radiosity_r/g/b "
                            "(not a ./simulate --mesh file)")
    for k, face in enumerate(faces):
        if face["element"] != k:
            raise AccuracyError(f"{path}: face {k} is element {face['element']}: the mesh of a "
                                "run with --subdivide has no element of the reference's grid")
    return [(f["patch"], (f["radiosity_r"], f["radiosity_g"], f["radiosity_b"])) for f in faces]


def read_reference(path):
    try:
        with open(path, encoding="utf-8") as f:
            reference = json.load(f)
    except (OSError, ValueError) as e:
        raise AccuracyError(f"{path}: cannot read the reference: {e}") from None
    if reference.get("reference_file_version") != 1 or "elements" not in reference:
        raise AccuracyError(f"{path}: not a reference file (build/reference_solution)")
    return reference


def compare(solution, reference, solution_name="solution", reference_name="reference"):
    """The measures of the module's docstring, for `solution` ([(patch, rgb)]) against the
    reference's elements ([patch, area, r, g, b] each)."""
    elements = reference["elements"]
    if len(solution) != len(elements):
        raise AccuracyError(f"{solution_name}: {len(solution)} elements, {reference_name} has "
                            f"{len(elements)}: not the same scene's element grid")
    patch_count = 1 + max(e[0] for e in elements)
    squares = weight = 0.0
    per_element = []
    patch_sum, patch_ref, patch_area = [0.0] * patch_count, [0.0] * patch_count, [0.0] * patch_count
    for k, ((patch, rgb), (ref_patch, area, *ref_rgb)) in enumerate(zip(solution, elements)):
        if patch != ref_patch:
            raise AccuracyError(f"{solution_name}: element {k} is on patch {patch}, in "
                                f"{reference_name} on patch {ref_patch}")
        y, y_ref = luminance(rgb), luminance(ref_rgb)
        if y_ref > 0:
            relative = (y - y_ref) / y_ref
            squares += area * relative ** 2
            weight += area
        else:
            relative = 0.0 if y == 0 else math.inf
        per_element.append(relative)
        patch_sum[patch] += area * y
        patch_ref[patch] += area * y_ref
        patch_area[patch] += area
    per_patch, worst, largest = [], -1, 0.0
    patch_squares = patch_weight = 0.0
    for p in range(patch_count):
        y = patch_sum[p] / patch_area[p]
        y_ref = patch_ref[p] / patch_area[p]
        if y_ref > 0:
            relative = (y - y_ref) / y_ref
            patch_squares += patch_area[p] * relative ** 2
            patch_weight += patch_area[p]
            if worst < 0 or abs(relative) > largest:
                worst, largest = p, abs(relative)
        else:
            relative = 0.0 if y == 0 else math.inf
        per_patch.append(relative)
    return {"element_rms": math.sqrt(squares / weight) if weight > 0 else 0.0,
            "patch_rms": math.sqrt(patch_squares / patch_weight) if patch_weight > 0 else 0.0,
            "patch_max": largest, "worst_patch": worst,
            "reference_element_rms": reference["self_agreement"]["element_rms"],
            "per_element": per_element, "per_patch": per_patch}


def accuracy(solution_ply, reference_json):
    return compare(solution_from_ply(solution_ply), read_reference(reference_json),
                   str(solution_ply), str(reference_json))


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("solution")
    parser.add_argument("reference")
    parser.add_argument("--per-patch", action="store_true")
    parser.add_argument("--per-element", action="store_true")
    parser.add_argument("--json", help="write every measure as JSON here")
    args = parser.parse_args(argv)
    try:
        result = accuracy(args.solution, args.reference)
    except AccuracyError as e:
        print(f"accuracy: {e}", file=sys.stderr)
        return 2
    print(f"element RMS {result['element_rms']:.4g}  patch RMS {result['patch_rms']:.4g}  "
          f"largest patch error {result['patch_max']:.4g} (patch {result['worst_patch']})  "
          f"[reference's own: element RMS {result['reference_element_rms']:.2g}]")
    if args.per_patch:
        for p, e in enumerate(result["per_patch"]):
            print(f"patch {p} {e:+.4g}")
    if args.per_element:
        for k, e in enumerate(result["per_element"]):
            print(f"element {k} {e:+.4g}")
    if args.json:
        with open(args.json, "w", encoding="utf-8") as f:
            json.dump(result, f, indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main())
