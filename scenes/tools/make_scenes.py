#!/usr/bin/env python3
"""Write Verity's JSON scenes (DIRT format, see docs/scene-format.md).

The scenes in scenes/*.json are plain files that can be edited by hand; this
script is how they were first written, so that the eight Cornell-box variants
share one geometry and the numbers that must agree (light size, sphere
positions, camera) are typed once. Re-running it overwrites the scenes it
knows about (and only those), deterministically:

  python3 scenes/tools/make_scenes.py            # all scenes
  python3 scenes/tools/make_scenes.py teapot     # only scenes/teapot.json
"""

import json
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
SCENES = os.path.normpath(os.path.join(HERE, ".."))


# --- JSON output: indented objects, short arrays on one line ------------------------
def dump(value, indent=0):
    pad, pad1 = "  " * indent, "  " * (indent + 1)
    if isinstance(value, dict):
        if not value:
            return "{}"
        items = ['%s%s: %s' % (pad1, json.dumps(k), dump(v, indent + 1)) for k, v in value.items()]
        one = "{" + ", ".join('%s: %s' % (json.dumps(k), dump(v, indent + 1)) for k, v in value.items()) + "}"
        if len(one) + len(pad) <= 100 and "\n" not in one:
            return one
        return "{\n" + ",\n".join(items) + "\n" + pad + "}"
    if isinstance(value, list):
        if all(isinstance(v, (int, float)) for v in value):
            return "[" + ", ".join(num(v) for v in value) + "]"
        one = "[" + ", ".join(dump(v, indent + 1) for v in value) + "]"
        if len(one) + len(pad) <= 100 and "\n" not in one:
            return one
        return "[\n" + ",\n".join(pad1 + dump(v, indent + 1) for v in value) + "\n" + pad + "]"
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        return num(value)
    return json.dumps(value)


def num(v):
    if isinstance(v, int):
        return str(v)
    r = round(v, 6)
    if r == int(r) and abs(r) < 1e15:
        return str(int(r))
    return repr(r)


def write(name, scene):
    path = os.path.join(SCENES, name + ".json")
    text = dump(scene) + "\n"
    json.loads(text)  # must round-trip
    with open(path, "w", newline="\n") as f:
        f.write(text)
    print("wrote", os.path.relpath(path, os.path.join(SCENES, "..")))


# --- small helpers ------------------------------------------------------------------
def norm3(v):
    n = math.sqrt(sum(c * c for c in v))
    return [c / n for c in v]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def integrator(kind="path_tracer_nee", max_bounces=64):
    return {"type": kind, "max_bounces": max_bounces}


def camera(eye, at, vfov, res, up=(0, 1, 0)):
    return {"transform": {"from": list(eye), "at": list(at), "up": list(up)},
            "vfov": vfov, "resolution": list(res)}


def facing(position, target):
    """Transform for a quad centred at `position` whose normal (+z) faces `target`.

    A look-at maps local -z towards "at", so aim it at the mirror point
    2*position - target; the quad's +z then points at the target.
    """
    at = [2 * p - t for p, t in zip(position, target)]
    d = norm3([t - p for p, t in zip(position, target)])
    up = [0, 1, 0] if abs(d[1]) < 0.99 else [0, 0, 1]
    return {"from": list(position), "at": at, "up": up}


def quad(size, transform, material):
    return {"type": "quad", "size": size, "transform": transform, "material": material}


def sphere(center, radius, material):
    return {"type": "sphere", "radius": radius, "transform": {"translate": list(center)},
            "material": material}


# --- the Cornell box (geometry from the format doc) -------------------------------------------
H = 277.5            # half of the 555-unit box
LIGHT_Y = 277.0      # the 130x130 light, just below the ceiling, facing down
SPHERE_L = [-140, -177.5, -100]   # radius-100 spheres resting on the floor
SPHERE_R = [140, -177.5, 100]

