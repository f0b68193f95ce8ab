#!/usr/bin/python3
"""The accuracy reference against Cycles' answers, patch by patch (docs/accuracy.md).

usage: analysis/cycles/compare.py REFERENCE.json CYCLES.json [--per-patch] [--json OUT]

REFERENCE.json: build/reference_solution's file; CYCLES.json: analysis/cycles/cycles_answers.py's
of the same scene file (the SHA-256 must match). Per patch, on the one error measure
(analysis/ncube/error_measure.py, docs/accuracy.md "The error measure"): the symmetric relative
difference d_p = (Y_ref - Y_cycles) / ((Y_ref + Y_cycles) / 2) of the luminances (Rec. 709),
Cycles' answer the truth, a patch darker than the dark floor (1 % of the mean of the patches
that do not emit; which emit, from the scene file the reference names) left out; and d_p's
standard error from Cycles', s_p = |dd_p/dY_cycles| se_Y = 4 Y_ref se_Y / (Y_ref + Y_cycles)^2.
Printed: the area-weighted RMS of d_p (as analysis/ncube/accuracy.py's patch RMS), the largest
|d_p| and its patch, and the largest |d_p| / s_p. Exit codes: 0, 2 (unreadable files, not the
same scene, or the reference's scene file not found)."""
import argparse
import json
import math
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from ncube import accuracy, error_measure, input_file  # noqa: E402
from ncube import page  # noqa: E402

LIMIT = 64 << 20


def number(value, where, low=0.0):
    """VALUE as a finite number of at least LOW, else a ValueError naming WHERE."""
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value) \
            or value < low:
        raise ValueError(f"{where}: {value!r} is not a finite number of at least {low:g}")
    return float(value)


def compare(reference, cycles, names=("reference file", "Cycles answer file"), emits=None):
    """The reference's patches against Cycles' on the one error measure; emits: per patch
    whether it emits (None: no patch emits)."""
    if reference["scene_sha256"] != cycles["scene_sha256"]:
        raise ValueError(f"not the same scene file: reference {reference['scene_file']} "
                         f"{reference['scene_sha256'][:12]}, Cycles {cycles['scene_file']} "
                         f"{cycles['scene_sha256'][:12]}")
    rows = cycles["patches"]
    if len(rows) != len(reference["patch_luminance"]):
        raise ValueError("not the same number of patches")
    if emits is not None and len(emits) != len(rows):
        raise ValueError(f"the scene file has {len(emits)} patches, the answers {len(rows)}")
    patch, area, y_ref, y, se = [], [], [], [], []
    for index, (row, value) in enumerate(zip(rows, reference["patch_luminance"])):
        y_ref.append(number(value, f"{names[0]}: patch_luminance[{index}]"))
        where = f"{names[1]}: patches[{index}]"
        patch.append(row[0])
        area.append(number(row[1], f"{where}: area"))
        y.append(number(row[8], f"{where}: luminance"))
        se.append(number(row[9], f"{where}: standard error"))
        if area[-1] == 0.0:
            raise ValueError(f"{where}: area: 0 (a patch has an area)")
    if not any(v > 0.0 for v in y):
        raise ValueError(f"{names[1]}: no patch with a luminance above 0 (nothing to compare)")
    emitting = [False] * len(rows) if emits is None else list(emits)
    floor = error_measure.dark_floor(y, area, emitting)
    kept = error_measure.kept(y, floor)
    d = error_measure.difference(y_ref, y)
    per_patch = []
    for k in range(len(rows)):
        if not kept[k]:
            continue
        total = y_ref[k] + y[k]
        s = 4 * y_ref[k] * se[k] / (total * total) if total > 0 else 0.0
        per_patch.append({"patch": patch[k], "area": area[k], "reference": y_ref[k], "cycles": y[k],
                          "difference": float(d[k]), "cycles_se": s})
    worst = max(per_patch, key=lambda p: abs(p["difference"]))
    area_total = sum(p["area"] for p in per_patch)
    return {"measure": "error_measure: symmetric relative difference, dark floor "
                       f"{error_measure.FLOOR:g} of the non-emitting mean",
            "patch_rms": error_measure.rms(y_ref, y, area, floor),
            "patch_max": abs(worst["difference"]), "worst_patch": worst["patch"],
            "left_out_patches": len(rows) - len(per_patch),
            "largest_sigmas": max((abs(p["difference"]) / p["cycles_se"] for p in per_patch
                                   if p["cycles_se"] > 0), default=math.inf),
            "cycles_se_rms": math.sqrt(sum(p["area"] * p["cycles_se"] ** 2 for p in per_patch) / area_total),
            "per_patch": per_patch}


# What each file must hold at its top (the rest is checked where it is used, by number()).
SHAPES = {"reference file": {"scene_sha256": str, "scene_file": str, "patch_luminance": list},
          "Cycles answer file": {"scene_sha256": str, "scene_file": str, "patches": list}}


def load(path, what):
    """The file through the input gate, with the items compare() reads of the right types;
    else a ValueError naming the file and the item."""
    document = input_file.read_json(path, what, LIMIT)
    if not isinstance(document, dict):
        raise ValueError(f"{path}: {what}: not a JSON object")
    for item, kind in SHAPES[what].items():
        if not isinstance(document.get(item), kind):
            raise ValueError(f"{path}: {what}: {item}: missing or not a {kind.__name__}")
    if what == "Cycles answer file":
        for index, row in enumerate(document["patches"]):
            if not isinstance(row, list) or len(row) < 10:
                raise ValueError(f"{path}: {what}: patches[{index}]: not a row of 10 numbers")
    return document


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("reference")
    parser.add_argument("cycles")
    parser.add_argument("--per-patch", action="store_true")
    parser.add_argument("--json")
    args = parser.parse_args(argv)
    try:
        reference = load(args.reference, "reference file")
        cycles = load(args.cycles, "Cycles answer file")
        result = compare(reference, cycles, (args.reference, args.cycles),
                         accuracy.scene_emits(reference, args.reference))
    except (input_file.InputFileError, accuracy.AccuracyError, ValueError, KeyError, TypeError,
            IndexError) as e:
        print(f"compare: {e if not isinstance(e, (KeyError, IndexError)) else 'a field is missing: ' + str(e)}",
              file=sys.stderr)
        return 2
    if args.json:   # before anything is printed: a refusal is the only line (exit 2 or 5)
        page.check_outputs("compare", [args.json], folders_made=False, replace_committed=False)
    print(f"patch RMS {result['patch_rms']:.4f}  largest patch {result['patch_max']:.4f} "
          f"(patch {result['worst_patch']})  largest |d|/se {result['largest_sigmas']:.1f}  "
          f"Cycles' own se (RMS) {result['cycles_se_rms']:.4f}  patches left out (darker than the "
          f"floor) {result['left_out_patches']}")
    if args.per_patch:
        for p in result["per_patch"]:
            print(f"  patch {p['patch']:4d}  reference {p['reference']:.6g}  Cycles {p['cycles']:.6g}"
                  f"  d {p['difference']:+.4f}  se {p['cycles_se']:.4f}")
    if args.json:
        return page.write_output("compare", "--json", args.json,
                                 json.dumps(result, indent=1, allow_nan=False) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
