#!/usr/bin/env python3
"""Writes scenes/malformed/: scenes that must each be rejected with a one-line error naming
the file and the JSON path (or the line and column of a syntax error), and expected.tsv,
which lists for each file the text its error must contain. Re-run after editing CASES."""
import json
import pathlib

OUT = pathlib.Path(__file__).resolve().parent.parent / "malformed"

CAMERA = {"transform": {"from": [0, 0, 5], "at": [0, 0, 0], "up": [0, 1, 0]}, "resolution": [8, 8]}
LAMB = {"type": "lambertian", "albedo": 0.5}


def scene(**extra):
    s = {"camera": CAMERA}
    s.update(extra)
    return s


def surf(**kw):
    s = {"type": "sphere", "material": LAMB}
    s.update(kw)
    return s


def mat(**kw):
    return scene(surfaces=[surf(material=kw)])


# name -> (scene object or raw text, substring the error must contain)
CASES = {
    # Syntax errors: line and column.
    "syntax-trailing-comma": ('{\n  "camera": {"vfov": 40,}\n}\n', "line 2"),
    "syntax-missing-brace": ('{\n  "camera": {"vfov": 40}\n', "line 3"),
    "syntax-bare-word": ('{\n  "camera": {"vfov": forty}\n}\n', "line 2, column 23"),
    "syntax-empty-file": ("", "line 1"),
    "syntax-single-quotes": ("{'camera': {}}\n", "line 1, column 2"),
    "syntax-nan-literal": ('{"camera": {"vfov": NaN}}\n', "column"),
    "syntax-number-overflow": ('{"camera": {"vfov": 1e999}}\n', "number overflow"),
    "not-an-object": ("[1, 2, 3]\n", "must be a JSON object"),
    "syntax-nul-byte": ('{"camera": {"vfov": 40}}\n\0{"garbage"\n', "line 2, column 1: a NUL byte"),
    "duplicate-key": ('{"camera": {"vfov": 40, "resolution": [8, 8], "vfov": 50}}\n', "camera.vfov: the key appears twice"),
    "duplicate-key-in-array": ('{"camera": {"resolution": [8, 8]}, "surfaces": [{"type": "sphere"}, {"type": "sphere", "radius": 1, "radius": 2}]}\n', "surfaces[1].radius: the key appears twice"),
    # Top level.
    "missing-camera": ({"surfaces": []}, 'missing required key "camera"'),
    "unknown-top-key": (scene(lights=[]), "lights: unknown key"),
    "image-samples-zero": (scene(image_samples=0), "image_samples"),
    "image-samples-fraction": (scene(image_samples=2.5), "image_samples"),
    "image-samples-string": (scene(image_samples="many"), "image_samples: expected an integer"),
    "sampler-unknown": (scene(sampler={"type": "zsobol"}), "sampler.type"),
    "sampler-disagrees": (scene(image_samples=4, sampler={"type": "independent", "samples": 8}), "sampler.samples"),
    "sampler-unknown-key": (scene(sampler={"type": "independent", "seed": 3}), "sampler.seed: unknown key"),
    # Camera.
    "camera-resolution-zero": (scene(camera={"resolution": [0, 8]}), "camera.resolution[0]"),
    "camera-resolution-short": (scene(camera={"resolution": [8]}), "camera.resolution"),
    "camera-resolution-negative": (scene(camera={"resolution": [8, -8]}), "camera.resolution[1]"),
    "camera-vfov-zero": (scene(camera={"vfov": 0}), "camera.vfov"),
    "camera-vfov-huge": (scene(camera={"vfov": 270}), "camera.vfov"),
    "camera-fdist-negative": (scene(camera={"fdist": -1}), "camera.fdist"),
    "camera-aperture-negative": (scene(camera={"aperture": -0.1}), "camera.aperture"),
    "camera-lookat-degenerate": (scene(camera={"transform": {"from": [1, 1, 1], "at": [1, 1, 1]}}), "camera.transform"),
    "camera-up-parallel": (scene(camera={"transform": {"from": [0, 0, 5], "at": [0, 0, 0], "up": [0, 0, 1]}}), "camera.transform"),
    "camera-unknown-key": (scene(camera={"fov": 40}), "camera.fov: unknown key"),
    # Integrator.
    "integrator-unknown": (scene(integrator={"type": "photon_mapper"}), "integrator.type"),
    "integrator-missing-type": (scene(integrator={"max_bounces": 3}), 'integrator: missing required key "type"'),
    "integrator-bounces-negative": (scene(integrator={"type": "path_tracer_nee", "max_bounces": -2}), "integrator.max_bounces"),
    "integrator-bounces-both-spellings": (scene(integrator={"type": "path_tracer_nee", "max_bounces": 2, "max bounces": 2}), "integrator"),
    "integrator-power-zero": (scene(integrator={"type": "path_tracer_mis", "power": 0}), "integrator.power"),
    "integrator-unknown-key": (scene(integrator={"type": "path_tracer_mats", "rr": True}), "integrator.rr: unknown key"),
    # Background.
    "background-negative": (scene(background=[1, -1, 1]), "background"),
    "background-unknown-type": (scene(background={"type": "sky"}), "background.type"),
    "background-missing-image": (scene(background={"type": "image", "filename": "no-such-sky.exr"}), "background.filename"),
    "background-wrong-length": (scene(background=[1, 1]), "background"),
    # Surfaces.
    "surfaces-not-array": (scene(surfaces={"type": "sphere"}), "surfaces: expected an array"),
    "surface-unknown-type": (scene(surfaces=[surf(type="cube")]), "surfaces[0].type"),
    "surface-missing-material": (scene(surfaces=[{"type": "sphere"}]), 'surfaces[0]: missing required key "material"'),
    "surface-unknown-material-name": (scene(surfaces=[surf(material="gold")]), "surfaces[0].material"),
    "sphere-negative-radius": (scene(surfaces=[surf(radius=-1)]), "surfaces[0].radius"),
    "sphere-zero-radius": (scene(surfaces=[surf(radius=0)]), "surfaces[0].radius"),
    "sphere-huge-radius": (scene(surfaces=[surf(radius=1e39)]), "surfaces[0].radius"),
    "sphere-radius-string": (scene(surfaces=[surf(radius="1")]), "surfaces[0].radius: expected a number"),
    "sphere-nonuniform-scale": (scene(surfaces=[surf(transform={"scale": [1, 2, 1]})]), "surfaces[0].transform"),
    "quad-size-zero": (scene(surfaces=[{"type": "quad", "size": [1, 0], "material": LAMB}]), "surfaces[0].size[1]"),
    "quad-size-three": (scene(surfaces=[{"type": "quad", "size": [1, 2, 3], "material": LAMB}]), "surfaces[0].size"),
    "mesh-missing-file": (scene(surfaces=[{"type": "mesh", "filename": "no-such.obj", "material": LAMB}]), "surfaces[0].filename"),
    "mesh-broken-obj": (scene(surfaces=[{"type": "mesh", "filename": "broken.obj", "material": LAMB}]), "surfaces[0].filename"),
    "mesh-empty-obj": (scene(surfaces=[{"type": "mesh", "filename": "empty.obj", "material": LAMB}]), "surfaces[0].filename"),
    "mesh-overflow-vertex": (scene(surfaces=[{"type": "mesh", "filename": "overflow-vertex.obj", "material": LAMB}]), "surfaces[0].filename"),
    "mesh-nan-vertex": (scene(surfaces=[{"type": "mesh", "filename": "nan-vertex.obj", "material": LAMB}]), 'line 2: "nan" is not a finite number'),
    "mesh-unparsable-vertex": (scene(surfaces=[{"type": "mesh", "filename": "unparsable-vertex.obj", "material": LAMB}]), 'line 2: "abc" is not a finite number'),
    "mesh-short-vertex": (scene(surfaces=[{"type": "mesh", "filename": "short-vertex.obj", "material": LAMB}]), 'line 2: "v" with 2 numbers'),
    "mesh-normal-index-out-of-range": (scene(surfaces=[{"type": "mesh", "filename": "normal-index-out-of-range.obj", "material": LAMB}]), "normal index out of range"),
    "triangle-two-points": (scene(surfaces=[{"type": "triangle", "positions": [[0, 0, 0], [1, 0, 0]], "material": LAMB}]), "surfaces[0].positions"),
    "triangle-zero-normal": (scene(surfaces=[{"type": "triangle", "positions": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "normals": [[0, 0, 1], [0, 0, 0], [0, 0, 1]], "material": LAMB}]), "surfaces[0].normals[1]"),
    "group-without-children": (scene(surfaces=[{"type": "group"}]), 'surfaces[0]: missing required key "children"'),
    "group-bad-child": (scene(surfaces=[{"type": "group", "children": [surf(radius=-3)]}]), "surfaces[0].children[0].radius"),
    # Transforms.
    "transform-zero-scale": (scene(surfaces=[surf(transform={"scale": 0})]), "surfaces[0].transform.scale"),
    "transform-two-forms": (scene(surfaces=[surf(transform={"translate": [1, 0, 0], "scale": 2})]), "surfaces[0].transform"),
    "transform-matrix-short": (scene(surfaces=[surf(transform={"matrix": [1, 0, 0]})]), "surfaces[0].transform.matrix"),
    "transform-singular-matrix": (scene(surfaces=[{"type": "quad", "material": LAMB, "transform": {"matrix": [1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]}}]), "surfaces[0].transform"),
    "transform-axis-zero": (scene(surfaces=[surf(transform={"axis": [0, 0, 0], "angle": 30})]), "surfaces[0].transform.axis"),
    "transform-empty": (scene(surfaces=[surf(transform={})]), "surfaces[0].transform"),
    "transform-unknown-key": (scene(surfaces=[surf(transform={"rotate": 30})]), "surfaces[0].transform"),
    # Materials and textures.
    "material-unknown-type": (mat(type="velvet"), "surfaces[0].material.type"),
    "material-missing-name": (scene(materials=[{"type": "lambertian"}]), 'materials[0]: missing required key "name"'),
    "material-unknown-key": (mat(type="lambertian", albdo=0.5), "surfaces[0].material.albdo: unknown key"),
    "albedo-two-components": (mat(type="lambertian", albedo=[1, 2]), "surfaces[0].material.albedo"),
    "albedo-negative": (mat(type="lambertian", albedo=-0.5), "surfaces[0].material.albedo"),
    "albedo-string": (mat(type="lambertian", albedo="red"), "surfaces[0].material.albedo"),
    "emit-negative": (mat(type="diffuse light", emit=[-1, 1, 1]), "surfaces[0].material.emit"),
    "emit-overflow": (mat(type="diffuse light", emit=1e39), "surfaces[0].material.emit"),
    "texture-unknown-type": (mat(type="lambertian", albedo={"type": "wood"}), "surfaces[0].material.albedo.type"),
    "texture-missing-image": (mat(type="lambertian", albedo={"type": "image", "filename": "no-such.png"}), "surfaces[0].material.albedo.filename"),
    "texture-corrupt-image": (mat(type="lambertian", albedo={"type": "image", "filename": "corrupt.png"}), "surfaces[0].material.albedo.filename"),
    "checker-scale-zero": (mat(type="lambertian", albedo={"type": "checker", "scale": 0}), "surfaces[0].material.albedo.scale"),
    "marble-scale-overflow": (mat(type="lambertian", albedo={"type": "marble", "scale": 3e38}), "surfaces[0].material.albedo.scale"),
    "checker-transform-singular": (mat(type="lambertian", albedo={"type": "checker", "transform": {"scale": [1, 0, 1]}}), "surfaces[0].material.albedo.transform"),
    "marble-transform-unknown-key": (mat(type="lambertian", albedo={"type": "marble", "transform": {"rotate": 30}}), "surfaces[0].material.albedo.transform"),
    "dielectric-ior-zero": (mat(type="dielectric", ior=0), "surfaces[0].material.ior"),
    "dielectric-ior-negative": (mat(type="dielectric", ior=-1.5), "surfaces[0].material.ior"),
    "conductor-unknown-metal": (mat(type="ggx", conductor="gold"), 'surfaces[0].material.conductor: unknown conductor "gold"'),
    "conductor-ior-wrong-length": (mat(type="beckmann", ior=[0.2, 1.1]), "surfaces[0].material.ior"),
}


