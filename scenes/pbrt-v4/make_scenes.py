#!/usr/bin/env python3
"""Writes the pbrt-v4 scenes of this folder (the .pbrt files are committed; this is how they
were made). Every scene leaves out the Integrator statement: a render names one of
integrators/*.pbrt first on pbrt's command line (see README.md)."""
import pathlib

HERE = pathlib.Path(__file__).resolve().parent

GREY = "0.5 0.5 0.5"
# A grey conductor: eta and k constant over pbrt's visible range.
CONDUCTOR = '"spectrum eta" [ 360 0.2 830 0.2 ] "spectrum k" [ 360 3 830 3 ]'


def header(comment, lookat, fov=40, res=32):
    return (
        f"# {comment}\n"
        "# pbrt-v4 scene of Verity's cross-check (scenes/pbrt-v4/README.md). No Integrator here:\n"
        "# name one of integrators/*.pbrt before this file on pbrt's command line.\n"
        "# Scale -1 1 1: pbrt is left-handed; this makes its image match a right-handed renderer's.\n"
        "Scale -1 1 1\n"
        f"LookAt {lookat}\n"
        f'Camera "perspective" "float fov" [ {fov} ]\n'
        f'Film "rgb" "integer xresolution" [ {res} ] "integer yresolution" [ {res} ]\n'
        'PixelFilter "box" "float xradius" [ 0.5 ] "float yradius" [ 0.5 ]\n'
        'Sampler "independent" "integer pixelsamples" [ 256 ]\n'
        "WorldBegin\n"
    )


def quad(p0, p1, p2, p3):
    """Two triangles (p0,p1,p2), (p0,p2,p3); the front face, (p1-p0)x(p2-p0), emits."""
    pts = "  ".join(" ".join(f"{c:g}" for c in p) for p in (p0, p1, p2, p3))
    return ('  Shape "trianglemesh" "integer indices" [ 0 1 2 0 2 3 ]\n'
            f'      "point3 P" [ {pts} ]\n')


def block(material, shape, light=None, translate=None):
    s = "AttributeBegin\n"
    if translate:
        s += f"  Translate {translate}\n"
    if light:
        s += f"  {light}\n"
    s += f"  {material}\n{shape}AttributeEnd\n"
    return s


def sphere(r):
    return f'  Shape "sphere" "float radius" [ {r:g} ]\n'


DIFFUSE = f'Material "diffuse" "rgb reflectance" [ {GREY} ]'
BLACK = 'Material "diffuse" "rgb reflectance" [ 0 0 0 ]'

# The box: x in [-1, 1], y in [0, 2], z in [-1, 1], open towards the camera (z = -1).
# Every wall's front face looks into the box.
def box(back=DIFFUSE):
    return (block(DIFFUSE, quad((-1, 0, -1), (-1, 0, 1), (1, 0, 1), (1, 0, -1)))  # floor, +y
            + block(DIFFUSE, quad((-1, 2, -1), (1, 2, -1), (1, 2, 1), (-1, 2, 1)))  # ceiling, -y
            + block(back, quad((-1, 0, 1), (-1, 2, 1), (1, 2, 1), (1, 0, 1)))  # back, -z
            + block(DIFFUSE, quad((-1, 0, -1), (-1, 2, -1), (-1, 2, 1), (-1, 0, 1)))  # x=-1, +x
            + block(DIFFUSE, quad((1, 0, -1), (1, 0, 1), (1, 2, 1), (1, 2, -1))))  # x=+1, -x


BOX = box()
BOX_VIEW = "0 1 -3.4  0 1 0  0 1 0"
CEILING_LIGHT = block(BLACK, quad((-0.4, 1.99, -0.4), (0.4, 1.99, -0.4), (0.4, 1.99, 0.4),
                                  (-0.4, 1.99, 0.4)),
                      light='AreaLightSource "diffuse" "rgb L" [ 6 6 6 ]')


scenes = {}

