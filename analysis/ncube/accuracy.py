#!/usr/bin/python3
"""The accuracy of an element solution against the reference (docs/accuracy.md).

usage: analysis/ncube/accuracy.py SOLUTION.ply REFERENCE.json [--per-patch] [--per-element]
                                  [--json OUT]

SOLUTION.ply is ./simulate's --mesh of a run without --subdivide (its faces are the scene's
elements in order, each with its raw radiosity as doubles: src/models/solution_mesh.h);
REFERENCE.json is build/reference_solution's file of the same scene. Luminance is Rec. 709's,
as the simulator's (src/scene/scene.cpp: Y = 0.2126 R + 0.7152 G + 0.0722 B). The measures
are the one error measure of every study (analysis/ncube/error_measure.py, docs/accuracy.md
"The error measure"):

* per element and per patch (a patch's luminance the area-weighted mean of its elements', the
  result file's patch_radiosity): the symmetric relative difference (Y - Yref) / ((Y + Yref) / 2);
  an element (patch) whose reference is below the dark floor, 1 % of the area-weighted mean of
  the reference over the non-emitting ones (which patches emit: the scene file the reference
  names), is left out (null in --json, "undefined" in the listing; counted: left_out_elements,
  left_out_patches);
* element_rms, patch_rms: the area-weighted RMS over the items kept; patch_max: the largest
  |difference| of a patch kept, and worst_patch, its index.

Every file is read through the project's input gate (ncube.input_file: regular files only, a
size limit, a FIFO or a device refused at once) and every value is checked: a face's patch and
element indices whole numbers >= 0, radiosities and areas finite and >= 0 (areas > 0), a PLY
header's counts within what its file holds. --json is written under the
output rule (ncube.output_file): never onto an input, whatever link leads there.

Exit codes: 0; 2 bad input (a file unreadable, malformed, with a value out of range, or not of
the same scene's elements; a --json path onto an input), one line naming the file, item and
field; 5 the --json file could not be written. No traceback, no partial --json file."""


import sys  # noqa: E402
from pathlib import Path  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "analysis"))
from ncube.interpreter import use_project_python  # noqa: E402

use_project_python()   # Debian's /usr/bin/python3 (README.md, "Use")

import argparse  # noqa: E402
import hashlib  # noqa: E402
import json  # noqa: E402
import math  # noqa: E402
import struct  # noqa: E402

# The error measure (numpy) is imported where it is used: a file refused, a --help, an option
# refused end without numpy's import (about as long as the rest of the run).
from ncube import input_file, page, paths  # noqa: E402

LUMINANCE = (0.2126, 0.7152, 0.0722)

_TYPES = {"char": "b", "uchar": "B", "short": "h", "ushort": "H", "int": "i", "uint": "I",
          "float": "f", "double": "d", "int8": "b", "uint8": "B", "int16": "h", "uint16": "H",
          "int32": "i", "uint32": "I", "float32": "f", "float64": "d"}


# A ./simulate --mesh of scene4 (51,200 patches at 4 x 4 elements) is about 90 MB; a reference of
# the same scene about 60 MB.
MESH_BYTES = 1 << 30
REFERENCE_BYTES = 512 << 20


class AccuracyError(Exception):
    pass


def _finite(value, what, low=0.0, strictly=False):
    """`value` as a float when it is a finite number >= low (> low when strictly), else an
    AccuracyError naming `what`."""
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value) \
            or value < low or (strictly and value == low):
        raise AccuracyError(f"{what}: {value!r} must be a finite number "
                            f"{'>' if strictly else '>='} {low:g}")
    return float(value)


def _index(value, what):
    if isinstance(value, bool) or not isinstance(value, int) or value < 0:
        raise AccuracyError(f"{what}: {value!r} must be a whole number >= 0")
    return value


def luminance(rgb):
    return sum(w * c for w, c in zip(LUMINANCE, rgb))


def read_ply(path):
    """The faces of a binary little-endian PLY as dicts of their scalar properties (and
    'vertex_indices'), and the vertices likewise."""
    try:
        data = input_file.read_input_bytes(path, "solution mesh", MESH_BYTES)
    except input_file.InputFileError as e:
        raise AccuracyError(str(e)) from None
    end = data.find(b"end_header\n")
    if not data.startswith(b"ply\n") or end < 0:
        raise AccuracyError(f"{path}: not a PLY file")
    elements = []
    for number, line in enumerate(data[:end].decode("ascii", "replace").splitlines(), 1):
        words = line.split()
        try:
            if words[:1] == ["format"] and words[1] != "binary_little_endian":
                raise AccuracyError(f"{path}: format {words[1]}: only binary_little_endian is read")
            if words[:1] == ["element"]:
                count = int(words[2])
                if count < 0:
                    raise ValueError
                elements.append((words[1], count, []))
            elif words[:1] == ["property"]:
                if not elements:
                    raise ValueError
                if words[1] == "list":
                    elements[-1][2].append((words[4], _TYPES[words[2]], _TYPES[words[3]]))
                else:
                    elements[-1][2].append((words[2], _TYPES[words[1]], None))
        except (IndexError, KeyError, ValueError):
            raise AccuracyError(f"{path}: header line {number} ({line[:60]!r}): not a PLY "
                                "element or property this reader knows") from None
    # Every row takes at least its scalars' bytes and one count per list: a header announcing
    # more rows than the file can hold is refused before any is read.
    least = sum(count * sum(struct.calcsize(kind) for _, kind, _ in properties)
                for _, count, properties in elements)
    holds = len(data) - end - len(b"end_header\n")
    if least > holds:
        raise AccuracyError(f"{path}: its header announces at least {least:,} bytes of rows, "
                            f"the file holds {holds:,}")
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
    solution = []
    for k, face in enumerate(faces):
        if _index(face["element"], f"{path}: face {k}: element") != k:
            raise AccuracyError(f"{path}: face {k} is element {face['element']}: the mesh of a "
                                "run with --subdivide has no element of the reference's grid")
        solution.append((_index(face["patch"], f"{path}: face {k}: patch"),
                         tuple(_finite(face[f"radiosity_{c}"], f"{path}: face {k}: radiosity_{c}")
                               for c in "rgb")))
    return solution


