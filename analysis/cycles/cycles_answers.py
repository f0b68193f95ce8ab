#!/usr/bin/python3
"""Blender's Cycles path tracer as the accuracy reference's anchor (docs/accuracy.md):
for every patch of a scene file, its mean radiosity B = E + rho H (H the patch's mean
irradiance) with its Monte Carlo standard error, per colour.

usage: analysis/cycles/cycles_answers.py SCENE --out OUT.json [--samples S] [--seeds N]
           [--texels R] [--bounces B] [--threads T] [--blender PATH]

How (each choice checked in tests/cycles_answers_test.sh on closed forms):
* Units: radiosity does not depend on the scene's size, so the scene is scaled to a
  bounding-box diagonal of 10 Blender units (away from the float rounding of very large or very
  small coordinates). An emission E of the scene is Cycles' Emission shader of colour E and
  strength 1 (radiance E); Cycles' diffuse lighting pass without colour is then H in the
  scene's radiosity units (a surface of radiance E has radiosity pi E, and the pass is
  irradiance over pi): B = E + rho * pass. The two parallel unit squares check it.
* One-sided: only a patch's front (its corners counter-clockwise seen from it, the project's
  and Blender's convention) reflects and emits; its back is black and opaque (an Emission of
  strength 0, no BSDF: a path that reaches it ends). The world is black.
* No clamping (direct and indirect), no light ignored (light_sampling_threshold 0), Sobol
  sampling (the default progressive multi-jitter read about 0.2 % low in a furnace at
  rho = 0.8), B bounces (default 1024; Russian roulette ends paths unbiasedly before that),
  Lambert (roughness 0), no denoising, no adaptive sampling.
* The patch's mean: each quad patch is one Blender quad (triangles v0 v1 v2 and v0 v2 v3)
  whose UV layout is the whole unit square, so every texel lies wholly on the patch (no edge
  texel partly outside, which would be over-counted); a triangle patch is three such quads
  (its corner, two edge midpoints, its centroid). Cycles bakes each texel as the mean of S
  samples jittered over the texel's footprint; the patch's mean is the texels' mean weighted
  by the area each covers on the patch (a texel below the diagonal lies on the first triangle,
  above it on the second, on it half on each: the weights sum to the patch's area exactly).
  Every quad gets R x R texels, whatever its area: the texels only spread the samples over
  the patch (each is an unbiased mean of its footprint), and every patch gets as many paths,
  so that small patches are not noisier than large ones.
* The standard error: N independent bakes (Cycles seeds 0 .. N-1), the patch means' spread
  over them divided by sqrt(N); the answer is their mean.
The answer file: scene, scene_file, scene_sha256, the settings, blender version, host seconds
and per patch [patch, area, R, G, B, se_R, se_G, se_B, Y, se_Y] (Y: Rec. 709 luminance, as the
simulator's); and `seed_radiosity`, each seed's own [R, G, B] per patch (the mean and standard
error are theirs), so that a run of the first seeds alone reproduces part of a committed file:
Cycles is deterministic for a seed, and seed s renders the same whatever N. Exit codes: 0; 2 bad input or Blender missing; 5 output not writable; 7 Blender
failed."""
import argparse
import hashlib
import io
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "analysis"))
from ncube.interpreter import use_project_python  # noqa: E402

use_project_python()   # Debian's /usr/bin/python3 (README.md, "Use")

from ncube import input_file  # noqa: E402
from ncube import page  # noqa: E402

np = None   # numpy, imported by run(): --help and a refused option need none (0.2 s a start)
LUMINANCE = (0.2126, 0.7152, 0.0722)
SCENE_DIAGONAL = 10.0
BAKE_SCRIPT = Path(__file__).resolve().parent / "bake_in_blender.py"
CAMERA_SCRIPT = Path(__file__).resolve().parent / "camera_in_blender.py"


class Refusal(Exception):
    def __init__(self, message, code):
        super().__init__(message)
        self.code = code


def resolve_scene(name):
    if os.path.exists(name):
        return Path(name)
    for candidate in (name, name + ".json"):
        if (ROOT / "scenes" / candidate).exists():
            return ROOT / "scenes" / candidate
    raise Refusal(f"{name}: no such scene file (nor scenes/{name}.json)", 2)


