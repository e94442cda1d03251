#!/usr/bin/env python3
"""Generate the Utah teapot as a Wavefront OBJ with vertex normals and UVs.

Geometry: Newell 1975, the Utah teapot -- Martin Newell's 32 bicubic Bezier
patches over 306 control points (the public "teaset" data: rim, body, lid,
knob, handle, spout and bottom). The data is z-up, in its original units: the
teapot stands on z = 0, is about 6.43 units long in x (handle at -x, spout
at +x), 4 units deep in y and 3.15 units tall in z.

Each patch is tessellated on an N x N grid of its parameters (default 12).
Positions shared by neighbouring patches are welded; triangles that collapse
at the poles of the knob and the bottom are dropped. Normals are computed
analytically as dS/du x dS/dv; where one derivative vanishes (the degenerate
pole rows at the lid top and the bottom), the limit direction dS/du x d2S/dudv
is used instead. Every patch is oriented so that its normals point outward.
UVs are the patch parameters (u, v) in [0,1]^2.

Pure Python 3 (no numpy), deterministic: re-running it rewrites the same file.

  python3 scenes/tools/make_teapot.py                      # -> scenes/meshes/teapot.obj
  python3 scenes/tools/make_teapot.py --res 8 -o /tmp/t.obj
  python3 scenes/tools/make_teapot.py --check              # print sanity checks only
"""

import argparse
import math
import os
import sys

# --- Newell 1975, the Utah teapot: 32 patches, 16 control point indices each
# (zero-based, row-major: 4 rows along u, 4 columns along v). -----------------
PATCHES = [
    # rim (0-3)
    [0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15],
    [3, 16, 17, 18, 7, 19, 20, 21, 11, 22, 23, 24, 15, 25, 26, 27],
    [18, 28, 29, 30, 21, 31, 32, 33, 24, 34, 35, 36, 27, 37, 38, 39],
    [30, 40, 41, 0, 33, 42, 43, 4, 36, 44, 45, 8, 39, 46, 47, 12],
    # upper body (4-7)
    [12, 13, 14, 15, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59],
    [15, 25, 26, 27, 51, 60, 61, 62, 55, 63, 64, 65, 59, 66, 67, 68],
    [27, 37, 38, 39, 62, 69, 70, 71, 65, 72, 73, 74, 68, 75, 76, 77],
    [39, 46, 47, 12, 71, 78, 79, 48, 74, 80, 81, 52, 77, 82, 83, 56],
    # lower body (8-11)
    [56, 57, 58, 59, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95],
    [59, 66, 67, 68, 87, 96, 97, 98, 91, 99, 100, 101, 95, 102, 103, 104],
    [68, 75, 76, 77, 98, 105, 106, 107, 101, 108, 109, 110, 104, 111, 112, 113],
    [77, 82, 83, 56, 107, 114, 115, 84, 110, 116, 117, 88, 113, 118, 119, 92],
    # handle (12-15)
    [120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135],
    [123, 136, 137, 120, 127, 138, 139, 124, 131, 140, 141, 128, 135, 142, 143, 132],
    [132, 133, 134, 135, 144, 145, 146, 147, 148, 149, 150, 151, 68, 152, 153, 154],
    [135, 142, 143, 132, 147, 155, 156, 144, 151, 157, 158, 148, 154, 159, 160, 68],
    # spout (16-19)
    [161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176],
    [164, 177, 178, 161, 168, 179, 180, 165, 172, 181, 182, 169, 176, 183, 184, 173],
    [173, 174, 175, 176, 185, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196],
    [176, 183, 184, 173, 188, 197, 198, 185, 192, 199, 200, 189, 196, 201, 202, 193],
    # lid knob (20-23): row 0 collapses to the pole at the top of the knob
    [203, 203, 203, 203, 206, 207, 208, 209, 210, 210, 210, 210, 211, 212, 213, 214],
    [203, 203, 203, 203, 209, 216, 217, 218, 210, 210, 210, 210, 214, 219, 220, 221],
    [203, 203, 203, 203, 218, 223, 224, 225, 210, 210, 210, 210, 221, 226, 227, 228],
    [203, 203, 203, 203, 225, 229, 230, 206, 210, 210, 210, 210, 228, 231, 232, 211],
    # lid (24-27)
    [211, 212, 213, 214, 233, 234, 235, 236, 237, 238, 239, 240, 241, 242, 243, 244],
    [214, 219, 220, 221, 236, 245, 246, 247, 240, 248, 249, 250, 244, 251, 252, 253],
    [221, 226, 227, 228, 247, 254, 255, 256, 250, 257, 258, 259, 253, 260, 261, 262],
    [228, 231, 232, 211, 256, 263, 264, 233, 259, 265, 266, 237, 262, 267, 268, 241],
    # bottom (28-31): row 0 collapses to the pole at the centre of the base
    [269, 269, 269, 269, 278, 279, 280, 281, 274, 275, 276, 277, 270, 271, 272, 273],
    [269, 269, 269, 269, 281, 288, 289, 290, 277, 285, 286, 287, 273, 282, 283, 284],
    [269, 269, 269, 269, 290, 297, 298, 299, 287, 294, 295, 296, 284, 291, 292, 293],
    [269, 269, 269, 269, 299, 304, 305, 278, 296, 302, 303, 274, 293, 300, 301, 270],
]