AREA_BOX_SPHERES = (
    block('Material "diffuse" "rgb reflectance" [ 0.8 0.8 0.8 ]', sphere(0.45),
          translate="-0.45 0.45 0.2")
    + block(f'Material "conductor" {CONDUCTOR} "float roughness" [ 0.2 ] '
            '"bool remaproughness" false', sphere(0.4), translate="0.5 0.4 -0.2"))

scenes["area-box"] = (
    header("area-box: a grey diffuse box lit by a one-sided quad light on its ceiling; a diffuse "
           "sphere and a rough conductor sphere (GGX alpha 0.2).", BOX_VIEW)
    + BOX + CEILING_LIGHT + AREA_BOX_SPHERES)

# The referee's regression example: area-box with one material 1% brighter, the back wall's
# reflectance 0.505 for 0.5.
scenes["area-box-back-wall-1pct"] = (
    header("area-box-back-wall-1pct: area-box with its back wall's reflectance 0.505 in place "
           "of 0.5 (1% brighter), for the referee's regression example.", BOX_VIEW)
    + box(back='Material "diffuse" "rgb reflectance" [ 0.505 0.505 0.505 ]') + CEILING_LIGHT
    + AREA_BOX_SPHERES)

scenes["delta-lights"] = (
    header("delta-lights: the grey box lit by a point light and a spot light; a rough "
           "dielectric sphere (eta 1.5, GGX alpha 0.3) and a coated diffuse sphere.", BOX_VIEW)
    + BOX
    + 'LightSource "point" "rgb I" [ 1.5 1.5 1.5 ] "point3 from" [ 0.2 1.7 0.1 ]\n'
    + 'LightSource "spot" "rgb I" [ 4 4 4 ] "point3 from" [ -0.7 1.9 -0.6 ]\n'
      '    "point3 to" [ 0.3 0 0.4 ] "float coneangle" [ 25 ] "float conedeltaangle" [ 5 ]\n'
    + block('Material "dielectric" "float eta" [ 1.5 ] "float roughness" [ 0.3 ] '
            '"bool remaproughness" false', sphere(0.4), translate="0.45 0.4 0")
    + block('Material "coateddiffuse" "rgb reflectance" [ 0.5 0.5 0.5 ] "float roughness" '
            '[ 0.1 ] "bool remaproughness" false', sphere(0.4), translate="-0.5 0.4 -0.1"))

# Looking down on a large ground quad that fills the whole view, so that no pixel sees the
# infinite light directly.
scenes["env-ground"] = (
    header("env-ground: a uniform infinite light over a grey ground; a diffuse sphere, a rough "
           "dielectric sphere (eta 1.5, GGX alpha 0.3) and a diffuse-transmission panel.",
           "0 3.2 -1.6  0 0 0.3  0 1 0")
    + 'LightSource "infinite" "rgb L" [ 1 1 1 ]\n'
    + block(DIFFUSE, quad((-10, 0, -10), (-10, 0, 10), (10, 0, 10), (10, 0, -10)))
    + block(DIFFUSE, sphere(0.4), translate="-0.55 0.4 0.5")
    + block('Material "dielectric" "float eta" [ 1.5 ] "float roughness" [ 0.3 ] '
            '"bool remaproughness" false', sphere(0.4), translate="0.5 0.4 0.1")
    + block('Material "diffusetransmission" "rgb reflectance" [ 0.3 0.3 0.3 ] '
            '"rgb transmittance" [ 0.5 0.5 0.5 ]',
            quad((-0.6, 0.05, -0.2), (0.2, 0.05, -0.2), (0.2, 0.6, -0.5), (-0.6, 0.6, -0.5))))

scenes["specular-box"] = (
    header("specular-box: the grey box with its ceiling light, a smooth glass sphere (eta 1.5) "
           "and a smooth grey conductor sphere.", BOX_VIEW)
    + BOX + CEILING_LIGHT
    + block('Material "dielectric" "float eta" [ 1.5 ]', sphere(0.4), translate="-0.45 0.4 0")
    + block(f'Material "conductor" {CONDUCTOR}', sphere(0.4), translate="0.5 0.4 0.2"))

