#!/usr/bin/env python3
"""Writes the stress scenes of scenes/stress/ (see scenes/stress/README.md).

Small (32x32, few samples): the stability suite renders each with every integrator.
Deterministic: re-running rewrites byte-identical files.
"""
import json
import os

OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "stress")

FLOOR = {"type": "quad", "size": 8, "transform": {"axis": [1, 0, 0], "angle": -90}}
DOWN = {"axis": [1, 0, 0], "angle": 90}  # a quad facing -y


def scene(camera_from, camera_at, materials, surfaces, background=0, spp=64, vfov=40):
    return {
        "camera": {"transform": {"from": camera_from, "at": camera_at, "up": [0, 1, 0]},
                   "vfov": vfov, "resolution": [32, 32]},
        "integrator": {"type": "path_tracer_mis", "max_bounces": 4},
        "sampler": {"type": "independent"},
        "image_samples": spp,
        "background": background,
        "materials": materials,
        "surfaces": surfaces,
    }


def light_in_glass():
    # The only emitter sits inside a smooth glass sphere: every light path leaves through a
    # delta interface (no connection can reach it, only material sampling and refraction).
    return scene([0, 1.5, 5], [0, 0.8, 0],
                 [{"name": "floor", "type": "lambertian", "albedo": 0.6},
                  {"name": "glass", "type": "dielectric", "ior": 1.5},
                  {"name": "light", "type": "diffuse light", "emit": 40}],
                 [dict(FLOOR, material="floor"),
                  {"type": "sphere", "radius": 1, "transform": {"translate": [0, 1, 0]},
                   "material": "glass"},
                  {"type": "sphere", "radius": 0.2, "transform": {"translate": [0, 1, 0]},
                   "material": "light"}])


def coincident_surfaces():
    # Two floors in the same plane, an emitter coincident with a diffuse quad, spheres that
    # cut the floor and each other, and a quad through a sphere's centre.
    return scene([0, 2, 5], [0, 0.5, 0],
                 [{"name": "white", "type": "lambertian", "albedo": 0.7},
                  {"name": "red", "type": "lambertian", "albedo": [0.8, 0.1, 0.1]},
                  {"name": "gold", "type": "ggx", "albedo": [1, 0.8, 0.4], "ab": 0.2},
                  {"name": "glass", "type": "rough_dielectric", "alpha": 0.1, "ior": 1.5},
                  {"name": "light", "type": "diffuse light", "emit": 10}],
                 [dict(FLOOR, material="white"),
                  dict(FLOOR, material="red"),
                  {"type": "sphere", "radius": 0.8, "transform": {"translate": [-0.6, 0.3, 0]},
                   "material": "gold"},
                  {"type": "sphere", "radius": 0.7, "transform": {"translate": [0.4, 0.5, 0.3]},
                   "material": "glass"},
                  {"type": "quad", "size": 1.5,
                   "transform": [{"axis": [0, 1, 0], "angle": 30}, {"translate": [0.4, 0.5, 0.3]}],
                   "material": "white"},
                  {"type": "quad", "size": 1.5, "transform": [DOWN, {"translate": [0, 3, 0]}],
                   "material": "light"},
                  {"type": "quad", "size": 1.5, "transform": [DOWN, {"translate": [0, 3, 0]}],
                   "material": "white"}])


def degenerate_triangles():
    # Zero-area triangles (a repeated vertex, collinear vertices, all three equal), needle
    # triangles 4 long and 1e-4 wide, an emitting needle and an emitting zero-area triangle,
    # lit by a quad light.
    def tri(p, material):
        return {"type": "triangle", "positions": p, "material": material}
    return scene([0, 1.5, 5], [0, 0.5, 0],
                 [{"name": "white", "type": "lambertian", "albedo": 0.7},
                  {"name": "rough", "type": "beckmann", "ab": 0.05},
                  {"name": "light", "type": "diffuse light", "emit": 10},
                  {"name": "needle light", "type": "diffuse light", "emit": 1000}],
                 [dict(FLOOR, material="white"),
                  tri([[-1, 0.5, 0], [1, 0.5, 0], [1, 0.5, 0]], "white"),
                  tri([[-1, 0.2, 0], [0, 0.6, 0], [1, 1.0, 0]], "rough"),
                  tri([[0.3, 0.3, 0.3], [0.3, 0.3, 0.3], [0.3, 0.3, 0.3]], "white"),
                  tri([[-2, 0.1, 0.5], [2, 0.1, 0.5], [2, 0.1001, 0.5]], "rough"),
                  tri([[-2, 1.5, -0.5], [2, 1.6, -0.5], [2, 1.6001, -0.5]], "white"),
                  tri([[0.5, 0.01, -2], [0.5, 0.0101, 2], [0.5001, 0.01, 2]], "white"),
                  tri([[-2, 2, 0], [2, 2, 0.0001], [2, 2, 0]], "needle light"),
                  tri([[-1, 2.5, 0], [0, 2.5, 0], [1, 2.5, 0]], "needle light"),
                  {"type": "quad", "size": 1.5, "transform": [DOWN, {"translate": [0, 3, 0]}],
                   "material": "light"}])