# --- Newell 1975, the Utah teapot: the 306 control points (x, y, z), z up. ----
VERTICES = [
    # 0-47: rim
    (1.4, 0.0, 2.4), (1.4, -0.784, 2.4), (0.784, -1.4, 2.4), (0.0, -1.4, 2.4),
    (1.3375, 0.0, 2.53125), (1.3375, -0.749, 2.53125), (0.749, -1.3375, 2.53125), (0.0, -1.3375, 2.53125),
    (1.4375, 0.0, 2.53125), (1.4375, -0.805, 2.53125), (0.805, -1.4375, 2.53125), (0.0, -1.4375, 2.53125),
    (1.5, 0.0, 2.4), (1.5, -0.84, 2.4), (0.84, -1.5, 2.4), (0.0, -1.5, 2.4),
    (-0.784, -1.4, 2.4), (-1.4, -0.784, 2.4), (-1.4, 0.0, 2.4),
    (-0.749, -1.3375, 2.53125), (-1.3375, -0.749, 2.53125), (-1.3375, 0.0, 2.53125),
    (-0.805, -1.4375, 2.53125), (-1.4375, -0.805, 2.53125), (-1.4375, 0.0, 2.53125),
    (-0.84, -1.5, 2.4), (-1.5, -0.84, 2.4), (-1.5, 0.0, 2.4),
    (-1.4, 0.784, 2.4), (-0.784, 1.4, 2.4), (0.0, 1.4, 2.4),
    (-1.3375, 0.749, 2.53125), (-0.749, 1.3375, 2.53125), (0.0, 1.3375, 2.53125),
    (-1.4375, 0.805, 2.53125), (-0.805, 1.4375, 2.53125), (0.0, 1.4375, 2.53125),
    (-1.5, 0.84, 2.4), (-0.84, 1.5, 2.4), (0.0, 1.5, 2.4),
    (0.784, 1.4, 2.4), (1.4, 0.784, 2.4),
    (0.749, 1.3375, 2.53125), (1.3375, 0.749, 2.53125),
    (0.805, 1.4375, 2.53125), (1.4375, 0.805, 2.53125),
    (0.84, 1.5, 2.4), (1.5, 0.84, 2.4),
    # 48-83: upper body
    (1.75, 0.0, 1.875), (1.75, -0.98, 1.875), (0.98, -1.75, 1.875), (0.0, -1.75, 1.875),
    (2.0, 0.0, 1.35), (2.0, -1.12, 1.35), (1.12, -2.0, 1.35), (0.0, -2.0, 1.35),
    (2.0, 0.0, 0.9), (2.0, -1.12, 0.9), (1.12, -2.0, 0.9), (0.0, -2.0, 0.9),
    (-0.98, -1.75, 1.875), (-1.75, -0.98, 1.875), (-1.75, 0.0, 1.875),
    (-1.12, -2.0, 1.35), (-2.0, -1.12, 1.35), (-2.0, 0.0, 1.35),
    (-1.12, -2.0, 0.9), (-2.0, -1.12, 0.9), (-2.0, 0.0, 0.9),
    (-1.75, 0.98, 1.875), (-0.98, 1.75, 1.875), (0.0, 1.75, 1.875),
    (-2.0, 1.12, 1.35), (-1.12, 2.0, 1.35), (0.0, 2.0, 1.35),
    (-2.0, 1.12, 0.9), (-1.12, 2.0, 0.9), (0.0, 2.0, 0.9),
    (0.98, 1.75, 1.875), (1.75, 0.98, 1.875),
    (1.12, 2.0, 1.35), (2.0, 1.12, 1.35),
    (1.12, 2.0, 0.9), (2.0, 1.12, 0.9),
    # 84-119: lower body
    (2.0, 0.0, 0.45), (2.0, -1.12, 0.45), (1.12, -2.0, 0.45), (0.0, -2.0, 0.45),
    (1.5, 0.0, 0.225), (1.5, -0.84, 0.225), (0.84, -1.5, 0.225), (0.0, -1.5, 0.225),
    (1.5, 0.0, 0.15), (1.5, -0.84, 0.15), (0.84, -1.5, 0.15), (0.0, -1.5, 0.15),
    (-1.12, -2.0, 0.45), (-2.0, -1.12, 0.45), (-2.0, 0.0, 0.45),
    (-0.84, -1.5, 0.225), (-1.5, -0.84, 0.225), (-1.5, 0.0, 0.225),
    (-0.84, -1.5, 0.15), (-1.5, -0.84, 0.15), (-1.5, 0.0, 0.15),
    (-2.0, 1.12, 0.45), (-1.12, 2.0, 0.45), (0.0, 2.0, 0.45),
    (-1.5, 0.84, 0.225), (-0.84, 1.5, 0.225), (0.0, 1.5, 0.225),
    (-1.5, 0.84, 0.15), (-0.84, 1.5, 0.15), (0.0, 1.5, 0.15),
    (1.12, 2.0, 0.45), (2.0, 1.12, 0.45),
    (0.84, 1.5, 0.225), (1.5, 0.84, 0.225),
    (0.84, 1.5, 0.15), (1.5, 0.84, 0.15),
    # 120-160: handle
    (-1.6, 0.0, 2.025), (-1.6, -0.3, 2.025), (-1.5, -0.3, 2.25), (-1.5, 0.0, 2.25),
    (-2.3, 0.0, 2.025), (-2.3, -0.3, 2.025), (-2.5, -0.3, 2.25), (-2.5, 0.0, 2.25),
    (-2.7, 0.0, 2.025), (-2.7, -0.3, 2.025), (-3.0, -0.3, 2.25), (-3.0, 0.0, 2.25),
    (-2.7, 0.0, 1.8), (-2.7, -0.3, 1.8), (-3.0, -0.3, 1.8), (-3.0, 0.0, 1.8),
    (-1.5, 0.3, 2.25), (-1.6, 0.3, 2.025),
    (-2.5, 0.3, 2.25), (-2.3, 0.3, 2.025),
    (-3.0, 0.3, 2.25), (-2.7, 0.3, 2.025),
    (-3.0, 0.3, 1.8), (-2.7, 0.3, 1.8),
    (-2.7, 0.0, 1.575), (-2.7, -0.3, 1.575), (-3.0, -0.3, 1.35), (-3.0, 0.0, 1.35),
    (-2.5, 0.0, 1.125), (-2.5, -0.3, 1.125), (-2.65, -0.3, 0.9375), (-2.65, 0.0, 0.9375),
    (-2.0, -0.3, 0.9), (-1.9, -0.3, 0.6), (-1.9, 0.0, 0.6),
    (-3.0, 0.3, 1.35), (-2.7, 0.3, 1.575),
    (-2.65, 0.3, 0.9375), (-2.5, 0.3, 1.125),
    (-1.9, 0.3, 0.6), (-2.0, 0.3, 0.9),
    # 161-202: spout
    (1.7, 0.0, 1.425), (1.7, -0.66, 1.425), (1.7, -0.66, 0.6), (1.7, 0.0, 0.6),
    (2.6, 0.0, 1.425), (2.6, -0.66, 1.425), (3.1, -0.66, 0.825), (3.1, 0.0, 0.825),
    (2.3, 0.0, 2.1), (2.3, -0.25, 2.1), (2.4, -0.25, 2.025), (2.4, 0.0, 2.025),
    (2.7, 0.0, 2.4), (2.7, -0.25, 2.4), (3.3, -0.25, 2.4), (3.3, 0.0, 2.4),
    (1.7, 0.66, 0.6), (1.7, 0.66, 1.425),
    (3.1, 0.66, 0.825), (2.6, 0.66, 1.425),
    (2.4, 0.25, 2.025), (2.3, 0.25, 2.1),
    (3.3, 0.25, 2.4), (2.7, 0.25, 2.4),
    (2.8, 0.0, 2.475), (2.8, -0.25, 2.475), (3.525, -0.25, 2.49375), (3.525, 0.0, 2.49375),
    (2.9, 0.0, 2.475), (2.9, -0.15, 2.475), (3.45, -0.15, 2.5125), (3.45, 0.0, 2.5125),
    (2.8, 0.0, 2.4), (2.8, -0.15, 2.4), (3.2, -0.15, 2.4), (3.2, 0.0, 2.4),
    (3.525, 0.25, 2.49375), (2.8, 0.25, 2.475),
    (3.45, 0.15, 2.5125), (2.9, 0.15, 2.475),
    (3.2, 0.15, 2.4), (2.8, 0.15, 2.4),
    # 203-232: lid knob
    (0.0, 0.0, 3.15), (0.0, -0.002, 3.15), (0.002, 0.0, 3.15),
    (0.8, 0.0, 3.15), (0.8, -0.45, 3.15), (0.45, -0.8, 3.15), (0.0, -0.8, 3.15),
    (0.0, 0.0, 2.85),
    (0.2, 0.0, 2.7), (0.2, -0.112, 2.7), (0.112, -0.2, 2.7), (0.0, -0.2, 2.7),
    (-0.002, 0.0, 3.15),
    (-0.45, -0.8, 3.15), (-0.8, -0.45, 3.15), (-0.8, 0.0, 3.15),
    (-0.112, -0.2, 2.7), (-0.2, -0.112, 2.7), (-0.2, 0.0, 2.7),
    (0.0, 0.002, 3.15),
    (-0.8, 0.45, 3.15), (-0.45, 0.8, 3.15), (0.0, 0.8, 3.15),
    (-0.2, 0.112, 2.7), (-0.112, 0.2, 2.7), (0.0, 0.2, 2.7),
    (0.45, 0.8, 3.15), (0.8, 0.45, 3.15),
    (0.112, 0.2, 2.7), (0.2, 0.112, 2.7),
    # 233-268: lid
    (0.4, 0.0, 2.55), (0.4, -0.224, 2.55), (0.224, -0.4, 2.55), (0.0, -0.4, 2.55),
    (1.3, 0.0, 2.55), (1.3, -0.728, 2.55), (0.728, -1.3, 2.55), (0.0, -1.3, 2.55),
    (1.3, 0.0, 2.4), (1.3, -0.728, 2.4), (0.728, -1.3, 2.4), (0.0, -1.3, 2.4),
    (-0.224, -0.4, 2.55), (-0.4, -0.224, 2.55), (-0.4, 0.0, 2.55),
    (-0.728, -1.3, 2.55), (-1.3, -0.728, 2.55), (-1.3, 0.0, 2.55),
    (-0.728, -1.3, 2.4), (-1.3, -0.728, 2.4), (-1.3, 0.0, 2.4),
    (-0.4, 0.224, 2.55), (-0.224, 0.4, 2.55), (0.0, 0.4, 2.55),
    (-1.3, 0.728, 2.55), (-0.728, 1.3, 2.55), (0.0, 1.3, 2.55),
    (-1.3, 0.728, 2.4), (-0.728, 1.3, 2.4), (0.0, 1.3, 2.4),
    (0.224, 0.4, 2.55), (0.4, 0.224, 2.55),
    (0.728, 1.3, 2.55), (1.3, 0.728, 2.55),
    (0.728, 1.3, 2.4), (1.3, 0.728, 2.4),
    # 269-305: bottom
    (0.0, 0.0, 0.0),
    (1.5, 0.0, 0.15), (1.5, 0.84, 0.15), (0.84, 1.5, 0.15), (0.0, 1.5, 0.15),
    (1.5, 0.0, 0.075), (1.5, 0.84, 0.075), (0.84, 1.5, 0.075), (0.0, 1.5, 0.075),
    (1.425, 0.0, 0.0), (1.425, 0.798, 0.0), (0.798, 1.425, 0.0), (0.0, 1.425, 0.0),
    (-0.84, 1.5, 0.15), (-1.5, 0.84, 0.15), (-1.5, 0.0, 0.15),
    (-0.84, 1.5, 0.075), (-1.5, 0.84, 0.075), (-1.5, 0.0, 0.075),
    (-0.798, 1.425, 0.0), (-1.425, 0.798, 0.0), (-1.425, 0.0, 0.0),
    (-1.5, -0.84, 0.15), (-0.84, -1.5, 0.15), (0.0, -1.5, 0.15),
    (-1.5, -0.84, 0.075), (-0.84, -1.5, 0.075), (0.0, -1.5, 0.075),
    (-1.425, -0.798, 0.0), (-0.798, -1.425, 0.0), (0.0, -1.425, 0.0),
    (0.84, -1.5, 0.15), (1.5, -0.84, 0.15),
    (0.84, -1.5, 0.075), (1.5, -0.84, 0.075),
    (0.798, -1.425, 0.0), (1.425, -0.798, 0.0),
]