# Reduced from area-box, where lightpath disagrees with path on the pixels that see the ceiling
# light: one quad light seen obliquely, over a floor.
scenes["visible-light"] = (
    header("visible-light: a one-sided quad light (L = 6) seen obliquely by the camera, over a "
           "grey diffuse floor. Reduced from area-box for lightpath's directly visible emitters.",
           "0 1 -3.4  0 1 0  0 1 0")
    + block(DIFFUSE, quad((-1, 0, -1), (-1, 0, 1), (1, 0, 1), (1, 0, -1)))
    + block(BLACK, quad((-0.6, 1.9, -0.5), (0.6, 1.9, -0.5), (0.6, 1.2, 0.5), (-0.6, 1.2, 0.5)),
            light='AreaLightSource "diffuse" "rgb L" [ 6 6 6 ]'))

import math


def smooth_sphere(radius, rings, segments, normals=True):
    """A coarse UV sphere as one triangle mesh with per-vertex normals (the normalised
    positions): its shading normals differ from its flat triangles' normals. Faces wind so that
    their front faces point outwards."""
    pts, nrm, idx = [], [], []
    for i in range(rings + 1):
        theta = math.pi * i / rings
        for j in range(segments):
            phi = 2 * math.pi * j / segments
            d = (math.sin(theta) * math.cos(phi), math.cos(theta), math.sin(theta) * math.sin(phi))
            pts.append(tuple(radius * c for c in d))
            nrm.append(d)
    for i in range(rings):
        for j in range(segments):
            a, b = i * segments + j, i * segments + (j + 1) % segments
            c, d = a + segments, b + segments
            if i > 0:
                idx += [a, b, c]
            if i < rings - 1:
                idx += [b, d, c]
    fmt = lambda v: "  ".join(" ".join(f"{x:.6f}" for x in p) for p in v)
    return ('  Shape "trianglemesh"\n'
            f'      "integer indices" [ {" ".join(map(str, idx))} ]\n'
            f'      "point3 P" [ {fmt(pts)} ]\n'
            + (f'      "normal N" [ {fmt(nrm)} ]\n' if normals else ""))


scenes["shading-normals"] = (
    header("shading-normals: a coarse sphere (6 rings, 8 segments) with per-vertex normals, grey "
           "diffuse, lit by a one-sided quad light above it that the camera does not see.",
           "0 0.2 -3  0 0 0  0 1 0", fov=30)
    + block(BLACK, quad((-0.5, 1.5, -1.2), (0.5, 1.5, -1.2), (0.5, 1.5, -0.2), (-0.5, 1.5, -0.2)),
            light='AreaLightSource "diffuse" "rgb L" [ 6 6 6 ]')
    + block(DIFFUSE, smooth_sphere(0.7, 6, 8)))

# The control: the same triangles without per-vertex normals (flat shading).
scenes["flat-normals"] = (
    header("flat-normals: shading-normals without its per-vertex normals: the same coarse "
           "sphere, flat shaded, under the same light.", "0 0.2 -3  0 0 0  0 1 0", fov=30)
    + block(BLACK, quad((-0.5, 1.5, -1.2), (0.5, 1.5, -1.2), (0.5, 1.5, -0.2), (-0.5, 1.5, -0.2)),
            light='AreaLightSource "diffuse" "rgb L" [ 6 6 6 ]')
    + block(DIFFUSE, smooth_sphere(0.7, 6, 8, normals=False)))

for name, text in scenes.items():
    (HERE / f"{name}.pbrt").write_text(text)