def read_reference(path):
    try:   # the gate's JSON: strict (a NaN anywhere refused), nesting bounded
        reference = input_file.read_json(path, "reference file", REFERENCE_BYTES)
    except input_file.InputFileError as e:
        raise AccuracyError(str(e)) from None
    if not isinstance(reference, dict) or reference.get("reference_file_version") != 1 \
            or not isinstance(reference.get("elements"), list) or not reference["elements"]:
        raise AccuracyError(f"{path}: not a reference file (build/reference_solution)")
    for k, element in enumerate(reference["elements"]):
        if not isinstance(element, list) or len(element) != 5:
            raise AccuracyError(f"{path}: element {k}: expected [patch, area, radiosity_r, "
                                "radiosity_g, radiosity_b]")
        _index(element[0], f"{path}: element {k}: patch")
        _finite(element[1], f"{path}: element {k}: area", strictly=True)
        for c, value in zip("rgb", element[2:]):
            _finite(value, f"{path}: element {k}: radiosity_{c}")
    agreement = reference.get("self_agreement")
    if not isinstance(agreement, dict):
        raise AccuracyError(f"{path}: self_agreement: expected an object")
    _finite(agreement.get("element_rms"), f"{path}: self_agreement: element_rms")
    return reference


def scene_emits(reference, reference_name="reference"):
    """Per patch whether it emits, from the scene file the reference names (`scene_file`),
    found by the input lookup rule (docs/cli.md, "Finding the input files") from the
    reference's own folder: beside it, then in the project's scenes/; a hand-made reference
    without one: no patch emits."""
    name = reference.get("scene_file")
    if name is None:
        return None
    base = Path(str(reference_name)).parent if reference_name != "reference" else Path.cwd()
    # The first candidate of the lookup rule that is the scene the reference was made from
    # (its scene_sha256, when it records one): a bare name may also name the reference itself,
    # as analysis/reference/<scene>.json beside scenes/<scene>.json does.
    wanted = reference.get("scene_sha256")
    path = None
    for candidate in paths.input_candidates(str(name), base, "scene"):
        if not candidate.is_file():
            continue
        try:
            data = input_file.read_input_bytes(candidate, "scene file", REFERENCE_BYTES)
        except input_file.InputFileError:
            continue
        if wanted is None or "sha256:" + hashlib.sha256(data).hexdigest() == wanted:
            path = candidate
            break
    if path is None:
        raise AccuracyError(f"{reference_name}: scene_file {name}: no such scene"
                            + (" with its scene_sha256" if wanted else "") + " ("
                            + paths.looked_for(str(name), base, "scene") + ")")
    try:
        scene = json.loads(input_file.read_input_text(path, "scene file", REFERENCE_BYTES))
        return [luminance(p.get("emission", (0.0, 0.0, 0.0))) > 0 for p in scene["patches"]]
    except input_file.InputFileError as e:
        raise AccuracyError(f"{reference_name}: scene_file: {e}") from None
    except (ValueError, KeyError, TypeError, AttributeError) as e:
        raise AccuracyError(f"{reference_name}: scene_file {path}: not a scene file ({e})") from None


def compare(solution, reference, solution_name="solution", reference_name="reference",
            emits=None):
    """The measures of docs/accuracy.md ("The error measure", analysis/ncube/error_measure.py:
    the symmetric relative difference, the dark floor) for `solution` ([(patch, rgb)]) against
    the reference's elements ([patch, area, r, g, b] each). emits: per patch whether it emits
    (default: from the reference's scene file)."""
    elements = reference["elements"]
    if len(solution) != len(elements):
        raise AccuracyError(f"{solution_name}: {len(solution)} elements, {reference_name} has "
                            f"{len(elements)}: not the same scene's element grid")
    patch_count = 1 + max(e[0] for e in elements)
    for k, ((patch, _), (ref_patch, *_)) in enumerate(zip(solution, elements)):
        if patch != ref_patch:
            raise AccuracyError(f"{solution_name}: element {k} is on patch {patch}, in "
                                f"{reference_name} on patch {ref_patch}")
    if emits is None:
        emits = scene_emits(reference, reference_name)
    if emits is None:
        emits = [False] * patch_count
    if len(emits) < patch_count:
        raise AccuracyError(f"{reference_name}: {patch_count} patches, its scene has {len(emits)}")
    from ncube import error_measure
    out = error_measure.measure([luminance(rgb) for _, rgb in solution],
                                [luminance(e[2:]) for e in elements], [e[1] for e in elements],
                                [e[0] for e in elements], list(emits)[:patch_count])
    out["reference_element_rms"] = reference["self_agreement"]["element_rms"]
    return out


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
            print(f"patch {p} " + ("undefined" if e is None else f"{e:+.4g}"))
    if args.per_element:
        for k, e in enumerate(result["per_element"]):
            print(f"element {k} " + ("undefined" if e is None else f"{e:+.4g}"))
    if args.json:
        # page.write: the output rule with docs/cli.md's exits (onto an input, a loop of links
        # or a missing folder 2; anything else 5).
        return page.write_output("accuracy", "--json", args.json,
                                 json.dumps(result, indent=1, allow_nan=False) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
