"""Runs inside Blender, imported by bake_in_blender.py and camera_in_blender.py: the scene a
job of analysis/cycles/cycles_answers.py describes, built once for both of Cycles' estimators
(docs/accuracy.md, "Against Cycles"), with the render settings they share.

Each quad is one Blender object of two triangles (v0 v1 v2) and (v0 v2 v3), with the UV
corners (0,0) (1,0) (1,1) (0,1), so a bake's texels cover the quad exactly; its own material:
  front (Backfacing = 0): Diffuse BSDF (colour rho) + Emission (colour E, strength 1)
  back  (Backfacing = 1): black: an Emission of strength 0 and no BSDF, so a path that
         reaches a back ends there: opaque backs, one-sided emitters and receivers.
"""
import bpy


def material_for(name, rho, emission):
    mat = bpy.data.materials.new(name)
    mat.use_nodes = True
    nodes, links = mat.node_tree.nodes, mat.node_tree.links
    nodes.clear()
    out = nodes.new("ShaderNodeOutputMaterial")
    geometry = nodes.new("ShaderNodeNewGeometry")
    mix = nodes.new("ShaderNodeMixShader")
    add = nodes.new("ShaderNodeAddShader")
    diffuse = nodes.new("ShaderNodeBsdfDiffuse")
    diffuse.inputs["Color"].default_value = (*rho, 1.0)
    diffuse.inputs["Roughness"].default_value = 0.0  # Lambert, not Oren-Nayar
    emit = nodes.new("ShaderNodeEmission")
    emit.inputs["Color"].default_value = (*emission, 1.0)
    emit.inputs["Strength"].default_value = 1.0
    black = nodes.new("ShaderNodeEmission")
    black.inputs["Strength"].default_value = 0.0
    links.new(diffuse.outputs[0], add.inputs[0])
    links.new(emit.outputs[0], add.inputs[1])
    links.new(geometry.outputs["Backfacing"], mix.inputs["Fac"])
    links.new(add.outputs[0], mix.inputs[1])     # Fac 0: the front
    links.new(black.outputs[0], mix.inputs[2])   # Fac 1: the back
    links.new(mix.outputs[0], out.inputs["Surface"])
    texture = nodes.new("ShaderNodeTexImage")   # a bake's target: the active image node
    nodes.active = texture
    return mat, texture


def build(job):
    """The job's scene in an empty Blender file: (scene, objects, textures, normals), one of
    each per quad in the job's order; the textures are the materials' (empty) image nodes."""
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    scene.render.engine = "CYCLES"
    cycles = scene.cycles
    cycles.device = "CPU"
    cycles.samples = job["samples"]
    cycles.use_adaptive_sampling = False
    cycles.use_denoising = False
    cycles.sampling_pattern = "SOBOL"          # PMJ read 0.2 % low in a furnace
    cycles.max_bounces = job["bounces"]
    cycles.diffuse_bounces = job["bounces"]
    cycles.glossy_bounces = cycles.transmission_bounces = cycles.volume_bounces = 0
    cycles.transparent_max_bounces = 0
    cycles.min_light_bounces = 0               # Russian roulette after that: unbiased
    cycles.sample_clamp_direct = 0.0           # no clamping
    cycles.sample_clamp_indirect = 0.0
    cycles.light_sampling_threshold = 0.0      # no light ignored
    cycles.blur_glossy = 0.0
    scene.render.threads_mode = "FIXED"
    scene.render.threads = job["threads"]
    world = bpy.data.worlds.new("black")
    world.use_nodes = True
    world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.0
    scene.world = world
    objects, textures, normals = [], [], []
    for q, quad in enumerate(job["quads"]):
        patch = job["patches"][quad["patch"]]
        mesh = bpy.data.meshes.new(f"quad{q}")
        mesh.from_pydata([tuple(c) for c in quad["corners"]], [], [(0, 1, 2), (0, 2, 3)])
        uv = mesh.uv_layers.new(name="bake")
        corner_uv = {0: (0.0, 0.0), 1: (1.0, 0.0), 2: (1.0, 1.0), 3: (0.0, 1.0)}
        for loop in mesh.loops:
            uv.data[loop.index].uv = corner_uv[loop.vertex_index]
        mesh.update()
        normals.append([list(p.normal) for p in mesh.polygons])
        obj = bpy.data.objects.new(f"quad{q}", mesh)
        scene.collection.objects.link(obj)
        mat, texture = material_for(f"m{q}", patch["rho"], patch["emission"])
        mesh.materials.append(mat)
        objects.append(obj)
        textures.append(texture)
    return scene, objects, textures, normals
