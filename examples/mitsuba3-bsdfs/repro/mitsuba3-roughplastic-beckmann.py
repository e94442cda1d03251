# roughplastic (Beckmann, visible normals) alpha 1, eta 3, wi 30 deg, in llvm_rgb: the fraction
# of draws sample() returns against the integral of pdf() (2e6 uniform directions), above and
# below the horizon: finding 9's unmasked pdf() with the other distribution.
import numpy as np, mitsuba as mi, drjit as dr, math
mi.set_variant('llvm_rgb'); mi.set_log_level(mi.LogLevel.Error); dr.set_thread_count(1)
rng = np.random.default_rng(0)
n = 2_000_000
v = rng.normal(size=(n, 3)); v /= np.linalg.norm(v, axis=1, keepdims=True)
ctx = mi.BSDFContext()
def F(x): return mi.Float(np.asarray(x, np.float32))
for R in (1.0, 0.01):
    b = mi.load_dict({'type': 'roughplastic', 'distribution': 'beckmann', 'alpha': 1.0,
                      'diffuse_reflectance': {'type': 'rgb', 'value': [R] * 3}, 'int_ior': 3.0, 'ext_ior': 1.0})
    t = math.radians(30); wi = [math.sin(t), 0.0, math.cos(t)]
    si = dr.zeros(mi.SurfaceInteraction3f, n)
    si.wi = mi.Vector3f(*[F(np.full(n, x)) for x in wi])
    bs, w = b.sample(ctx, si, F(rng.random(n)), mi.Point2f(F(rng.random(n)), F(rng.random(n))))
    valid = np.mean(np.any(np.stack([np.broadcast_to(np.asarray(w[i]), (n,)) for i in range(3)]) != 0, axis=0))
    p = np.asarray(b.pdf(ctx, si, mi.Vector3f(*[F(v[:, i]) for i in range(3)])))
    up, down = 4 * np.pi * np.mean(p * (v[:, 2] > 0)), 4 * np.pi * np.mean(p * (v[:, 2] < 0))
    print(f"R {R}: sampled fraction {valid:.4f}; integral of pdf() above the horizon {up:.4f}, "
          f"below {down:.4f} (+- {4*np.pi*p.std()/math.sqrt(n):.4f} in all)")