def load_scene(path):
    data = input_file.read_input_bytes(path, "scene file", input_file.SCENE_FILE_BYTES)
    # The gate's strict JSON (nesting bounded, a NaN anywhere refused) on the bytes hashed.
    scene = input_file.read_json(path, "scene file", input_file.SCENE_FILE_BYTES)
    try:
        patches = []
        for index, patch in enumerate(scene["patches"]):
            for item in ("vertices", "reflectance", "emission"):
                values = patch.get(item, [])
                flat = [v for row in values for v in (row if isinstance(row, list) else [row])] \
                    if isinstance(values, list) else [values]
                if any(isinstance(v, bool) or not isinstance(v, (int, float)) for v in flat):
                    raise Refusal(f"{path}: patch {index}: {item}: not numbers", 2)
            corners = np.array(patch["vertices"], dtype=float)
            if corners.shape not in ((3, 3), (4, 3)):
                raise Refusal(f"{path}: patch {index}: vertices: 3 or 4 points of 3 coordinates", 2)
            if not np.isfinite(corners).all():
                raise Refusal(f"{path}: patch {index}: vertices: not finite numbers", 2)
            patches.append({"corners": corners,
                            "rho": [float(x) for x in patch.get("reflectance", [0.0] * 3)],
                            "emission": [float(x) for x in patch.get("emission", [0.0] * 3)]})
    except (ValueError, KeyError, TypeError) as e:
        raise Refusal(f"{path}: not a scene file ({e})", 2) from None
    return scene.get("name", path.stem), patches, hashlib.sha256(data).hexdigest()


def triangle_area(a, b, c):
    return 0.5 * np.linalg.norm(np.cross(b - a, c - a))


def quads_of(corners):
    """The patch as quads whose UV squares cover it exactly."""
    if len(corners) == 4:
        return [corners]
    centroid = corners.mean(axis=0)
    quads = []
    for k in range(3):
        a, b, c = corners[k], corners[(k + 1) % 3], corners[(k + 2) % 3]
        quads.append(np.array([a, 0.5 * (a + b), centroid, 0.5 * (a + c)]))
    return quads


def texel_weights(quad, n):
    """The area of the patch each of the n x n texels covers (rows along v, columns along u):
    below the diagonal (v < u) the triangle v0 v1 v2, above it v0 v2 v3, on it half each."""
    first = triangle_area(quad[0], quad[1], quad[2]) * 2.0 / (n * n)
    second = triangle_area(quad[0], quad[2], quad[3]) * 2.0 / (n * n)
    rows, columns = np.indices((n, n))
    return np.where(rows < columns, first, np.where(rows > columns, second, 0.5 * (first + second)))


REPORT_BYTES = 64 << 20   # Blender's report: the quads' normals, a few KiB


def read_bake(report_path, job_path, job, quads, texels=True):
    """Blender's report and texels through the input gate (ncube.input_file: a regular file
    within its limit, strict JSON): what Blender wrote, checked before it is used; anything
    else is a Refusal with exit 7 (the bake, not the user's input, went wrong)."""
    try:
        report = input_file.read_json(str(report_path), "Blender's report", REPORT_BYTES)
        normals = report["normals"] if isinstance(report, dict) else None
        if not isinstance(normals, list) or len(normals) != len(quads):
            raise Refusal(f"{report_path}: Blender's report: normals: not one list "
                          f"per quad ({len(quads)})", 7)
        for index, listed in enumerate(normals):
            array = np.array(listed, dtype=float) if isinstance(listed, list) else None
            if array is None or array.ndim != 2 or array.shape[1:] != (3,) \
                    or not np.isfinite(array).all():
                raise Refusal(f"{report_path}: Blender's report: normals[{index}]: "
                              "not finite 3-vectors", 7)
        per_seed = []
        for seed in (job["seeds"] if texels else []):
            path = f"{job_path}.texels-{seed}.npy"
            data = input_file.read_input_bytes(path, "Blender's texels", input_file.SCENE_FILE_BYTES)
            texels = np.load(io.BytesIO(data), allow_pickle=False)
            if not np.isfinite(texels).all():
                raise Refusal(f"{path}: Blender's texels: not finite numbers", 7)
            per_seed.append(texels)
    except input_file.InputFileError as e:
        raise Refusal(str(e), 7) from None
    except (ValueError, TypeError) as e:
        raise Refusal(f"{job_path}: Blender's output: {e}", 7) from None
    return report, per_seed


