#!/usr/bin/env python3
"""Procedural textures for Verity's scenes, written as 8-bit sRGB PNGs.

  scenes/textures/earth.png  1024x512 lat-long planet: oceans, continents from
                             fractal noise on the sphere (no seam at the date
                             line, no pinching at the poles), deserts,
                             mountains, snow and polar ice caps.
  scenes/textures/wood.png   512x512 wooden planks (rings + grain), for the
                             textured box.
  scenes/textures/tiles.png  512x512 glazed tiles with grout.

Needs numpy (Debian's /usr/bin/python3 has it). PNGs are written by hand
with zlib, so the output is byte-for-byte deterministic (fixed seeds, no
timestamps or library metadata):

  /usr/bin/python3 scenes/tools/make_textures.py            # all textures
  /usr/bin/python3 scenes/tools/make_textures.py earth      # only some
"""

import os
import struct
import sys
import zlib

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
OUT_DIR = os.path.normpath(os.path.join(HERE, "..", "textures"))


# --- PNG output ---------------------------------------------------------------
def write_png(path, rgb):
    """rgb: HxWx3 uint8 array (already sRGB-encoded)."""
    rgb = np.ascontiguousarray(rgb, dtype=np.uint8)
    h, w, _ = rgb.shape
    raw = b"".join(b"\x00" + rgb[y].tobytes() for y in range(h))  # filter 0 per row

    def chunk(tag, data):
        c = struct.pack(">I", len(data)) + tag + data
        return c + struct.pack(">I", zlib.crc32(tag + data) & 0xFFFFFFFF)

    png = b"\x89PNG\r\n\x1a\n"
    png += chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
    png += chunk(b"sRGB", b"\x00")  # perceptual rendering intent: the data is sRGB
    png += chunk(b"IDAT", zlib.compress(raw, 9))
    png += chunk(b"IEND", b"")
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "wb") as f:
        f.write(png)
    print("wrote %s (%dx%d, %d bytes)" % (path, w, h, len(png)))


def linear_to_srgb8(c):
    """Exact sRGB curve, as the renderer's output uses; input linear in [0,1]."""
    c = np.clip(c, 0.0, 1.0)
    s = np.where(c <= 0.0031308, 12.92 * c, 1.055 * np.power(c, 1 / 2.4) - 0.055)
    return np.clip(np.round(s * 255.0), 0, 255).astype(np.uint8)


def srgb(hexcolor):
    """A colour picked in sRGB (like a colour picker), returned as linear RGB."""
    v = np.array([int(hexcolor[i:i + 2], 16) for i in (1, 3, 5)], dtype=np.float64) / 255.0
    return np.where(v <= 0.04045, v / 12.92, ((v + 0.055) / 1.055) ** 2.4)


# --- noise ----------------------------------------------------------------------
def _hash3(ix, iy, iz, seed):
    """Deterministic integer hash of lattice points -> float in [-1,1]."""
    h = (ix.astype(np.int64) * 73856093) ^ (iy.astype(np.int64) * 19349663) \
        ^ (iz.astype(np.int64) * 83492791) ^ (seed * 2654435761)
    h = h & 0xFFFFFFFF
    h = (h ^ (h >> 16)) * 0x45D9F3B & 0xFFFFFFFF
    h = (h ^ (h >> 16)) * 0x45D9F3B & 0xFFFFFFFF
    h = h ^ (h >> 16)
    return (h & 0xFFFFFF).astype(np.float64) / float(0x7FFFFF) - 1.0


def value_noise3(x, y, z, seed):
    """Smooth 3D value noise in about [-1,1] (quintic fade, trilinear blend)."""
    x0, y0, z0 = np.floor(x), np.floor(y), np.floor(z)
    fx, fy, fz = x - x0, y - y0, z - z0
    ix, iy, iz = x0.astype(np.int64), y0.astype(np.int64), z0.astype(np.int64)

    def fade(t):
        return t * t * t * (t * (t * 6 - 15) + 10)
    ux, uy, uz = fade(fx), fade(fy), fade(fz)
    out = 0.0
    for dx in (0, 1):
        wx = ux if dx else 1 - ux
        for dy in (0, 1):
            wy = uy if dy else 1 - uy
            for dz in (0, 1):
                wz = uz if dz else 1 - uz
                out = out + wx * wy * wz * _hash3(ix + dx, iy + dy, iz + dz, seed)
    return out