def main():
    OUT.mkdir(exist_ok=True)
    for old in OUT.glob("*.json"):
        old.unlink()
    (OUT / "broken.obj").write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n")
    (OUT / "empty.obj").write_text("# a mesh with no faces\nv 0 0 0\n")
    (OUT / "overflow-vertex.obj").write_text("v 0 0 0\nv 1e39 0 0\nv 0 1 0\nf 1 2 3\n")
    (OUT / "nan-vertex.obj").write_text("v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n")
    (OUT / "unparsable-vertex.obj").write_text("v 0 0 0\nv abc 0 0\nv 0 1 0\nf 1 2 3\n")
    (OUT / "short-vertex.obj").write_text("v 0 0 0\nv 1 2\nv 0 1 0\nf 1 2 3\n")
    (OUT / "normal-index-out-of-range.obj").write_text(
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//7\n")
    (OUT / "corrupt.png").write_bytes(b"\x89PNG\r\n\x1a\nnot really a png")
    lines = []
    for name, (content, expected) in sorted(CASES.items()):
        text = content if isinstance(content, str) else json.dumps(content, indent=2) + "\n"
        (OUT / f"{name}.json").write_text(text)
        lines.append(f"{name}.json\t{expected}")
    (OUT / "expected.tsv").write_text("\n".join(lines) + "\n")
    print(f"wrote {len(CASES)} malformed scenes to {OUT}")


if __name__ == "__main__":
    main()
