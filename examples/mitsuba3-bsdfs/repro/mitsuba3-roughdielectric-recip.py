# Reciprocity of Mitsuba's roughdielectric (GGX, alpha 1, eta 3) for one transmitted pair, the
# failing sample of roughdielectric-ggx at 0 deg from above; Walter et al. 2007's BTDF written
# here in double (no Mitsuba code) as the reference for both orders.
import math, numpy as np, mitsuba as mi, drjit as dr
mi.set_variant('scalar_rgb')
A, ETA = 1.0, 3.0
def fresnel(c, n):            # unpolarised, real relative index n, c = cos on the incident side
    c = abs(c); s2 = (1 - c * c) / (n * n)
    if s2 >= 1: return 1.0
    ct = math.sqrt(1 - s2)
    rs = (c - n * ct) / (c + n * ct); rp = (n * c - ct) / (n * c + ct)
    return (rs * rs + rp * rp) / 2
def D(h):
    return 1 / (math.pi * A * A * ((h[0]**2 + h[1]**2) / (A * A) + h[2]**2) ** 2)
def G1(v, h):
    if np.dot(v, h) * v[2] <= 0: return 0.0
    return 2 * abs(v[2]) / (abs(v[2]) + math.sqrt(A * A * (v[0]**2 + v[1]**2) + v[2]**2))
def btdf(wi, wo):             # f without cos, radiance transport: scaled by (eta_i/eta_o)^2 of wi's side
    ni, no = (1.0, ETA) if wi[2] > 0 else (ETA, 1.0)
    h = -(ni * wi + no * wo); h /= np.linalg.norm(h)
    if h[2] < 0: h = -h
    F = fresnel(np.dot(wi, h), no / ni)
    den = (ni * np.dot(wi, h) + no * np.dot(wo, h)) ** 2
    f = abs(np.dot(wi, h)) * abs(np.dot(wo, h)) * no * no * (1 - F) * D(h) * G1(wi, h) * G1(wo, h) \
        / (abs(wi[2]) * abs(wo[2]) * den)
    return f * (ni / no) ** 2
b = mi.load_dict({'type': 'roughdielectric', 'distribution': 'ggx', 'alpha': A, 'int_ior': ETA, 'ext_ior': 1.0})
ctx = mi.BSDFContext()
def mev(wi, wo):
    si = dr.zeros(mi.SurfaceInteraction3f); si.wi = mi.Vector3f(*map(float, wi))
    return b.eval(ctx, si, mi.Vector3f(*map(float, wo)))[0] / abs(float(np.float32(wo[2])))
wi = np.array([0.0, 0.0, 1.0]); wo = np.array([-0.9025404, 0.2562943, -0.3460261])
wo = wo / np.linalg.norm(wo)
for a, bb, ei, eo in ((wi, wo, 1.0, ETA), (wo, wi, ETA, 1.0)):
    m, d = mev(a, bb), btdf(a, bb)
    print(f"eval(wi={np.round(a,4)}, wo={np.round(bb,4)}): Mitsuba {m:.7g}, double {d:.7g}, ratio {m/d:.6f}; times eta(wo)^2 = {m*eo*eo:.7g} (double {d*eo*eo:.7g})")
# Mitsuba's Fresnel term for the same half vector, from each side, against the double one
wi_in = wo
h = -(1.0 * wi + ETA * wi_in); h /= np.linalg.norm(h); h = h if h[2] > 0 else -h
c_out, c_in = float(np.dot(wi, h)), float(np.dot(wi_in, h))
print("cos on the outside", c_out, "inside", c_in)
print("mi.fresnel outside:", mi.fresnel(c_out, ETA)[0], " double:", fresnel(c_out, ETA))
print("mi.fresnel inside: ", mi.fresnel(c_in, ETA)[0], " double:", fresnel(c_in, 1 / ETA))
# Condition: Mitsuba's eval from inside at float neighbours of the inside direction, against
# the double BTDF at the same (float) directions
base = np.array([np.float32(x) for x in wi_in])
rng = np.random.default_rng(0)
rat = []
for k in range(200):
    d = base.copy()
    for j in range(3):
        d[j] = np.float32(d[j]) + np.float32(rng.integers(-4, 5)) * np.spacing(np.float32(d[j]))
    d = d.astype(np.float64)
    rat.append(mev(d, wi) / btdf(d / np.linalg.norm(d), wi))
print("Mitsuba / double from inside over 200 directions within 4 ulps: min %.5f median %.5f max %.5f"
      % (min(rat), float(np.median(rat)), max(rat)))