assert len(PATCHES) == 32 and all(len(p) == 16 for p in PATCHES)
assert len(VERTICES) == 306


# --- small vector helpers ------------------------------------------------------
def add(a, b): return (a[0] + b[0], a[1] + b[1], a[2] + b[2])
def sub(a, b): return (a[0] - b[0], a[1] - b[1], a[2] - b[2])
def mul(a, s): return (a[0] * s, a[1] * s, a[2] * s)
def dot(a, b): return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])
def norm(a): return math.sqrt(dot(a, a))
def normalize(a):
    n = norm(a)
    return mul(a, 1.0 / n) if n > 0 else a


def bernstein(t):
    s = 1.0 - t
    return (s * s * s, 3 * t * s * s, 3 * t * t * s, t * t * t)


def bernstein_d(t):
    s = 1.0 - t
    return (-3 * s * s, 3 * s * s - 6 * t * s, 6 * t * s - 3 * t * t, 3 * t * t)


def eval_patch(cp, u, v):
    """Position, dS/du, dS/dv and d2S/dudv of a bicubic patch (cp: 4x4 rows along u)."""
    bu, bv = bernstein(u), bernstein(v)
    du, dv = bernstein_d(u), bernstein_d(v)
    p = su = sv = suv = (0.0, 0.0, 0.0)
    for i in range(4):
        for j in range(4):
            c = cp[i][j]
            p = add(p, mul(c, bu[i] * bv[j]))
            su = add(su, mul(c, du[i] * bv[j]))
            sv = add(sv, mul(c, bu[i] * dv[j]))
            suv = add(suv, mul(c, du[i] * dv[j]))
    return p, su, sv, suv