CORNELL_MATERIALS = [
    {"name": "white", "type": "lambertian", "albedo": 0.73},
    {"name": "red", "type": "lambertian", "albedo": [0.65, 0.05, 0.05]},
    {"name": "green", "type": "lambertian", "albedo": [0.12, 0.45, 0.15]},
    {"name": "light", "type": "diffuse light", "emit": 15},
]


def cornell_camera():
    return camera([0, 20, 1077.5], [0, -4, 0], 40, [512, 512])


def cornell_walls(floor="white", ceiling="white", back="white", left="red", right="green",
                  floor_transform=None):
    ft = floor_transform or [{"axis": [1, 0, 0], "angle": -90}, {"translate": [0, -H, 0]}]
    return [
        quad(555, ft, floor),                                                              # normal +y
        quad(555, [{"axis": [1, 0, 0], "angle": 90}, {"translate": [0, H, 0]}], ceiling),  # normal -y
        quad(555, {"translate": [0, 0, -H]}, back),                                        # normal +z
        quad(555, [{"axis": [0, 1, 0], "angle": 90}, {"translate": [-H, 0, 0]}], left),    # normal +x
        quad(555, [{"axis": [0, 1, 0], "angle": -90}, {"translate": [H, 0, 0]}], right),   # normal -x
        quad(130, [{"axis": [1, 0, 0], "angle": 90}, {"translate": [0, LIGHT_Y, 0]}], "light"),
    ]


def cornell_scene(materials, surfaces, spp=64, kind="path_tracer_nee"):
    return {
        "camera": cornell_camera(),
        "integrator": integrator(kind, 64),
        "sampler": {"type": "independent"},
        "image_samples": spp,
        "materials": materials,
        "surfaces": surfaces,
    }


def cornell_box():
    return cornell_scene(list(CORNELL_MATERIALS), cornell_walls() + [
        sphere(SPHERE_L, 100, "white"),
        sphere(SPHERE_R, 100, "white"),
    ])


def cornell_box_glass():
    mats = list(CORNELL_MATERIALS) + [
        {"name": "mirror", "type": "metal", "albedo": 1, "roughness": 0},
        {"name": "glass", "type": "dielectric", "ior": 1.5},
    ]
    return cornell_scene(mats, cornell_walls() + [
        sphere(SPHERE_L, 100, "mirror"),
        sphere(SPHERE_R, 100, "glass"),
    ])


def textured_box():
    mats = [
        {"name": "white", "type": "lambertian", "albedo": 0.73},
        {"name": "green", "type": "lambertian", "albedo": [0.12, 0.45, 0.15]},
        {"name": "light", "type": "diffuse light", "emit": 15},
        # image textures (8-bit sRGB PNGs from scenes/tools/make_textures.py)
        {"name": "wood", "type": "lambertian",
         "albedo": {"type": "image", "filename": "textures/wood.png"}},
        {"name": "tiles", "type": "lambertian",
         "albedo": {"type": "image", "filename": "textures/tiles.png"}},
        {"name": "earth", "type": "lambertian",
         "albedo": {"type": "image", "filename": "textures/earth.png"}},
        # a solid (world-space) checker: cells of 1/scale = 66.7 units; the left
        # wall at x = -277.5 sits inside a cell layer, not on a cell boundary
        {"name": "red checker", "type": "lambertian",
         "albedo": {"type": "checker", "even": [0.65, 0.05, 0.05], "odd": 0.73, "scale": 0.015}},
        {"name": "marble", "type": "lambertian",
         "albedo": {"type": "marble", "veins": [0.08, 0.08, 0.1], "base": [0.8, 0.78, 0.74],
                    "scale": 0.02}},
    ]
    # floor: the planks run away from the camera (quad turned 90 degrees in its plane)
    floor_t = [{"axis": [0, 0, 1], "angle": 90}, {"axis": [1, 0, 0], "angle": -90},
               {"translate": [0, -H, 0]}]
    return cornell_scene(mats, cornell_walls(floor="wood", back="tiles", left="red checker",
                                             floor_transform=floor_t) + [
        sphere(SPHERE_L, 100, "marble"),
        # the earth sphere turned so that a continent faces the camera
        {"type": "sphere", "radius": 100,
         "transform": [{"axis": [0, 1, 0], "angle": 200}, {"axis": [1, 0, 0], "angle": 15},
                       {"translate": SPHERE_R}],
         "material": "earth"},
    ])


