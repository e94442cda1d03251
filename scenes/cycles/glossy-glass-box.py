"""A Cornell box lit by a small area light in its ceiling, holding a glossy sphere (GGX,
roughness 0.2) and a glass sphere (index 1.5, smooth), whose caustic falls on the floor: what
Cycles' clamping, "filter glossy" and caustics options change. See cycles_setup.py."""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bpy  # noqa: E402

import cycles_setup as setup  # noqa: E402

args = setup.options(__file__, __doc__.splitlines()[0])
setup.empty_scene()

white = setup.material("white", "ShaderNodeBsdfDiffuse", Color=(0.73, 0.73, 0.73, 1))
red = setup.material("red", "ShaderNodeBsdfDiffuse", Color=(0.65, 0.05, 0.05, 1))
green = setup.material("green", "ShaderNodeBsdfDiffuse", Color=(0.12, 0.45, 0.15, 1))


def wall(location, rotation, mat):
    bpy.ops.mesh.primitive_plane_add(size=2, location=location, rotation=rotation)
    setup.with_material(bpy.context.object, mat)


half = math.pi / 2
wall((0, 0, 0), (0, 0, 0), white)             # floor
wall((0, 0, 2), (math.pi, 0, 0), white)       # ceiling
wall((0, 1, 1), (half, 0, 0), white)          # back
wall((-1, 0, 1), (0, half, 0), red)           # left
wall((1, 0, 1), (0, -half, 0), green)         # right

# The light: a small emitting square just below the ceiling, facing down.
bpy.ops.mesh.primitive_plane_add(size=0.5, location=(0, 0, 1.98), rotation=(math.pi, 0, 0))
setup.with_material(bpy.context.object, setup.emission("light", 40.0 * args.emission_scale))

bpy.ops.mesh.primitive_uv_sphere_add(radius=0.35, location=(-0.4, 0.3, 0.35), segments=48,
                                     ring_count=24)
bpy.ops.object.shade_smooth()
setup.with_material(bpy.context.object,
                    setup.material("glossy", "ShaderNodeBsdfGlossy", Color=(0.9, 0.9, 0.9, 1),
                                   Roughness=0.2))
bpy.ops.mesh.primitive_uv_sphere_add(radius=0.35, location=(0.45, -0.2, 0.35), segments=48,
                                     ring_count=24)
bpy.ops.object.shade_smooth()
setup.with_material(bpy.context.object,
                    setup.material("glass", "ShaderNodeBsdfGlass", Color=(1, 1, 1, 1),
                                   Roughness=0.0, IOR=1.5))

setup.camera(location=(0, -3.9, 1.0), rotation=(half, 0, 0), lens=38)
world = bpy.data.worlds.new("black")  # no light but the box's
world.color = (0, 0, 0)
bpy.context.scene.world = world
setup.render(args)
