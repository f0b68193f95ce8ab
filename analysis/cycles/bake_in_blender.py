"""Runs inside Blender (`blender -b --factory-startup -P bake_in_blender.py -- JOB.json`): the
Cycles side of analysis/cycles/cycles_answers.py, which writes JOB.json and reads what this
writes. Nothing here decides a number of the answer: it builds the scene the job describes,
bakes Cycles' diffuse lighting (direct + indirect, without the surface's colour) onto every
quad of it once per seed, and saves the raw texels as float32 next to the job
(`<job>.texels-<seed>.npy`: every quad's res x res x 3 values in turn, rows along v), and
`<job>.report.json` (Blender's version, the faces' normals as built, the bakes' seconds).

The job (written by cycles_answers.py, units already scaled there):
  quads: [{"corners": [[x,y,z] x 4], "patch": p, "res": n}], patches: [{"rho": [r,g,b],
  "emission": [r,g,b]}], samples, seeds, bounces, threads.
The scene and the settings both estimators share: blender_scene.py.
"""
import json
import os
import sys
import time

import bpy
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import blender_scene  # noqa: E402


def main():
    job_path = sys.argv[sys.argv.index("--") + 1]
    job = json.load(open(job_path))
    scene, objects, textures, normals = blender_scene.build(job)
    cycles = scene.cycles
    scene.render.bake.margin = 0
    scene.render.bake.use_clear = True
    images = []
    for q, quad in enumerate(job["quads"]):
        image = bpy.data.images.new(f"img{q}", quad["res"], quad["res"], float_buffer=True)
        image.colorspace_settings.name = "Non-Color"   # raw values, no view transform
        textures[q].image = image
        images.append(image)
    bpy.ops.object.select_all(action="DESELECT")
    for obj in objects:
        obj.select_set(True)
    bpy.context.view_layer.objects.active = objects[0]
    report = {"blender": bpy.app.version_string, "normals": normals, "seconds": []}
    for seed in job["seeds"]:
        cycles.seed = seed
        start = time.time()
        bpy.ops.object.bake(type="DIFFUSE", pass_filter={"DIRECT", "INDIRECT"}, margin=0,
                            use_clear=True, target="IMAGE_TEXTURES")
        report["seconds"].append(time.time() - start)
        texels = []
        for image, quad in zip(images, job["quads"]):
            n = quad["res"]
            pixels = np.empty(n * n * 4, dtype=np.float32)
            image.pixels.foreach_get(pixels)
            texels.append(pixels.reshape(n, n, 4)[:, :, :3].ravel())   # row = v, column = u
        np.save(f"{job_path}.texels-{seed}.npy", np.concatenate(texels))
    json.dump(report, open(job_path + ".report.json", "w"))


main()