def fbm3(x, y, z, seed, octaves=6, lacunarity=2.0, gain=0.5):
    total, amp, norm = 0.0, 1.0, 0.0
    for o in range(octaves):
        f = lacunarity ** o
        # offset each octave so lattice points do not line up
        total = total + amp * value_noise3(x * f + 17.3 * o, y * f - 9.1 * o, z * f + 3.7 * o, seed + 101 * o)
        norm += amp
        amp *= gain
    return total / norm


def smoothstep(a, b, x):
    t = np.clip((x - a) / (b - a), 0.0, 1.0)
    return t * t * (3 - 2 * t)


def mix(a, b, t):
    t = np.asarray(t)[..., None]
    return a * (1 - t) + b * t


# --- earth ------------------------------------------------------------------------
def make_earth(width=1024, height=512, seed=1975):
    # pixel centres -> longitude/latitude -> points on the unit sphere
    lon = ((np.arange(width) + 0.5) / width) * 2 * np.pi - np.pi
    lat = np.pi / 2 - ((np.arange(height) + 0.5) / height) * np.pi
    lon, lat = np.meshgrid(lon, lat)
    px, py, pz = np.cos(lat) * np.cos(lon), np.cos(lat) * np.sin(lon), np.sin(lat)

    # domain-warped fractal noise gives ragged continents
    f = 1.6
    wx = fbm3(px * f + 5.2, py * f + 1.3, pz * f, seed + 1, octaves=4)
    wy = fbm3(px * f - 3.1, py * f + 7.7, pz * f, seed + 2, octaves=4)
    wz = fbm3(px * f + 2.4, py * f - 4.4, pz * f, seed + 3, octaves=4)
    warp = 0.35
    qx, qy, qz = px + warp * wx, py + warp * wy, pz + warp * wz
    elev = fbm3(qx * 1.8, qy * 1.8, qz * 1.8, seed, octaves=8, gain=0.52)

    # sea level at a quantile (weighted by area, cos(lat)) so ~32% is land
    wts = np.cos(lat).ravel()
    order = np.argsort(elev.ravel())
    cdf = np.cumsum(wts[order]) / wts.sum()
    sea = elev.ravel()[order][np.searchsorted(cdf, 0.68)]
    h = elev - sea                           # >0 land
    land_max = np.percentile(h[h > 0], 99.5)
    sea_min = np.percentile(h[h < 0], 0.5)
    hl = np.clip(h / land_max, 0, 1)         # 0 coast .. 1 peaks
    hd = np.clip(h / sea_min, 0, 1)          # 0 coast .. 1 abyss

    moist = fbm3(px * 3.0 + 11.0, py * 3.0, pz * 3.0, seed + 7, octaves=5)
    alat = np.abs(np.degrees(lat))

    # ocean: shallow turquoise at the coast to deep navy
    shallow, mid, deep = srgb("#2f6fa3"), srgb("#123f78"), srgb("#06173f")
    ocean = mix(mix(shallow, mid, smoothstep(0.0, 0.25, hd)), deep, smoothstep(0.25, 0.9, hd))

    # land biomes: desert in the subtropics where it is dry, forests elsewhere,
    # tundra towards the poles, then rock and snow with height
    forest, grass = srgb("#2f5a22"), srgb("#5f7d35")
    desert, tundra = srgb("#c2a36b"), srgb("#7d7a5c")
    rock, snow = srgb("#6e6357"), srgb("#f2f4f7")
    dryness = smoothstep(0.0, 0.35, 1 - np.abs(alat - 24) / 18 + 0.8 * moist)
    land = mix(forest, grass, smoothstep(-0.2, 0.3, moist))
    land = mix(land, desert, dryness * smoothstep(0.0, 0.05, hl))
    land = mix(land, tundra, smoothstep(50, 62, alat + 8 * moist))
    land = mix(land, rock, smoothstep(0.45, 0.7, hl))
    snowline = 0.82 - 0.5 * smoothstep(35, 70, alat)
    land = mix(land, snow, smoothstep(snowline, snowline + 0.08, hl))

    coast = smoothstep(-0.004, 0.004, h)
    color = mix(ocean, land, coast)

    # polar ice caps with a ragged noisy edge (over land and sea)
    edge = fbm3(px * 6 + 3.3, py * 6, pz * 6, seed + 13, octaves=5)
    ice = smoothstep(70, 73, alat + 7 * edge + 2.0 * (h > 0))
    color = mix(color, srgb("#eef2f6"), ice)
    return linear_to_srgb8(color)