def patch_normal(cp, u, v):
    """Unnormalised-orientation analytic normal Su x Sv, with the pole limits."""
    p, su, sv, suv = eval_patch(cp, u, v)
    scale = max(norm(su), norm(sv), 1e-30)
    n = cross(su, sv)
    if norm(n) > 1e-9 * scale * scale:
        return p, normalize(n)
    # Degenerate: a whole boundary row of control points collapsed to a pole, so
    # one partial derivative vanishes there. Near the row u = u0, Sv ~ (u - u0) Suv,
    # so Su x Sv / |..| tends to sign(u - u0) * Su x Suv (and likewise in v).
    if norm(sv) < norm(su):
        sign = 1.0 if u < 0.5 else -1.0
        n = mul(cross(su, suv), sign)
    else:
        sign = 1.0 if v < 0.5 else -1.0
        n = mul(cross(suv, sv), sign)
    if norm(n) < 1e-12:  # should not happen for this data; fall back to a tiny step
        eps = 1e-4
        uu = u + eps if u < 0.5 else u - eps
        vv = v + eps if v < 0.5 else v - eps
        _, su2, sv2, _ = eval_patch(cp, uu, vv)
        n = cross(su2, sv2)
    return p, normalize(n)


def patch_outward_score(cp):
    """Positive when Su x Sv tends to point outward on this patch.

    Outward is judged against a local centre: the midpoint of the patch's two
    v-boundary curves at the same u (the axis for the body and lid, the centre
    line of the tube for the handle and spout). The score is only a vote: a
    thin lip such as the rim can fool it, so tessellate() sums the votes over
    each set of patches that share edges and orients that set consistently.
    """
    total = 0.0
    m = 8
    for a in range(m + 1):
        u = (a + 0.5) / (m + 1)
        p0 = eval_patch(cp, u, 0.0)[0]
        p1 = eval_patch(cp, u, 1.0)[0]
        mid = mul(add(p0, p1), 0.5)
        for b in range(m + 1):
            v = (b + 0.5) / (m + 1)
            p, n = patch_normal(cp, u, v)
            total += dot(n, sub(p, mid))
    return total


