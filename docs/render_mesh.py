"""Renders a solution mesh (./simulate --mesh out.ply) in Blender (Debian: blender), headless,
to show that the exported radiosity is a real mesh a viewer can look at from anywhere.

    blender -b -P docs/render_mesh.py -- out.ply picture.png [eye_x eye_y eye_z target_x target_y target_z [fov_deg]]

Each face is drawn with an emission shader fed by the vertex colours (the tone-mapped
radiosity), under the "Standard" view transform, so the picture shows the exported colours
as they are, without Blender lighting anything itself."""
import math
import sys

import bpy
from mathutils import Vector

args = sys.argv[sys.argv.index("--") + 1:]
mesh_file, picture = args[0], args[1]
view = [float(v) for v in args[2:8]] if len(args) >= 8 else None
fov_deg = float(args[8]) if len(args) >= 9 else 40.0

bpy.ops.wm.read_factory_settings(use_empty=True)
bpy.ops.import_mesh.ply(filepath=mesh_file)
model = bpy.context.selected_objects[0]
# The simulator's scenes are y-up, Blender's world is z-up: turn the model a quarter about x,
# (x, y, z) -> (x, -z, y), and the given camera with it.
model.rotation_euler = (math.pi / 2, 0.0, 0.0)
bpy.context.view_layer.update()


def z_up(p):
    return Vector((p[0], -p[2], p[1]))


material = bpy.data.materials.new("radiosity")
material.use_nodes = True
nodes, links = material.node_tree.nodes, material.node_tree.links
nodes.clear()
colours = nodes.new("ShaderNodeVertexColor")
colours.layer_name = model.data.color_attributes[0].name
emission = nodes.new("ShaderNodeEmission")
output = nodes.new("ShaderNodeOutputMaterial")
links.new(colours.outputs["Color"], emission.inputs["Color"])
links.new(emission.outputs["Emission"], output.inputs["Surface"])
model.data.materials.append(material)

# The camera: given (the scene's own convention: y up), or from outside the model's bounding
# box looking at its centre.
corners = [model.matrix_world @ Vector(c) for c in model.bound_box]
centre = sum(corners, Vector()) / 8
size = max((c - centre).length for c in corners)
eye = z_up(view[0:3]) if view else centre + Vector((0.9, -1.6, 0.7)) * size
target = z_up(view[3:6]) if view else centre
lens = bpy.data.cameras.new("camera")
lens.sensor_fit = "VERTICAL"
lens.angle = math.radians(fov_deg)
camera = bpy.data.objects.new("camera", lens)
lens.clip_start, lens.clip_end = size * 1e-3, size * 100  # Blender's 1000 would cut big scenes
bpy.context.scene.collection.objects.link(camera)
camera.location = eye
camera.rotation_euler = (target - eye).to_track_quat("-Z", "Y").to_euler()  # z stays up
scene = bpy.context.scene
scene.camera = camera

scene.render.engine = "CYCLES"
scene.cycles.device = "CPU"
scene.cycles.samples = 16
scene.cycles.use_denoising = False
scene.view_settings.view_transform = "Standard"
scene.render.resolution_x, scene.render.resolution_y = 640, 480
scene.render.filepath = picture
bpy.ops.render.render(write_still=True)
