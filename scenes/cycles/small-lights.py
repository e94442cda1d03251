"""Three small, bright point lights (radius 1 cm, 60 W each, red, green and blue) over a
diffuse floor and a smooth-ish glossy sphere (GGX, roughness 0.05), in a grey room: tiny
highlights and the rare glossy paths that find the lights, where clamping bites. See
cycles_setup.py."""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bpy  # noqa: E402

import cycles_setup as setup  # noqa: E402

args = setup.options(__file__, __doc__.splitlines()[0])
scene = setup.empty_scene()

grey = setup.material("grey", "ShaderNodeBsdfDiffuse", Color=(0.5, 0.5, 0.5, 1))
bpy.ops.mesh.primitive_plane_add(size=6, location=(0, 0, 0))
setup.with_material(bpy.context.object, grey)
bpy.ops.mesh.primitive_plane_add(size=6, location=(0, 2.5, 3), rotation=(math.pi / 2, 0, 0))
setup.with_material(bpy.context.object, grey)
bpy.ops.mesh.primitive_uv_sphere_add(radius=0.6, location=(0, 0.4, 0.6), segments=64,
                                     ring_count=32)
bpy.ops.object.shade_smooth()
setup.with_material(bpy.context.object,
                    setup.material("glossy", "ShaderNodeBsdfGlossy", Color=(0.95, 0.95, 0.95, 1),
                                   Roughness=0.05))

for (x, y, z), color in (((-1.2, -0.5, 1.4), (1, 0.2, 0.2)), ((0, -0.9, 1.9), (0.2, 1, 0.2)),
                         ((1.2, -0.3, 1.2), (0.2, 0.2, 1))):
    light = bpy.data.lights.new("point", "POINT")
    light.energy = 60 * args.emission_scale
    light.shadow_soft_size = 0.01
    light.color = color
    obj = bpy.data.objects.new("point", light)
    obj.location = (x, y, z)
    scene.collection.objects.link(obj)

world = bpy.data.worlds.new("black")
world.color = (0, 0, 0)
scene.world = world
setup.camera(location=(0, -4.0, 1.5), rotation=(math.radians(78), 0, 0), lens=35)
setup.render(args)
