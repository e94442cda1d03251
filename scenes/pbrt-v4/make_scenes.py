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
BOX = (block(DIFFUSE, quad((-1, 0, -1), (-1, 0, 1), (1, 0, 1), (1, 0, -1)))  # floor, +y
       + block(DIFFUSE, quad((-1, 2, -1), (1, 2, -1), (1, 2, 1), (-1, 2, 1)))  # ceiling, -y
       + block(DIFFUSE, quad((-1, 0, 1), (-1, 2, 1), (1, 2, 1), (1, 0, 1)))  # back, -z
       + block(DIFFUSE, quad((-1, 0, -1), (-1, 2, -1), (-1, 2, 1), (-1, 0, 1)))  # x=-1, +x
       + block(DIFFUSE, quad((1, 0, -1), (1, 0, 1), (1, 2, 1), (1, 2, -1))))  # x=+1, -x
BOX_VIEW = "0 1 -3.4  0 1 0  0 1 0"
CEILING_LIGHT = block(BLACK, quad((-0.4, 1.99, -0.4), (0.4, 1.99, -0.4), (0.4, 1.99, 0.4),
                                  (-0.4, 1.99, 0.4)),
                      light='AreaLightSource "diffuse" "rgb L" [ 6 6 6 ]')


scenes = {}

scenes["area-box"] = (
    header("area-box: a grey diffuse box lit by a one-sided quad light on its ceiling; a diffuse "
           "sphere and a rough conductor sphere (GGX alpha 0.2).", BOX_VIEW)
    + BOX + CEILING_LIGHT
    + block('Material "diffuse" "rgb reflectance" [ 0.8 0.8 0.8 ]', sphere(0.45),
            translate="-0.45 0.45 0.2")
    + block(f'Material "conductor" {CONDUCTOR} "float roughness" [ 0.2 ] '
            '"bool remaproughness" false', sphere(0.4), translate="0.5 0.4 -0.2"))

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