def glossy_cornell_box():
    mats = list(CORNELL_MATERIALS) + [
        # a glossy back wall: normalised Blinn-Phong lobe
        {"name": "glossy white", "type": "blinnphong", "albedo": 0.73, "exponent": 40},
        # rough conductors (DIRT's beckmann parameters; the seed report's GGX takes the same)
        {"name": "gold", "type": "ggx", "albedo": [1.0, 0.78, 0.34], "ab": 0.1,
         "ior": 0.05, "ext": 3.9},
        {"name": "brushed silver", "type": "beckmann", "albedo": [0.95, 0.95, 0.95], "ab": 0.3,
         "ior": 0.05, "ext": 3.9},
        # a rough diffuse floor
        {"name": "rough white", "type": "oren-nayar", "albedo": 0.73, "sigma": 0.5},
    ]
    return cornell_scene(mats, cornell_walls(floor="rough white", back="glossy white") + [
        sphere(SPHERE_L, 100, "gold"),
        sphere(SPHERE_R, 100, "brushed silver"),
    ], kind="path_tracer_mis")


# --- analytic / furnace scenes ---------------------------------------------------------------
def analytic_sphere(kind="path_tracer_mis"):
    # A convex lambertian sphere under a uniform environment L = 1: no
    # interreflection, so every sphere pixel is exactly albedo * L = 0.5 and
    # every background pixel is exactly 1. The sphere (radius 1, seen from 4
    # units with vfov 40) covers the middle ~70% of the frame.
    return {
        "camera": camera([0, 0, 4], [0, 0, 0], 40, [32, 32]),
        "integrator": integrator(kind, 64),
        "sampler": {"type": "independent"},
        "image_samples": 64,
        "background": 1,
        "materials": [{"name": "grey", "type": "lambertian", "albedo": 0.5}],
        "surfaces": [sphere([0, 0, 0], 1, "grey")],
    }


def furnace():
    # White furnace: every surface has albedo 1 and the environment is a uniform
    # 1, so the image is exactly 1 everywhere (energy is conserved), including
    # the teapot's concave parts, up to the (tiny) loss from capping paths at
    # 64 bounces. A darker pixel means lost energy, a brighter one invented energy.
    # The camera stays below the teapot's rim (y = 1.27): looking into the gap
    # between lid and rim would see the pot's inside, where paths need far more
    # than 64 bounces to escape, and those pixels would come out visibly dark.
    return {
        "camera": camera([0, 0.9, 9], [0, 0.8, 0], 30, [64, 48]),
        "integrator": integrator("path_tracer_mis", 64),
        "sampler": {"type": "independent"},
        "image_samples": 16,
        "background": {"type": "constant", "color": [1, 1, 1]},
        "materials": [{"name": "white", "type": "lambertian", "albedo": 1}],
        "surfaces": [
            sphere([-2.6, 1, 0], 1, "white"),
            {"type": "mesh", "filename": "meshes/teapot.obj",
             "transform": [{"axis": [1, 0, 0], "angle": -90}, {"axis": [0, 1, 0], "angle": -30},
                           {"scale": 0.5}, {"translate": [1.2, 0, 0]}],
             "material": "white"},
            quad(3, [{"axis": [0, 1, 0], "angle": 30}, {"translate": [0.3, 1.5, -2.5]}], "white"),
        ],
    }


