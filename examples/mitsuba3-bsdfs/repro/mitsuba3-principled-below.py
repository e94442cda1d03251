# principled seen from below with (1 - metallic) * spec_trans = 0: sample() declines, pdf()?
# Uniform directions over the sphere estimate the integral of pdf() (and of eval*|cos|).
import numpy as np, mitsuba as mi, drjit as dr
mi.set_variant('llvm_rgb'); mi.set_log_level(mi.LogLevel.Error)
rng = np.random.default_rng(0)
n = 2_000_000
v = rng.normal(size=(n, 3)); v /= np.linalg.norm(v, axis=1, keepdims=True)
ctx = mi.BSDFContext()
for rough, metal, trans in ((1.0, 0.0, 0.0), (0.5, 0.0, 0.0), (1.0, 1.0, 1.0), (1.0, 0.0, 1.0)):
    b = mi.load_dict({'type': 'principled', 'base_color': {'type': 'rgb', 'value': [0.8] * 3},
                      'roughness': rough, 'metallic': metal, 'spec_trans': trans})
    wi = np.array([0.5, 0.0, -0.8660254])
    si = dr.zeros(mi.SurfaceInteraction3f, n)
    si.wi = mi.Vector3f(*[mi.Float(np.full(n, x, np.float32)) for x in wi])
    bs, w = b.sample(ctx, si, mi.Float(rng.random(n).astype(np.float32)),
                     mi.Point2f(mi.Float(rng.random(n).astype(np.float32)), mi.Float(rng.random(n).astype(np.float32))))
    valid = np.mean(np.any(np.stack([np.asarray(w[i]) for i in range(3)]) != 0, axis=0))
    wo = mi.Vector3f(*[mi.Float(v[:, i].astype(np.float32)) for i in range(3)])
    p = np.asarray(b.pdf(ctx, si, wo)); f = np.asarray(b.eval(ctx, si, wo)[0])
    print(f"roughness {rough} metallic {metal} spec_trans {trans}, wi 30 deg from below: "
          f"sampled fraction {valid:.4f}; integral of pdf() {4*np.pi*p.mean():.4f}; "
          f"integral of eval*|cos| {4*np.pi*f.mean():.4f}")