def tilted_normals():
    # Triangles whose vertex normals lean up to 89° away from the geometric normal, and past
    # it (below the surface), with diffuse, glossy and refractive materials.
    import math

    def lean(deg, az):
        t, p = math.radians(deg), math.radians(az)
        return [round(math.sin(t) * math.cos(p), 6), round(math.cos(t), 6),
                round(math.sin(t) * math.sin(p), 6)]
    surfaces = [dict(FLOOR, material="white"),
                {"type": "quad", "size": 1.5, "transform": [DOWN, {"translate": [0, 3, 0]}],
                 "material": "light"}]
    mats = ["white", "gold", "glass", "white"]
    leans = [(80, 0, 85, 120, 89, 240), (89, 90, 60, 180, 89.9, 0), (70, 45, 89, 200, 85, 300),
             (100, 0, 120, 120, 179, 240)]
    for i, (a, pa, b, pb, c, pc) in enumerate(leans):
        x = -1.5 + i
        surfaces.append({"type": "triangle",
                         "positions": [[x - 0.45, 0.2, 0.5], [x + 0.45, 0.2, 0.5],
                                       [x, 1.2, -0.3]],
                         "normals": [lean(a, pa), lean(b, pb), lean(c, pc)],
                         "material": mats[i]})
    return scene([0, 1.5, 5], [0, 0.6, 0],
                 [{"name": "white", "type": "lambertian", "albedo": 0.7},
                  {"name": "gold", "type": "ggx", "albedo": [1, 0.8, 0.4], "ab": 0.05},
                  {"name": "glass", "type": "dielectric", "ior": 1.5},
                  {"name": "light", "type": "diffuse light", "emit": 10}],
                 surfaces)


def camera_inside():
    # The camera sits inside a glass sphere, itself inside a closed diffuse sphere (a room)
    # with a small light.
    return scene([0, 0, 0], [0, -0.5, -2],
                 [{"name": "white", "type": "lambertian", "albedo": 0.7},
                  {"name": "glass", "type": "dielectric", "ior": 1.5},
                  {"name": "light", "type": "diffuse light", "emit": 30}],
                 [{"type": "sphere", "radius": 0.3, "material": "glass"},
                  {"type": "sphere", "radius": 4, "material": "white"},
                  {"type": "sphere", "radius": 0.3, "transform": {"translate": [1, -2, -2]},
                   "material": "white"},
                  {"type": "sphere", "radius": 0.4, "transform": {"translate": [-1, 2, -1]},
                   "material": "light"}])


def light_facing_away():
    # The only emitter faces up into an empty, black sky: no light reaches anything, so every
    # light-carrying integrator must return exactly black.
    up = {"axis": [1, 0, 0], "angle": -90}
    return scene([0, 2, 5], [0, 0.5, 0],
                 [{"name": "white", "type": "lambertian", "albedo": 0.7},
                  {"name": "light", "type": "diffuse light", "emit": 10}],
                 [dict(FLOOR, material="white"),
                  {"type": "sphere", "radius": 0.7, "transform": {"translate": [0, 0.7, 0]},
                   "material": "white"},
                  {"type": "quad", "size": 1.5, "transform": [up, {"translate": [0, 2.5, 0]}],
                   "material": "light"}])


def scaled(factor):
    # A lit scene whose geometry and camera are scaled by `factor`; radiance does not depend
    # on scale, so the image must equal the unscaled one in expectation. The sphere covers
    # every 16x16 tile, so no tile's test is a deterministic one decided by rounding.
    s = lambda v: [x * factor for x in v]
    return scene(s([0, 1, 4]), s([0, 0.7, 0]),
                 [{"name": "white", "type": "lambertian", "albedo": 0.7},
                  {"name": "gold", "type": "ggx", "albedo": [1, 0.8, 0.4], "ab": 0.1},
                  {"name": "light", "type": "diffuse light", "emit": 8}],
                 [{"type": "group", "transform": {"scale": factor}, "children": [
                     dict(FLOOR, material="white"),
                     {"type": "sphere", "radius": 1, "transform": {"translate": [0, 1, 0]},
                      "material": "gold"},
                     {"type": "sphere", "radius": 0.3,
                      "transform": {"translate": [1.2, 0.3, 0.8]}, "material": "white"},
                     {"type": "quad", "size": 1.5,
                      "transform": [DOWN, {"translate": [-0.8, 3, 1]}], "material": "light"}]}],
                 background=0.2, spp=256, vfov=60)