# --- earth and teapot ------------------------------------------------------------------------------
def earth():
    return {
        "camera": camera([0, 0.8, 4.2], [0, 0, 0], 32, [512, 512]),
        "integrator": integrator("path_tracer_mis", 64),
        "sampler": {"type": "independent"},
        "image_samples": 32,
        "background": 0.02,     # faint fill so the night side is not pitch black
        "materials": [
            {"name": "earth", "type": "lambertian",
             "albedo": {"type": "image", "filename": "textures/earth.png"}},
            {"name": "sun", "type": "diffuse light", "emit": 25},
        ],
        "surfaces": [
            # the sphere's poles are its local y axis; tilt it a little like the Earth
            {"type": "sphere", "radius": 1,
             # (253 degrees about y brings the big southern continent to face the camera)
             "transform": [{"axis": [0, 1, 0], "angle": 253}, {"axis": [0, 0, 1], "angle": 23.4}],
             "material": "earth"},
            # a 3x3 "sun" to the left and a little in front: the terminator crosses the disc
            quad(3, facing([-6, 2.5, 1.5], [0, 0, 0]), "sun"),
        ],
    }


def teapot():
    return {
        "camera": camera([0, 3.2, 7.5], [0, 0.7, 0], 30, [512, 384]),
        "integrator": integrator("path_tracer_mis", 64),
        "sampler": {"type": "independent"},
        "image_samples": 32,
        "background": 0.1,
        "materials": [
            {"name": "porcelain", "type": "lambertian", "albedo": [0.8, 0.3, 0.2]},
            {"name": "floor", "type": "lambertian",
             "albedo": {"type": "checker", "even": 0.7, "odd": 0.25, "scale": 1.0}},
            {"name": "lamp", "type": "diffuse light", "emit": 12},
        ],
        "surfaces": [
            # teapot.obj is Newell's data: z-up, 6.43 x 4 x 3.15 units, standing on
            # z = 0, spout along +x. Turn z-up into y-up (-90 about x), turn the spout
            # towards the camera, halve it (1.6 units tall) and centre it.
            {"type": "mesh", "filename": "meshes/teapot.obj",
             "transform": [{"axis": [1, 0, 0], "angle": -90}, {"axis": [0, 1, 0], "angle": -25},
                           {"scale": 0.5}, {"translate": [-0.1, 0, 0]}],
             "material": "porcelain"},
            # floor at y = -0.0005 keeps the solid checker off a cell boundary
            quad(30, [{"axis": [1, 0, 0], "angle": -90}, {"translate": [0, -0.0005, 0]}], "floor"),
            quad([3, 2], facing([-2.5, 6, 3], [0, 0.5, 0]), "lamp"),
        ],
    }


# --- rows of glossy spheres --------------------------------------------------------------------------
ROW_X = [-4.4, -2.2, 0, 2.2, 4.4]
ALPHAS = [0.05, 0.1, 0.2, 0.4, 0.8]


def sphere_row_scene(materials, spp=32):
    """Five unit spheres left to right (increasing roughness) on a checker floor."""
    mats = [
        {"name": "floor", "type": "lambertian",
         # cells of 0.8 units; the floor at y = -1 lies inside a cell layer (s.y = -1.25)
         "albedo": {"type": "checker", "even": 0.6, "odd": 0.2, "scale": 1.25}},
        {"name": "lamp", "type": "diffuse light", "emit": 6},
    ] + materials
    surfaces = [sphere([x, 0, 0], 1, m["name"]) for x, m in zip(ROW_X, materials)]
    surfaces += [
        quad(60, [{"axis": [1, 0, 0], "angle": -90}, {"translate": [0, -1, 0]}], "floor"),
        # a wide strip light above and in front: its reflection shows the lobe width
        quad([12, 2.5], facing([0, 6, 5], [0, 0, 0]), "lamp"),
    ]
    return {
        "camera": camera([0, 2.2, 13], [0, 0.45, 0], 25, [640, 256]),
        "integrator": integrator("path_tracer_mis", 64),
        "sampler": {"type": "independent"},
        "image_samples": spp,
        "background": 0.15,
        "materials": mats,
        "surfaces": surfaces,
    }