# One file per integrator variant; maxdepth 5 everywhere.
INTEGRATORS = {
    "path": 'Integrator "path" "integer maxdepth" [ 5 ]',
    "volpath": 'Integrator "volpath" "integer maxdepth" [ 5 ]',
    "simplepath": 'Integrator "simplepath" "integer maxdepth" [ 5 ]',
    "simplepath-nolights": 'Integrator "simplepath" "integer maxdepth" [ 5 ] '
                           '"bool samplelights" false',
    "simplepath-nobsdf": 'Integrator "simplepath" "integer maxdepth" [ 5 ] '
                         '"bool samplebsdf" false',
    "simplepath-neither": 'Integrator "simplepath" "integer maxdepth" [ 5 ] '
                          '"bool samplelights" false "bool samplebsdf" false',
    "lightpath": 'Integrator "lightpath" "integer maxdepth" [ 5 ]',
    "bdpt": 'Integrator "bdpt" "integer maxdepth" [ 5 ]',
}
(HERE / "integrators").mkdir(exist_ok=True)
for name, line in INTEGRATORS.items():
    (HERE / "integrators" / f"{name}.pbrt").write_text(line + "\n")

# ---------------------------------------------------------------------------------------------
# Twins: scenes that exist both as pbrt-v4 and as Verity (DIRT JSON) files, written from one
# description so that both hold the same triangles, spheres, materials and camera. pbrt-v4's
# renders of them are a second independent reference for Verity (references/pbrt-v4/README.md).
import json
import re

TWIN_MATERIALS = {
    "white": ('Material "diffuse" "rgb reflectance" [ 0.5 0.5 0.5 ]',
              {"type": "lambertian", "albedo": [0.5, 0.5, 0.5]}),
    "bright": ('Material "diffuse" "rgb reflectance" [ 0.8 0.8 0.8 ]',
               {"type": "lambertian", "albedo": [0.8, 0.8, 0.8]}),
    "light": (BLACK, {"type": "diffuse_light", "emit": [6, 6, 6]}),
    "rough-conductor": (f'Material "conductor" {CONDUCTOR} "float roughness" [ 0.2 ] '
                        '"bool remaproughness" false',
                        {"type": "ggx", "ab": 0.2, "ior": 0.2, "ext": 3.0, "albedo": 1}),
    "rough-glass-0.3": ('Material "dielectric" "float eta" [ 1.5 ] "float roughness" [ 0.3 ] '
                        '"bool remaproughness" false',
                        {"type": "rough_dielectric", "distribution": "ggx", "alpha": 0.3,
                         "ior": 1.5}),
    "rough-glass-0.1": ('Material "dielectric" "float eta" [ 1.5 ] "float roughness" [ 0.1 ] '
                        '"bool remaproughness" false',
                        {"type": "rough_dielectric", "distribution": "ggx", "alpha": 0.1,
                         "ior": 1.5}),
    "glass": ('Material "dielectric" "float eta" [ 1.5 ]', {"type": "dielectric", "ior": 1.5}),
}
LIGHT_L = 6

BOX_QUADS = [
    (((-1, 0, -1), (-1, 0, 1), (1, 0, 1), (1, 0, -1)), "white"),
    (((-1, 2, -1), (1, 2, -1), (1, 2, 1), (-1, 2, 1)), "white"),
    (((-1, 0, 1), (-1, 2, 1), (1, 2, 1), (1, 0, 1)), "white"),
    (((-1, 0, -1), (-1, 2, -1), (-1, 2, 1), (-1, 0, 1)), "white"),
    (((1, 0, -1), (1, 0, 1), (1, 2, 1), (1, 2, -1)), "white"),
    (((-0.4, 1.99, -0.4), (0.4, 1.99, -0.4), (0.4, 1.99, 0.4), (-0.4, 1.99, 0.4)), "light"),
]
BOX_CAMERA = ((0, 1, -3.4), (0, 1, 0), (0, 1, 0))