def object_on_floor(floor_size):
    # Small objects (unit spheres, a triangle, a light) on a floor `floor_size` wide, seen from
    # above so that the floor fills the view at any size. A floor two million units wide must
    # not change the image: ray offsets follow each point's own rounding error, not the
    # scene's extent. What the wider floor adds (light bounced back from far away) is far
    # below what the comparison can detect.
    return scene([0, 6, 4], [0, 0.5, 0],
                 [{"name": "white", "type": "lambertian", "albedo": 0.7},
                  {"name": "gold", "type": "ggx", "albedo": [1, 0.8, 0.4], "ab": 0.1},
                  {"name": "glass", "type": "dielectric", "ior": 1.5},
                  {"name": "light", "type": "diffuse light", "emit": 10}],
                 [dict(FLOOR, size=floor_size, material="white"),
                  {"type": "sphere", "radius": 1, "transform": {"translate": [0, 1, 0]},
                   "material": "gold"},
                  {"type": "sphere", "radius": 0.4, "transform": {"translate": [1.3, 0.4, 0.9]},
                   "material": "glass"},
                  {"type": "triangle", "positions": [[-2.2, 0, 0.8], [-1.2, 0, 1.2], [-1.6, 1.1, 0.2]],
                   "material": "white"},
                  {"type": "quad", "size": 1, "transform": [DOWN, {"translate": [0, 2.5, 0]}],
                   "material": "light"}],
                 spp=256)


def on_planes():
    # A corner of a room with its floor in y = 0 and its walls in x = 0 (two triangles) and
    # z = 0 (a quad), all facing into the corner: a surface whose points have a coordinate exactly 0 has no rounding error
    # in it, and a ray leaving it one denormal off the plane found the plane again at t = 0
    # (next-event estimation 21% dark). The light hangs inside the corner.
    wall_x = [[0, 0, 0], [0, 0, 4], [0, 4, 4], [0, 4, 0]]
    return scene([5, 3.2, 5.5], [1.2, 1, 1.2],
                 [{"name": "white", "type": "lambertian", "albedo": 0.7},
                  {"name": "red", "type": "lambertian", "albedo": [0.7, 0.1, 0.1]},
                  {"name": "light", "type": "diffuse light", "emit": 20}],
                 [{"type": "quad", "size": 4, "material": "white",
                   "transform": [{"axis": [1, 0, 0], "angle": -90}, {"translate": [2, 0, 2]}]},
                  {"type": "quad", "size": 4, "material": "white",
                   "transform": {"translate": [2, 2, 0]}},
                  {"type": "triangle", "positions": [wall_x[0], wall_x[2], wall_x[1]],
                   "material": "red"},
                  {"type": "triangle", "positions": [wall_x[0], wall_x[3], wall_x[2]],
                   "material": "red"},
                  {"type": "sphere", "radius": 0.5, "transform": {"translate": [1.5, 0.5, 1.2]},
                   "material": "white"},
                  {"type": "quad", "size": 0.8, "transform": [DOWN, {"translate": [1.4, 2.6, 1.4]}],
                   "material": "light"}])


SCENES = {
    "light-in-glass": light_in_glass(),
    "coincident-surfaces": coincident_surfaces(),
    "degenerate-triangles": degenerate_triangles(),
    "tilted-normals": tilted_normals(),
    "camera-inside": camera_inside(),
    "light-facing-away": light_facing_away(),
    "scaled-1": scaled(1),
    "scaled-1e-4": scaled(1e-4),
    "scaled-1e5": scaled(1e5),
    "floor-40": object_on_floor(40),
    "floor-2e6": object_on_floor(2e6),
    "on-planes": on_planes(),
}

if __name__ == "__main__":
    os.makedirs(OUT, exist_ok=True)
    for name, s in SCENES.items():
        with open(os.path.join(OUT, name + ".json"), "w") as f:
            json.dump(s, f, indent=1)
            f.write("\n")
