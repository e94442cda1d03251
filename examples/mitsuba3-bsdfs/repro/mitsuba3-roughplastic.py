# roughplastic (GGX, visible normals): the fraction of draws sample() returns against the
# integral of pdf() (2e6 uniform directions), and pdf()'s sign, at corners of the family.
import numpy as np, mitsuba as mi, drjit as dr, math
mi.set_variant('llvm_rgb'); mi.set_log_level(mi.LogLevel.Error)
rng = np.random.default_rng(0)
n = 2_000_000
v = rng.normal(size=(n, 3)); v /= np.linalg.norm(v, axis=1, keepdims=True)
ctx = mi.BSDFContext()
def F(x): return mi.Float(np.asarray(x, np.float32))
for alpha, R, eta, inc in ((1.0, 1.0, 3.0, 30), (1.0, 0.01, 3.0, 30), (1.0, 1.0, 3.0, 0), (0.3, 1.0, 3.0, 30),
                           (1e-4, 1.0, 1.0001, 30), (1e-4, 1.0, 1.0001, 0)):
    b = mi.load_dict({'type': 'roughplastic', 'distribution': 'ggx', 'alpha': alpha,
                      'diffuse_reflectance': {'type': 'rgb', 'value': [R] * 3}, 'int_ior': eta, 'ext_ior': 1.0})
    t = math.radians(inc); wi = [math.sin(t), 0.0, math.cos(t)]
    si = dr.zeros(mi.SurfaceInteraction3f, n)
    si.wi = mi.Vector3f(*[F(np.full(n, x)) for x in wi])
    bs, w = b.sample(ctx, si, F(rng.random(n)), mi.Point2f(F(rng.random(n)), F(rng.random(n))))
    valid = np.mean(np.any(np.stack([np.broadcast_to(np.asarray(w[i]), (n,)) for i in range(3)]) != 0, axis=0))
    wo = mi.Vector3f(*[F(v[:, i]) for i in range(3)])
    p = np.asarray(b.pdf(ctx, si, wo))
    print(f"alpha {alpha} R {R} eta {eta} at {inc} deg: sampled fraction {valid:.4f}; "
          f"integral of pdf() {4*np.pi*p.mean():.4f} +- {4*np.pi*p.std()/math.sqrt(n):.4f}; "
          f"min pdf() {p.min():.3g}, directions with pdf() < 0: {np.mean(p < 0):.2g}")