def exponent_for(alpha):
    # the usual Blinn-Phong <-> Beckmann correspondence: e = 2 / alpha^2 - 2
    return round(2.0 / (alpha * alpha) - 2.0, 3)


def blinn_phong():
    return sphere_row_scene([
        {"name": "blinnphong e=%g" % exponent_for(a), "type": "blinnphong",
         "albedo": [0.9, 0.55, 0.3], "exponent": exponent_for(a)} for a in ALPHAS])


def phong():
    return sphere_row_scene([
        {"name": "phong e=%g" % exponent_for(a), "type": "phong",
         "albedo": [0.3, 0.55, 0.9], "exponent": exponent_for(a)} for a in ALPHAS])


def beckmann():
    return sphere_row_scene([
        {"name": "beckmann a=%g" % a, "type": "beckmann", "albedo": [0.95, 0.64, 0.54],
         "ab": a, "ior": 0.05, "ext": 3.9} for a in ALPHAS])


def ggx():
    return sphere_row_scene([
        {"name": "ggx a=%g" % a, "type": "ggx", "albedo": [1.0, 0.78, 0.34],
         "ab": a, "ior": 0.05, "ext": 3.9} for a in ALPHAS])


def metals():
    # measured complex indices by name (renderer/materials/named_conductors.cpp), and one
    # stated per channel; albedo 1: no tint (the default, 0.8, would darken the metal)
    named = [{"name": m, "type": "ggx", "albedo": 1, "ab": 0.15, "conductor": m}
             for m in ("Au", "Cu", "Ag", "Al")]
    rgb = {"name": "rgb index", "type": "beckmann", "albedo": 1, "ab": 0.15,
           "ior": [0.2, 0.9, 1.1], "ext": [3.9, 2.4, 2.2]}
    return sphere_row_scene(named + [rgb])


def rough_glass():
    mats = [
        {"name": "floor", "type": "lambertian",
         "albedo": {"type": "checker", "even": 0.8, "odd": 0.1, "scale": 1.25}},
        {"name": "lamp", "type": "diffuse light", "emit": 6},
        {"name": "glass", "type": "dielectric", "ior": 1.5},
        {"name": "rough glass ggx", "type": "rough_dielectric", "distribution": "ggx",
         "alpha": 0.1, "ior": 1.5},
        {"name": "frosted glass beckmann", "type": "rough_dielectric", "distribution": "beckmann",
         "alpha": 0.3, "ior": 1.5},
    ]
    return {
        "camera": camera([0, 2.2, 11], [0, 0.45, 0], 25, [512, 256]),
        "integrator": integrator("path_tracer_mis", 64),
        "sampler": {"type": "independent"},
        "image_samples": 64,
        "background": 0.3,
        "materials": mats,
        "surfaces": [
            sphere([-2.4, 0, 0], 1, "glass"),
            sphere([0, 0, 0], 1, "rough glass ggx"),
            sphere([2.4, 0, 0], 1, "frosted glass beckmann"),
            quad(60, [{"axis": [1, 0, 0], "angle": -90}, {"translate": [0, -1, 0]}], "floor"),
            quad([8, 2.5], facing([0, 6, -3], [0, 0, 0]), "lamp"),
        ],
    }