TWINS = {
    "area-box": dict(
        comment="area-box: a grey diffuse box lit by a one-sided quad light on its ceiling; a "
                "diffuse sphere and a rough conductor sphere (GGX alpha 0.2).",
        camera=BOX_CAMERA, quads=BOX_QUADS,
        spheres=[((-0.45, 0.45, 0.2), 0.45, "bright"), ((0.5, 0.4, -0.2), 0.4, "rough-conductor")]),
    "rough-glass-box": dict(
        comment="rough-glass-box: the grey box with its ceiling light and two rough dielectric "
                "spheres (eta 1.5; GGX alpha 0.3 left, 0.1 right).",
        camera=BOX_CAMERA, quads=BOX_QUADS,
        spheres=[((-0.45, 0.42, 0.1), 0.42, "rough-glass-0.3"),
                 ((0.5, 0.4, -0.15), 0.4, "rough-glass-0.1")]),
    "glass-box": dict(
        comment="glass-box: the grey box with its ceiling light, a smooth glass sphere (eta 1.5) "
                "and a diffuse sphere (0.8).",
        camera=BOX_CAMERA, quads=BOX_QUADS,
        spheres=[((-0.45, 0.42, 0.1), 0.42, "glass"), ((0.5, 0.4, -0.15), 0.4, "bright")]),
    "env-spheres": dict(
        comment="env-spheres: a uniform infinite light (L = 1) over a grey ground that fills the "
                "view; a diffuse sphere (0.8) and a rough dielectric sphere (eta 1.5, GGX alpha "
                "0.3).",
        camera=((0, 3.2, -1.6), (0, 0, 0.3), (0, 1, 0)),
        quads=[(((-10, 0, -10), (-10, 0, 10), (10, 0, 10), (10, 0, -10)), "white")],
        spheres=[((-0.55, 0.4, 0.5), 0.4, "bright"), ((0.5, 0.4, 0.1), 0.4, "rough-glass-0.3")],
        background=1),
}


def vec(p):
    return " ".join(f"{c:g}" for c in p)


def twin_pbrt(name, t):
    (cf, ca, cu) = t["camera"]
    s = header(t["comment"], f"{vec(cf)}  {vec(ca)}  {vec(cu)}")
    if t.get("background"):
        b = t["background"]
        s += f'LightSource "infinite" "rgb L" [ {b} {b} {b} ]\n'
    for pts, mat in t["quads"]:
        light = (f'AreaLightSource "diffuse" "rgb L" [ {LIGHT_L} {LIGHT_L} {LIGHT_L} ]'
                 if mat == "light" else None)
        s += block(TWIN_MATERIALS[mat][0], quad(*pts), light=light)
    for centre, r, mat in t["spheres"]:
        s += block(TWIN_MATERIALS[mat][0], sphere(r), translate=vec(centre))
    return s


def twin_verity(name, t):
    (cf, ca, cu) = t["camera"]
    used = sorted({m for _, m in t["quads"]} | {m for _, _, m in t["spheres"]})
    surfaces = []
    for pts, mat in t["quads"]:
        for tri in ((pts[0], pts[1], pts[2]), (pts[0], pts[2], pts[3])):
            surfaces.append({"type": "triangle", "positions": [list(p) for p in tri],
                             "material": mat})
    for centre, r, mat in t["spheres"]:
        surfaces.append({"type": "sphere", "radius": r, "transform": {"translate": list(centre)},
                         "material": mat})
    scene = {
        "camera": {"transform": {"from": list(cf), "at": list(ca), "up": list(cu)},
                   "vfov": 40, "resolution": [32, 32]},
        "integrator": {"type": "path_tracer_mis", "max_bounces": 5},
        "sampler": {"type": "independent"},
        "image_samples": 256,
    }
    if t.get("background"):
        scene["background"] = t["background"]
    scene["materials"] = [dict(name=m, **TWIN_MATERIALS[m][1]) for m in used]
    scene["surfaces"] = surfaces
    text = json.dumps(scene, indent=2)
    # Lists of numbers on one line.
    return re.sub(r"\[\s*([-0-9.e,\s]+?)\s*\]",
                  lambda m: "[" + ", ".join(x.strip() for x in m.group(1).split(",")) + "]",
                  text) + "\n"


for name, t in TWINS.items():
    (HERE / f"{name}.pbrt").write_text(twin_pbrt(name, t))
    (HERE / f"{name}.json").write_text(twin_verity(name, t))
