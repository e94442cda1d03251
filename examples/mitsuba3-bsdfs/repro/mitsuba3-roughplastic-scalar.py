# roughplastic GGX alpha 1, R 1, eta 3, wi 30 deg, scalar_rgb: integral of pdf() over 200,000
# uniform directions, and the fraction of 200,000 draws that sample() returns
import numpy as np, mitsuba as mi, drjit as dr, math
mi.set_variant('scalar_rgb'); mi.set_log_level(mi.LogLevel.Error)
rng = np.random.default_rng(0); n = 200_000
b = mi.load_dict({'type': 'roughplastic', 'distribution': 'ggx', 'alpha': 1.0, 'int_ior': 3.0, 'ext_ior': 1.0,
                  'diffuse_reflectance': {'type': 'rgb', 'value': [1.0] * 3}})
si = dr.zeros(mi.SurfaceInteraction3f); si.wi = mi.Vector3f(0.5, 0, 0.8660254); ctx = mi.BSDFContext()
v = rng.normal(size=(n, 3)); v /= np.linalg.norm(v, axis=1, keepdims=True)
p = np.array([b.pdf(ctx, si, mi.Vector3f(*map(float, x))) for x in v])
u = rng.random((n, 3))
ok = 0
for a in u:
    bs, w = b.sample(ctx, si, float(a[0]), mi.Point2f(float(a[1]), float(a[2])))
    ok += w[0] != 0
print(f"scalar_rgb: integral of pdf() {4*math.pi*p.mean():.4f} +- {4*math.pi*p.std()/math.sqrt(n):.4f}; sampled fraction {ok/n:.4f}")