# --- Veach's multiple importance sampling scene -----------------------------------------------------------
def veach_mats():
    """Veach (1997, fig. 9.2): four glossy plates under four spherical lights.

    The plates (8 x 1) are placed and tilted as in the classic scene so that
    each mirrors the row of lights (y = 0, z = 0) towards the camera: the plate normal is the half-vector between the directions to
    the camera and to the lights. Each light emits the same power
    (radius^2 * L is constant): 0.033 / 901.8, 0.1 / 100, 0.3 / 11.1, 0.9 / 1.23.
    The plates go from nearly specular (back, top of the image) to rough (front). A fifth, far
    light dimly lights the dark backdrop, as in the original.
    """
    centres = [(-2.39513, -0.13512), (-3.06340, 0.92313), (-3.58237, 2.22305), (-3.90842, 3.57446)]
    # The classic view, from (0, 2, 15) at (0, -2, 2.5) with a 28-degree vertical field of
    # view, moved back along the same line so that the 16-degree field of view the project
    # specifies frames the same picture: distance × tan(14°) / tan(8°).
    at = [0, -2, 2.5]
    back = math.tan(math.radians(14)) / math.tan(math.radians(8))
    cam = [round(a + back * (c - a), 4) for a, c in zip(at, [0, 2, 15])]
    alphas = [0.01, 0.025, 0.05, 0.1]      # back (top of the image) to front
    mats = [
        {"name": "backdrop", "type": "lambertian", "albedo": 0.25},
        {"name": "light 0.033", "type": "diffuse light", "emit": 901.803},
        {"name": "light 0.1", "type": "diffuse light", "emit": 100},
        {"name": "light 0.3", "type": "diffuse light", "emit": 11.1111},
        {"name": "light 0.9", "type": "diffuse light", "emit": 1.23457},
        {"name": "fill light", "type": "diffuse light", "emit": 60},
    ]
    surfaces = []
    for i, ((y, z), a) in enumerate(zip(centres, alphas)):
        to_cam = norm3([cam[0], cam[1] - y, cam[2] - z])
        to_light = norm3([0, -y, -z])
        n = norm3([c + l for c, l in zip(to_cam, to_light)])
        t = cross(n, [1, 0, 0])          # along the plate, pointing up/back
        name = "plate %d (ggx a=%g)" % (i + 1, a)
        mats.append({"name": name, "type": "ggx", "albedo": 0.5, "ab": a, "ior": 0.05, "ext": 3.9})
        surfaces.append({"type": "quad", "size": [8, 1],
                         "transform": {"o": [0, y, z], "x": [1, 0, 0],
                                       "y": [round(c, 6) for c in t], "z": [round(c, 6) for c in n]},
                         "material": name})
    for x, r, m in [(-3.75, 0.033, "light 0.033"), (-1.25, 0.1, "light 0.1"),
                    (1.25, 0.3, "light 0.3"), (3.75, 0.9, "light 0.9")]:
        surfaces.append(sphere([x, 0, 0], r, m))
    surfaces.append(sphere([10, 10, 4], 0.5, "fill light"))
    # dark floor and backdrop behind/below the plates
    surfaces.append(quad(40, [{"axis": [1, 0, 0], "angle": -90}, {"translate": [0, -4.1, 0]}], "backdrop"))
    surfaces.append(quad(40, {"translate": [0, 0, -2]}, "backdrop"))
    return {
        "camera": camera(cam, at, 16, [768, 512]),
        "integrator": integrator("path_tracer_mis", 64),
        "sampler": {"type": "independent"},
        "image_samples": 32,
        "materials": mats,
        "surfaces": surfaces,
    }


ALL = {
    "cornell-box": cornell_box,
    "cornell-box-glass": cornell_box_glass,
    "textured-box": textured_box,
    "glossy-cornell-box": glossy_cornell_box,
    "analytic-sphere": analytic_sphere,
    "analytic-sphere-nee": lambda: analytic_sphere("path_tracer_nee"),
    "furnace": furnace,
    "earth": earth,
    "teapot": teapot,
    "blinn-phong": blinn_phong,
    "phong": phong,
    "beckmann": beckmann,
    "ggx": ggx,
    "metals": metals,
    "rough-glass": rough_glass,
    "veach-mats": veach_mats,
}


def main(argv):
    names = argv or list(ALL)
    for n in names:
        if n not in ALL:
            sys.exit("unknown scene %r (have: %s)" % (n, ", ".join(ALL)))
        write(n, ALL[n]())


if __name__ == "__main__":
    main(sys.argv[1:])
