"""A glossy monkey head (GGX, roughness 0.3) and a diffuse one on a grey ground, lit only by a
sky (Cycles' Hosek-Wilkie model, the sun 35° above the horizon): the environment's importance
sampling and the glossy paths that see it. See cycles_setup.py."""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bpy  # noqa: E402

import cycles_setup as setup  # noqa: E402

args = setup.options(__file__, __doc__.splitlines()[0])
setup.empty_scene()

bpy.ops.mesh.primitive_plane_add(size=20, location=(0, 0, 0))
setup.with_material(bpy.context.object,
                    setup.material("ground", "ShaderNodeBsdfDiffuse", Color=(0.4, 0.4, 0.4, 1)))
for x, mat in ((-0.8, setup.material("glossy", "ShaderNodeBsdfGlossy", Color=(0.9, 0.7, 0.4, 1),
                                     Roughness=0.3)),
               (0.8, setup.material("diffuse", "ShaderNodeBsdfDiffuse", Color=(0.2, 0.4, 0.8, 1)))):
    bpy.ops.mesh.primitive_monkey_add(size=1.2, location=(x, 0, 0.6), rotation=(0, 0, 0))
    bpy.ops.object.shade_smooth()
    setup.with_material(bpy.context.object, mat)

world = bpy.data.worlds.new("sky")
world.use_nodes = True
nodes = world.node_tree.nodes
sky = nodes.new("ShaderNodeTexSky")
sky.sky_type = "HOSEK_WILKIE"
sky.sun_direction = (math.cos(math.radians(35)) * 0.6, math.cos(math.radians(35)) * 0.8,
                     math.sin(math.radians(35)))
sky.turbidity = 3.0
world.node_tree.links.new(sky.outputs["Color"], nodes["Background"].inputs["Color"])
nodes["Background"].inputs["Strength"].default_value = 2.0 * args.emission_scale
bpy.context.scene.world = world

setup.camera(location=(0, -4.2, 1.6), rotation=(math.radians(75), 0, 0), lens=35)
setup.render(args)