def tessellate(res):
    """Returns positions, normals, uvs (lists) and faces [(p,t,n) x3] (0-based)."""
    positions, pos_index = [], {}
    normals, nrm_index = [], {}
    uvs, uv_index = [], {}
    faces = []

    def key(v, q):
        return tuple(round(c * q) for c in v)

    def get(table, index, value, q):
        k = key(value, q)
        i = index.get(k)
        if i is None:
            i = len(table)
            index[k] = i
            table.append(value)
        return i

    # Pass 1: sample every patch with its own Su x Sv orientation.
    grids, scores = [], []
    for patch in PATCHES:
        cp = [[VERTICES[patch[4 * i + j]] for j in range(4)] for i in range(4)]
        scores.append(patch_outward_score(cp))
        grid = []
        for a in range(res + 1):
            u = a / res
            row = []
            for b in range(res + 1):
                v = b / res
                p, n = patch_normal(cp, u, v)
                row.append((get(positions, pos_index, p, 1e6), (u, v), n))
            grid.append(row)
        grids.append(grid)

    # Pass 2: orient patches consistently across their shared (welded) edges:
    # a neighbour that runs a shared edge in the same direction is flipped
    # relative to this patch. Then orient each connected set by its vote.
    def boundary_edges(grid):
        out = []
        for a in range(res):
            for b in range(res):
                c00, c10 = grid[a][b][0], grid[a + 1][b][0]
                c11, c01 = grid[a + 1][b + 1][0], grid[a][b + 1][0]
                for t in ((c00, c10, c11), (c00, c11, c01)):
                    if len(set(t)) == 3:  # skip triangles collapsed at a pole
                        out.extend((t[k], t[(k + 1) % 3]) for k in range(3))
        return out
    directed = {}
    for pi, grid in enumerate(grids):
        for e in boundary_edges(grid):
            directed.setdefault(e, set()).add(pi)
    rel = [None] * len(PATCHES)
    sign = [1.0] * len(PATCHES)
    for start in range(len(PATCHES)):
        if rel[start] is not None:
            continue
        rel[start] = 1.0
        comp, stack = [start], [start]
        while stack:
            pi = stack.pop()
            for (a, b) in boundary_edges(grids[pi]):
                for qi in directed.get((a, b), ()):   # same direction: flipped
                    if qi != pi and rel[qi] is None:
                        rel[qi] = -rel[pi]; comp.append(qi); stack.append(qi)
                for qi in directed.get((b, a), ()):   # opposite: same orientation
                    if qi != pi and rel[qi] is None:
                        rel[qi] = rel[pi]; comp.append(qi); stack.append(qi)
        vote = sum(rel[pi] * scores[pi] for pi in comp)
        for pi in comp:
            sign[pi] = rel[pi] * (1.0 if vote >= 0 else -1.0)

    for pi, grid in enumerate(grids):
        s = sign[pi]
        cells = [[(ip, get(uvs, uv_index, uv, 1e9), get(normals, nrm_index, mul(n, s), 1e6))
                  for (ip, uv, n) in row] for row in grid]
        for a in range(res):
            for b in range(res):
                c00, c10 = cells[a][b], cells[a + 1][b]
                c11, c01 = cells[a + 1][b + 1], cells[a][b + 1]
                # (00,10,11) winds as Su x Sv; reverse when the patch is flipped.
                for t in ((c00, c10, c11), (c00, c11, c01)):
                    if s < 0:
                        t = (t[0], t[2], t[1])
                    if len({t[0][0], t[1][0], t[2][0]}) < 3:
                        continue  # collapsed at a pole
                    faces.append(t)
    tessellate.signs = sign
    return positions, normals, uvs, faces


