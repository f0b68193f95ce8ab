"""Writes docs/examples/monkey-room.obj + .mtl with Blender (Debian: blender), headless: a room
(a box seen from inside), Blender's monkey head on a block and a light panel under the
ceiling, the kind of model a researcher brings from a modelling tool.

    blender -b -P docs/examples/make_monkey_room.py -- docs/examples/monkey-room.obj
"""
import sys

import bpy

out = sys.argv[sys.argv.index("--") + 1]
bpy.ops.wm.read_factory_settings(use_empty=True)


def material(name, colour, emission=None):
    m = bpy.data.materials.new(name)
    m.use_nodes = True
    bsdf = m.node_tree.nodes["Principled BSDF"]
    bsdf.inputs["Base Color"].default_value = (*colour, 1)
    if emission:
        bsdf.inputs["Emission"].default_value = (*emission, 1)
        bsdf.inputs["Emission Strength"].default_value = 1.0
    return m


def add(obj, mat):
    obj.data.materials.append(mat)
    return obj


# Blender is z-up; the OBJ exporter writes y-up (forward -z), the simulator's convention.
bpy.ops.mesh.primitive_cube_add(size=4, location=(0, 0, 2))
room = add(bpy.context.object, material("walls", (0.7, 0.7, 0.65)))
bpy.ops.object.mode_set(mode="EDIT")
bpy.ops.mesh.flip_normals()     # seen from inside
bpy.ops.object.mode_set(mode="OBJECT")
bpy.ops.mesh.primitive_plane_add(size=4, location=(0, 0, 0.001))
add(bpy.context.object, material("floor", (0.55, 0.45, 0.35)))
bpy.ops.mesh.primitive_cube_add(size=1, location=(0, 0, 0.5))
add(bpy.context.object, material("block", (0.2, 0.35, 0.6)))
bpy.ops.mesh.primitive_monkey_add(size=1.2, location=(0, 0, 1.55), rotation=(0, 0, 0.5))
add(bpy.context.object, material("monkey", (0.8, 0.55, 0.2)))
bpy.ops.mesh.primitive_plane_add(size=1.2, location=(0, 0, 3.98), rotation=(3.14159265, 0, 0))
add(bpy.context.object, material("light", (0.8, 0.8, 0.8), emission=(10, 9, 7)))
bpy.ops.wm.obj_export(filepath=out, export_selected_objects=False, export_normals=False,
                      export_uv=False, export_materials=True, forward_axis="NEGATIVE_Z",
                      up_axis="Y")
