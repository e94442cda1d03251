"""What every Cycles scene of this folder shares: its command line, and the render settings
that make a render a referee's sample.

A scene script is run by Blender, headless and without the user's preferences:

    blender -b --factory-startup --python scenes/cycles/SCENE.py -- \\
        --seed {seed} --spp {spp} --out {out} [options]

It builds its scene from nothing (no .blend file is kept), then calls render(). Each render
is independent: its own seed, no animated seed, adaptive sampling and denoising off, a fixed
number of threads, the image written as a 32-bit float OpenEXR (R, G, B, A) of the scene's
linear light, exactly at {out}. The options change what the referee is asked to decide:
Cycles' sampling pattern, clamping, "filter glossy" and caustics.
"""
import argparse
import os
import sys

import bpy


def options(script, description):
    """The arguments after Blender's `--`, checked; a bad one exits with status 2 naming it
    (Blender passes that status on when run with --python-exit-code 2)."""
    parser = argparse.ArgumentParser(prog=os.path.basename(script), description=description)
    parser.add_argument("--seed", type=int, required=True, help="Cycles' seed")
    parser.add_argument("--spp", type=int, default=16, help="samples per pixel")
    parser.add_argument("--out", required=True, help="the OpenEXR file to write")
    parser.add_argument("--threads", type=int, default=1, help="render threads (default 1)")
    parser.add_argument("--width", type=int, default=64)
    parser.add_argument("--height", type=int, default=48)
    parser.add_argument("--pattern", choices=["sobol", "pmj"], default="sobol",
                        help="sampling pattern: Sobol or progressive multi-jitter")
    parser.add_argument("--clamp-direct", type=float, default=0.0,
                        help="sample_clamp_direct (0: off)")
    parser.add_argument("--clamp-indirect", type=float, default=0.0,
                        help="sample_clamp_indirect (0: off; Blender's default is 10)")
    parser.add_argument("--blur-glossy", type=float, default=0.0,
                        help="'filter glossy' (blur_glossy; 0: off; Blender's default is 1)")
    parser.add_argument("--caustics", choices=["on", "off"], default="on",
                        help="reflective and refractive caustics")
    parser.add_argument("--max-bounces", type=int, default=12, help="max_bounces")
    parser.add_argument("--emission-scale", type=float, default=1.0,
                        help="every light's strength times this (1.01: a change of 1%%)")
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    args = parser.parse_args(argv)
    for name in ("spp", "threads", "width", "height", "max_bounces"):
        if getattr(args, name) < 1:
            parser.error(f"--{name.replace('_', '-')} must be at least 1, not {getattr(args, name)}")
    if not args.emission_scale > 0:
        parser.error(f"--emission-scale must be positive, not {args.emission_scale}")
    if args.seed < 0:
        parser.error(f"--seed must be at least 0, not {args.seed}")
    return args


def empty_scene():
    """The factory scene without its cube, light and camera."""
    for obj in list(bpy.data.objects):
        bpy.data.objects.remove(obj, do_unlink=True)
    return bpy.context.scene


def material(name, shader, **inputs):
    """A material of one BSDF node (e.g. 'ShaderNodeBsdfDiffuse') with the given inputs."""
    m = bpy.data.materials.new(name)
    m.use_nodes = True
    nodes = m.node_tree.nodes
    nodes.clear()
    bsdf = nodes.new(shader)
    for key, value in inputs.items():
        bsdf.inputs[key].default_value = value
    out = nodes.new("ShaderNodeOutputMaterial")
    m.node_tree.links.new(bsdf.outputs[0], out.inputs["Surface"])
    return m


def emission(name, strength, color=(1, 1, 1, 1)):
    return material(name, "ShaderNodeEmission", Color=color, Strength=strength)


def with_material(obj, mat):
    obj.data.materials.append(mat)
    return obj


def camera(location, rotation, lens=35.0):
    cam = bpy.data.cameras.new("camera")
    cam.lens = lens
    obj = bpy.data.objects.new("camera", cam)
    obj.location = location
    obj.rotation_euler = rotation
    bpy.context.scene.collection.objects.link(obj)
    bpy.context.scene.camera = obj
    return obj


def render(args):
    """Renders the scene built so far as the arguments say and writes args.out."""
    scene = bpy.context.scene
    scene.render.engine = "CYCLES"
    c = scene.cycles
    c.device = "CPU"
    c.samples = args.spp
    c.seed = args.seed
    c.use_animated_seed = False
    c.use_adaptive_sampling = False
    c.use_denoising = False
    c.sampling_pattern = "SOBOL" if args.pattern == "sobol" else "PROGRESSIVE_MULTI_JITTER"
    c.sample_clamp_direct = args.clamp_direct
    c.sample_clamp_indirect = args.clamp_indirect
    c.blur_glossy = args.blur_glossy
    c.caustics_reflective = args.caustics == "on"
    c.caustics_refractive = args.caustics == "on"
    c.max_bounces = args.max_bounces
    c.diffuse_bounces = c.glossy_bounces = c.transmission_bounces = args.max_bounces
    c.transparent_max_bounces = args.max_bounces
    # No Russian roulette before this many bounces is Cycles' default; kept.
    scene.render.threads_mode = "FIXED"
    scene.render.threads = args.threads
    scene.render.resolution_x = args.width
    scene.render.resolution_y = args.height
    scene.render.resolution_percentage = 100
    scene.render.film_transparent = False
    scene.view_settings.view_transform = "Standard"
    scene.view_settings.look = "None"
    scene.view_settings.exposure = 0
    scene.view_settings.gamma = 1
    settings = scene.render.image_settings
    settings.file_format = "OPEN_EXR"
    settings.color_depth = "32"
    settings.exr_codec = "ZIP"
    settings.color_mode = "RGBA"
    scene.render.use_file_extension = False
    scene.render.filepath = args.out
    bpy.ops.render.render(write_still=True)