def check(positions, normals, faces, out=sys.stdout):
    """Print sanity checks; returns True when they pass."""
    lo = [min(p[k] for p in positions) for k in range(3)]
    hi = [max(p[k] for p in positions) for k in range(3)]
    ext = [hi[k] - lo[k] for k in range(3)]
    print("vertices %d, normals %d, triangles %d" % (len(positions), len(normals), len(faces)), file=out)
    print("bbox min (%.4f %.4f %.4f) max (%.4f %.4f %.4f) size %.4f x %.4f x %.4f"
          % tuple(lo + hi + ext), file=out)

    # edge manifoldness
    edges = {}
    for f in faces:
        for k in range(3):
            a, b = f[k][0], f[(k + 1) % 3][0]
            e = (min(a, b), max(a, b))
            edges[e] = edges.get(e, 0) + 1
    hist = {}
    for c in edges.values():
        hist[c] = hist.get(c, 0) + 1
    print("edge use histogram (uses: edges) %s" % dict(sorted(hist.items())), file=out)
    seen, bad = set(), 0
    for f in faces:
        for k in range(3):
            e = (f[k][0], f[(k + 1) % 3][0])
            if e in seen:
                bad += 1
            seen.add(e)
    print("edges run twice in the same direction (inconsistent winding): %d" % bad, file=out)

    # normals vs winding and vs the direction from the centroid
    area_total = 0.0
    c = [0.0, 0.0, 0.0]
    for f in faces:
        p0, p1, p2 = (positions[x[0]] for x in f)
        ar = 0.5 * norm(cross(sub(p1, p0), sub(p2, p0)))
        area_total += ar
        for k in range(3):
            c[k] += ar * (p0[k] + p1[k] + p2[k]) / 3.0
    c = tuple(x / area_total for x in c)
    agree_winding = 0
    outward_area = 0.0
    for f in faces:
        p0, p1, p2 = (positions[x[0]] for x in f)
        g = cross(sub(p1, p0), sub(p2, p0))
        ar = 0.5 * norm(g)
        ns = normalize(add(add(normals[f[0][2]], normals[f[1][2]]), normals[f[2][2]]))
        if dot(g, ns) > 0:
            agree_winding += 1
        centre = mul(add(add(p0, p1), p2), 1.0 / 3.0)
        if dot(ns, sub(centre, c)) > 0:
            outward_area += ar
    frac_wind = agree_winding / len(faces)
    frac_out = outward_area / area_total
    print("surface area %.4f, centroid (%.4f %.4f %.4f)" % ((area_total,) + c), file=out)
    print("shading normal agrees with winding: %.2f%% of triangles" % (100 * frac_wind), file=out)
    print("normal points away from the centroid: %.2f%% of the area" % (100 * frac_out), file=out)
    # The bounding box is only close to the true 6.43 x 4 x 3.15 on a fine enough grid.
    bbox_ok = (abs(ext[0] - 6.43) < 0.1 and abs(ext[1] - 4.0) < 0.05 and abs(ext[2] - 3.15) < 0.01)
    ok = ((bbox_ok or len(faces) < 32 * 2 * 6 * 6)
          and bad == 0 and frac_wind > 0.999 and frac_out > 0.85)
    print("checks %s" % ("passed" if ok else "FAILED"), file=out)
    return ok