# --- wood planks ----------------------------------------------------------------------
def make_wood(size=512, seed=7):
    y, x = np.mgrid[0:size, 0:size].astype(np.float64) + 0.5
    u, v = x / size, y / size
    planks = 6
    row = np.floor(v * planks)
    # each plank: its own ring centre (far away: long arcs), offset, tone
    rng = np.random.RandomState(seed)
    cy = rng.uniform(-3.0, 3.0, planks)
    cz = rng.uniform(-2.0, -0.6, planks)
    tone = rng.uniform(0.8, 1.15, planks)
    shift = rng.uniform(0, 1, planks)
    r = row.astype(int)
    vv = v * planks - row                    # 0..1 across a plank
    # distance to the tree's axis (along x) for a board cut off-centre
    d = np.sqrt((vv - 0.5 + cy[r] * 0.15) ** 2 + (cz[r]) ** 2 * 0.05)
    n = fbm3(u * 6.0, vv * 1.5, row * 5.3, seed, octaves=5)
    rings = d * 38.0 + 2.5 * n + 6 * shift[r]
    ring = 0.5 + 0.5 * np.sin(2 * np.pi * rings)
    ring = ring ** 3                         # thin dark latewood lines
    grain = fbm3(u * 90.0, vv * 6.0, row * 3.1 + 0.5, seed + 5, octaves=3)
    light, dark = srgb("#c8955a"), srgb("#7a4a22")
    col = mix(light, dark, np.clip(0.75 * ring + 0.25 * (0.5 + grain), 0, 1))
    col = col * tone[r][..., None]
    # dark gaps between planks and staggered butt joints
    gap = np.minimum(vv, 1 - vv) * size / planks
    joint_u = (u + 0.5 * (r % 2) + 0.13 * r) % 1.0
    jgap = np.minimum(joint_u, 1 - joint_u) * size
    groove = np.minimum(smoothstep(0.0, 2.0, gap), smoothstep(0.0, 1.5, jgap))
    col = col * (0.35 + 0.65 * groove[..., None])
    return linear_to_srgb8(col)


# --- tiles --------------------------------------------------------------------------
def make_tiles(size=512, seed=11, n=8):
    y, x = np.mgrid[0:size, 0:size].astype(np.float64) + 0.5
    u, v = x / size * n, y / size * n
    iu, iv = np.floor(u), np.floor(v)
    fu, fv = u - iu, v - iv
    rng = np.random.RandomState(seed)
    palette = np.array([srgb(c) for c in ("#e9e4d8", "#d9cfb8", "#3f6d8c", "#e9e4d8")])
    pick = rng.randint(0, len(palette), size=(n, n))
    pick[(np.add.outer(np.arange(n), np.arange(n)) % 2) == 0] = 0  # mostly cream
    jitter = rng.uniform(0.92, 1.05, size=(n, n))
    ti, tj = iv.astype(int) % n, iu.astype(int) % n
    col = palette[pick[tj, ti]] * jitter[tj, ti][..., None]
    glaze = fbm3(u * 4, v * 4, 0.5, seed, octaves=4)
    col = col * (1.0 + 0.06 * glaze[..., None])
    edge = np.minimum(np.minimum(fu, 1 - fu), np.minimum(fv, 1 - fv)) * size / n
    grout = srgb("#8a857c") * (1 + 0.1 * fbm3(u * 40, v * 40, 1.5, seed + 1, octaves=2))[..., None]
    col = mix(grout, col, smoothstep(1.5, 3.0, edge))
    return linear_to_srgb8(col)


TEXTURES = {"earth": make_earth, "wood": make_wood, "tiles": make_tiles}


def main(argv):
    names = argv or list(TEXTURES)
    for name in names:
        if name not in TEXTURES:
            sys.exit("unknown texture %r (have: %s)" % (name, ", ".join(TEXTURES)))
        write_png(os.path.join(OUT_DIR, name + ".png"), TEXTURES[name]())


if __name__ == "__main__":
    main(sys.argv[1:])
