# The mass of the GGX visible-normal reflection lobe above the horizon, in double precision,
# by integrating over the slope plane (sx = alpha tan u, so the heavy tails map to a finite
# range): the fraction of Mitsuba's samples that should land above the horizon.
import math, sys, numpy as np
a = float(sys.argv[1]); inc = float(sys.argv[2]); n = int(sys.argv[3]) if len(sys.argv) > 3 else 4000
t = math.radians(inc)
wi = np.array([float(np.float32(math.sin(t))), 0.0, float(np.float32(math.cos(t)))])
wi /= np.linalg.norm(wi)
g1 = 2 * wi[2] / (wi[2] + math.sqrt(a * a * (wi[0]**2 + wi[1]**2) + wi[2]**2))
u = (np.arange(n) + 0.5) / n * math.pi - math.pi / 2          # midpoint rule in u, v
du = math.pi / n
total = 0.0; above = 0.0
for chunk in np.array_split(np.arange(n), 40):
    U, V = np.meshgrid(u[chunk], u, indexing='ij')
    sx, sy = a * np.tan(U), a * np.tan(V)
    jac = a * a / (np.cos(U)**2 * np.cos(V)**2)                # ds = jac du dv
    p = 1 / (math.pi * a * a * (1 + (sx * sx + sy * sy) / (a * a))**2)
    m = np.stack([-sx, -sy, np.ones_like(sx)], -1)
    cm = 1 / np.sqrt(1 + sx * sx + sy * sy)
    m = m * cm[..., None]
    wim = m @ wi
    dens = g1 * np.maximum(0, wim) / (wi[2] * cm) * p * jac * du * du   # D_wi(m) dm
    woz = 2 * wim * m[..., 2] - wi[2]
    total += dens.sum(); above += dens[woz > 0].sum()
print(f"alpha {a} at {inc} deg: D_wi integrates to {total:.6f}; mass above the horizon {above:.6f} "
      f"({above/total:.6f} of it)")