def write_obj(path, res, positions, normals, uvs, faces):
    lines = ["# Utah teapot (Newell 1975, the Utah teapot): 32 bicubic Bezier patches,",
             "# tessellated %dx%d per patch by scenes/tools/make_teapot.py." % (res, res),
             "# z-up, original units: stands on z=0, spout +x, handle -x.",
             "# uv = patch parameters; normals analytic from the patch derivatives.",
             "o teapot"]
    for p in positions:
        lines.append("v %.6f %.6f %.6f" % tuple(0.0 if abs(x) < 5e-7 else x for x in p))
    for t in uvs:
        lines.append("vt %.6f %.6f" % t)
    for n in normals:
        lines.append("vn %.6f %.6f %.6f" % tuple(0.0 if abs(x) < 5e-7 else x for x in n))
    for f in faces:
        lines.append("f " + " ".join("%d/%d/%d" % (x[0] + 1, x[1] + 1, x[2] + 1) for x in f))
    data = "\n".join(lines) + "\n"
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    with open(path, "w", newline="\n") as fh:
        fh.write(data)
    return len(data)


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    default_out = os.path.normpath(os.path.join(here, "..", "meshes", "teapot.obj"))
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--res", type=int, default=12, help="grid cells per patch side (default 12)")
    ap.add_argument("-o", "--output", default=default_out, help="output OBJ (default scenes/meshes/teapot.obj)")
    ap.add_argument("--check", action="store_true", help="only print the sanity checks")
    args = ap.parse_args()
    if args.res < 1:
        ap.error("--res must be >= 1")
    positions, normals, uvs, faces = tessellate(args.res)
    ok = check(positions, normals, faces)
    if not args.check:
        size = write_obj(args.output, args.res, positions, normals, uvs, faces)
        print("wrote %s (%d bytes)" % (args.output, size))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