def run(args):
    global np
    import numpy as np
    scene_path = resolve_scene(args.scene)
    name, patches, sha256 = load_scene(scene_path)
    # The output under the output rule before minutes of baking (onto the scene, a folder, a
    # missing folder: one line, exit 2 or 5).
    page.check_outputs("cycles_answers", [args.out], folders_made=False)
    blender = shutil.which(args.blender)
    if blender is None:
        raise Refusal(f"--blender {args.blender}: not found (Debian: apt-get install blender)", 2)
    lo = np.min([p["corners"].min(axis=0) for p in patches], axis=0)
    hi = np.max([p["corners"].max(axis=0) for p in patches], axis=0)
    scale = SCENE_DIAGONAL / np.linalg.norm(hi - lo)
    quads = []
    for index, patch in enumerate(patches):
        for quad in quads_of(patch["corners"]):
            quads.append({"patch": index, "corners": quad})
    for quad in quads:
        quad["res"] = args.texels
    job = {"samples": args.samples, "seeds": list(range(args.seeds)), "bounces": args.bounces,
           "threads": args.threads, "pixels": args.pixels,
           "patches": [{"rho": p["rho"], "emission": p["emission"]} for p in patches],
           "quads": [{"patch": q["patch"], "res": q["res"],
                      "corners": (q["corners"] * scale).tolist()} for q in quads]}
    start = time.time()
    with tempfile.TemporaryDirectory(prefix="cycles-answers-") as scratch:
        job_path = Path(scratch) / "job.json"
        job_path.write_text(json.dumps(job))
        script = CAMERA_SCRIPT if args.estimator == "camera" else BAKE_SCRIPT
        done = subprocess.run([blender, "-b", "--factory-startup", "-t", str(args.threads),
                               "-P", str(script), "--", str(job_path)],
                              stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        report_path = Path(str(job_path) + (".camera.json" if args.estimator == "camera"
                                             else ".report.json"))
        if done.returncode != 0 or not report_path.exists():
            # One line: Blender's last words, cut (its log is hundreds of lines).
            tail = " | ".join(line.strip() for line in done.stdout.splitlines()[-3:]
                              if line.strip())[-300:]
            raise Refusal(f"blender failed (exit {done.returncode}): {tail or 'no output'}", 7)
        report, per_seed = read_bake(report_path, job_path, job, quads,
                                     texels=args.estimator != "camera")
    # The quads' normals as Blender built them face as the scene's (one-sidedness).
    for quad, normals in zip(quads, report["normals"]):
        c = quad["corners"]
        expected = np.cross(c[1] - c[0], c[2] - c[0])
        expected /= np.linalg.norm(expected)
        if min(float(np.dot(expected, n)) for n in normals) < 0.999:
            raise Refusal(f"patch {quad['patch']}: Blender's face normal is not the scene's", 7)
    area = np.zeros(len(patches))
    for quad in quads:
        area[quad["patch"]] += triangle_area(*quad["corners"][:3]) + triangle_area(
            quad["corners"][0], quad["corners"][2], quad["corners"][3])
    rho = np.array([p["rho"] for p in patches])
    emission = np.array([p["emission"] for p in patches])
    if args.estimator == "camera":
        # The pixels' sum times a pixel's area is the radiosity's integral over the patch
        # (camera_in_blender.py), in scaled units as the area below.
        scaled_area = area * scale * scale
        radiosity = np.array([[np.array(sums[str(p)]) * report["pixel_area"][str(p)] / scaled_area[p]
                               for p in range(len(patches))] for sums in report["sums"]])
    else:
        lighting = np.zeros((len(job["seeds"]), len(patches), 3))
        texel_area = np.zeros(len(patches))
        offset = 0
        for quad in quads:
            n = quad["res"]
            weights = texel_weights(quad["corners"], n)
            texel_area[quad["patch"]] += weights.sum()
            for s, texels in enumerate(per_seed):
                block = texels[offset:offset + n * n * 3].reshape(n, n, 3).astype(float)
                lighting[s, quad["patch"]] += np.einsum("ij,ijc->c", weights, block)
            offset += n * n * 3
        lighting /= texel_area[None, :, None]
        area = texel_area   # the same area to the last bit (sums of the texels' weights)
        radiosity = emission[None] + rho[None] * lighting          # seeds x patches x 3
    y = radiosity @ np.array(LUMINANCE)
    count = len(job["seeds"])
    mean, se = radiosity.mean(axis=0), radiosity.std(axis=0, ddof=1) / math.sqrt(count)
    y_mean, y_se = y.mean(axis=0), y.std(axis=0, ddof=1) / math.sqrt(count)
    rows = [[p, float(area[p])] + [float(v) for v in mean[p]] + [float(v) for v in se[p]] +
            [float(y_mean[p]), float(y_se[p])] for p in range(len(patches))]
    header = {
        "scene": name, "scene_file": scene_path.name, "scene_sha256": "sha256:" + sha256,
        "renderer": f"Blender {report['blender']} Cycles (CPU), analysis/cycles/"
                    + ("camera_in_blender.py" if args.estimator == "camera" else "bake_in_blender.py"),
    }
    if args.estimator == "camera":
        header.update({
            "method": "camera rays averaged over each patch's area (an orthographic camera on its "
                      "front, only the patch visible to camera rays, box pixel filter)",
            "estimator": "camera", "samples_per_pixel": args.samples, "seeds": count,
            "pixels_a_patch": args.pixels, "bounces": args.bounces,
            "threads": args.threads, "scale": float(scale),
            "pixels": int(sum(a * b for a, b in report["pixels"].values())),
            "camera_seconds": [round(s, 1) for s in report["seconds"]]})
    else:
        header.update({
            "method": "bake of diffuse direct + indirect lighting without colour, B = E + rho * lighting",
            "samples_per_texel": args.samples, "seeds": count, "texels_a_side": args.texels,
            "bounces": args.bounces, "threads": args.threads, "scale": float(scale),
            "texels": int(sum(q["res"] ** 2 for q in quads)),
            "bake_seconds": [round(s, 1) for s in report["seconds"]]})
    header.update({
        "host_seconds": round(time.time() - start, 1),
        "columns": ["patch", "area", "R", "G", "B", "se_R", "se_G", "se_B", "Y", "se_Y"],
        "seed_radiosity": [[[float(f"{v:.9g}") for v in radiosity[k, p]] for p in range(len(patches))]
                           for k in range(count)],
    })
    text = "{\n" + "".join(f" {json.dumps(k)}: {json.dumps(v)},\n" for k, v in header.items())
    text += ' "patches": [\n' + ",\n".join("  " + json.dumps([r[0]] + [float(f"{v:.9g}") for v in r[1:]])
                                          for r in rows) + "\n ]\n}\n"
    # Its answers are committed (analysis/cycles/SCENE.json, experiments/claims/cycles-answers).
    code = page.write_output("cycles_answers", "--out", args.out, text, replace_committed=True)
    if code:
        raise SystemExit(code)   # its one line said why
    return rows


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("scene")
    parser.add_argument("--out", required=True)
    parser.add_argument("--samples", type=int, default=256, help="Cycles samples per texel and bake")
    parser.add_argument("--seeds", type=int, default=8, help="independent bakes (the standard error)")
    parser.add_argument("--texels", type=int, default=24, help="texels a side of every quad (bake)")
    parser.add_argument("--estimator", choices=("bake", "camera"), default="bake",
                        help="bake: texels baked on every patch; camera: camera rays averaged over "
                             "each patch's area")
    parser.add_argument("--pixels", type=int, default=256,
                        help="pixels on each patch: its area over a pixel's (camera)")
    parser.add_argument("--bounces", type=int, default=1024)
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--blender", default="blender")
    args = parser.parse_args(argv)
    try:
        # Bounded before use: a bake's time and memory grow with each (seeds at least 2: the
        # standard error).
        for option, low, high in (("samples", 1, 1 << 16), ("texels", 1, 1024),
                                  ("bounces", 1, 1 << 16), ("threads", 1, 1024),
                                  ("seeds", 2, 1024), ("pixels", 16, 1 << 12)):
            if not low <= getattr(args, option) <= high:
                raise Refusal(f"--{option} {getattr(args, option)}: must be {low} to {high}"
                              + (" (the standard error)" if option == "seeds" else ""), 2)
        rows = run(args)
    except Refusal as e:
        print(f"cycles_answers: {e}", file=sys.stderr)
        return e.code
    except input_file.InputFileError as e:
        print(f"cycles_answers: {e}", file=sys.stderr)
        return 2
    except OSError as e:
        print(f"cycles_answers: {args.out}: cannot write: {e} (no output file was written)", file=sys.stderr)
        return 5
    print(f"cycles_answers: {len(rows)} patches -> {args.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
