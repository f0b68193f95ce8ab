"""Runs inside Blender (`blender -b --factory-startup -P camera_in_blender.py -- JOB.json`):
Cycles' second estimator of a patch's mean radiosity (analysis/cycles/cycles_answers.py
--estimator camera; docs/accuracy.md, "Against Cycles"), independent of the bake: camera rays
averaged over each patch's area. Nothing here decides a number of the answer.

For each patch in turn, only its quads are visible to camera rays (every other quad still
casts shadows and reflects light), the world is black, and an orthographic camera looks at the
patch's front along its normal, framing it with square pixels sized so that the patch's area
is job "pixels" of them (a thin leg gets as many samples as a wall). With the box pixel filter of width 1 every camera sample falls uniformly in its pixel
and reads the radiance leaving the patch where it hits it (E + rho x irradiance / pi, the
patch's radiosity in the scene's units, as the bake's B = E + rho x pass), or 0 where it
misses: the sum of the pixels times a pixel's area is the integral of the radiosity over the
patch, whatever the pixels' grid, so no pixel is chosen or weighted by coverage. Writes
`<job>.camera.json`: per seed, per patch, the sum of the pixels' R, G, B and the pixel area
(scaled units), with Blender's version, the faces' normals as built and the renders' seconds.
"""
import json
import math
import os
import sys
import tempfile
import time

import bpy
import numpy as np
from mathutils import Matrix, Vector

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import blender_scene  # noqa: E402


def frame(corners):
    """The patch's plane: unit axes u, v, n (n the front normal, u along the first edge) and
    its corners' extent along u and v."""
    c = [Vector(x) for x in corners]
    u = (c[1] - c[0]).normalized()
    n = (c[1] - c[0]).cross(c[2] - c[0]).normalized()
    v = n.cross(u)
    return u, v, n


def main():
    job_path = sys.argv[sys.argv.index("--") + 1]
    job = json.load(open(job_path))
    scene, objects, _, normals = blender_scene.build(job)
    cycles = scene.cycles
    cycles.pixel_filter_type = "BOX"   # uniform in the pixel: the pixels tile the image plane
    cycles.filter_width = 1.0
    # Cycles puts a pixel's first sample (index 0) at its centre, not jittered: with S samples
    # a pixel, 1/S of them at centres, which read a thin patch's coverage wrong (a 0.04-wide
    # emitter straddling two pixel rows read 0.77 of its emission at S = 4, 0.986 at S = 64).
    # Skipping sample 0 leaves every sample jittered over its pixel.
    cycles.sample_offset = 1
    scene.render.film_transparent = False
    scene.render.use_compositing = False
    scene.render.use_sequencer = False
    scene.render.resolution_percentage = 100
    scene.render.pixel_aspect_x = scene.render.pixel_aspect_y = 1.0
    scene.view_settings.view_transform = "Standard"
    scene.view_settings.look = "None"
    scene.view_settings.exposure = 0.0
    scene.view_settings.gamma = 1.0
    settings = scene.render.image_settings
    settings.file_format = "OPEN_EXR"
    settings.color_depth = "32"
    settings.exr_codec = "ZIP"
    settings.color_mode = "RGB"
    camera_data = bpy.data.cameras.new("ortho")
    camera_data.type = "ORTHO"
    camera_data.sensor_fit = "AUTO"
    camera_data.clip_start = 1e-3
    camera_data.clip_end = 1e3
    camera = bpy.data.objects.new("ortho", camera_data)
    scene.collection.objects.link(camera)
    scene.camera = camera
    patches = sorted({quad["patch"] for quad in job["quads"]})
    report = {"blender": bpy.app.version_string, "normals": normals, "seconds": [], "sums": [],
              "pixel_area": {}, "pixels": {}}
    scratch = tempfile.mkdtemp(prefix="camera-")
    views = {}
    for p in patches:
        quads = [q for q, quad in enumerate(job["quads"]) if quad["patch"] == p]
        corners = [Vector(c) for q in quads for c in job["quads"][q]["corners"]]
        u, v, n = frame(job["quads"][quads[0]]["corners"])
        us = [c.dot(u) for c in corners]
        vs = [c.dot(v) for c in corners]
        extent_u, extent_v = max(us) - min(us), max(vs) - min(vs)
        area = 0.0
        for q in quads:
            c = [Vector(x) for x in job["quads"][q]["corners"]]
            area += 0.5 * ((c[1] - c[0]).cross(c[2] - c[0]).length + (c[2] - c[0]).cross(c[3] - c[0]).length)
        pixel = math.sqrt(area / job["pixels"])
        # Blender renders at least 4 x 4 pixels: a frame taller than the patch only adds misses.
        nx, ny = max(4, math.ceil(extent_u / pixel - 1e-9)), max(4, math.ceil(extent_v / pixel - 1e-9))
        centre = u * (0.5 * (max(us) + min(us))) + v * (0.5 * (max(vs) + min(vs)))
        plane = n.dot(corners[0])
        centre += n * (plane - n.dot(centre))      # on the patch's plane
        # The camera looks along its -Z with +X right and +Y up: X = u, Y = v, Z = n.
        rotation = Matrix((u, v, n)).transposed().to_4x4()
        views[p] = (quads, rotation, Matrix.Translation(centre + n * 1.0), nx, ny, pixel)
        report["pixel_area"][str(p)] = pixel * pixel
        report["pixels"][str(p)] = [nx, ny]
    for seed in job["seeds"]:
        cycles.seed = seed
        start = time.time()
        sums = {}
        for p in patches:
            quads, rotation, translation, nx, ny, pixel = views[p]
            for q, obj in enumerate(objects):
                obj.visible_camera = q in quads
            camera.matrix_world = translation @ rotation
            camera_data.ortho_scale = max(nx, ny) * pixel
            scene.render.resolution_x, scene.render.resolution_y = nx, ny
            path = os.path.join(scratch, f"p{p}-s{seed}.exr")
            scene.render.filepath = path
            bpy.ops.render.render(write_still=True)
            image = bpy.data.images.load(path)
            values = np.empty(len(image.pixels), dtype=np.float32)
            image.pixels.foreach_get(values)
            channels = image.channels
            bpy.data.images.remove(image)
            os.remove(path)
            rgb = values.reshape(-1, channels)[:, :3].astype(np.float64)
            sums[str(p)] = [float(x) for x in rgb.sum(axis=0)]
        report["sums"].append(sums)
        report["seconds"].append(time.time() - start)
    json.dump(report, open(job_path + ".camera.json", "w"))


main()
