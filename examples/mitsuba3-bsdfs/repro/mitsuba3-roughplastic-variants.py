# roughplastic GGX alpha 1, R 1, eta 3, wi 30 deg: pdf() of the same 20,000 directions in
# scalar_rgb (one call each) and llvm_rgb (one batched call); where do they differ?
import sys, subprocess, json, numpy as np, math
if len(sys.argv) > 1:
    import mitsuba as mi, drjit as dr
    variant = sys.argv[1]; mi.set_variant(variant); mi.set_log_level(mi.LogLevel.Error)
    rng = np.random.default_rng(0); n = 20_000
    v = rng.normal(size=(n, 3)); v /= np.linalg.norm(v, axis=1, keepdims=True); v = v.astype(np.float32)
    b = mi.load_dict({'type': 'roughplastic', 'distribution': 'ggx', 'alpha': 1.0, 'int_ior': 3.0, 'ext_ior': 1.0,
                      'diffuse_reflectance': {'type': 'rgb', 'value': [1.0] * 3}})
    ctx = mi.BSDFContext()
    if variant == 'scalar_rgb':
        si = dr.zeros(mi.SurfaceInteraction3f); si.wi = mi.Vector3f(0.5, 0, 0.8660254)
        p = [float(b.pdf(ctx, si, mi.Vector3f(*map(float, x)))) for x in v]
    else:
        si = dr.zeros(mi.SurfaceInteraction3f, n); si.wi = mi.Vector3f(0.5, 0, 0.8660254)
        p = np.asarray(b.pdf(ctx, si, mi.Vector3f(*[mi.Float(v[:, i]) for i in range(3)]))).tolist()
    print(json.dumps(p))
else:
    res = {}
    for variant in ('scalar_rgb', 'llvm_rgb'):
        out = subprocess.run([sys.executable, __file__, variant], capture_output=True, text=True).stdout
        res[variant] = np.array(json.loads(out.strip().splitlines()[-1]))
    rng = np.random.default_rng(0); v = rng.normal(size=(20000, 3)); v /= np.linalg.norm(v, axis=1, keepdims=True)
    s, l = res['scalar_rgb'], res['llvm_rgb']
    diff = ~np.isclose(s, l, rtol=1e-4, atol=0)
    print(f"integral: scalar {4*math.pi*s.mean():.4f}, llvm {4*math.pi*l.mean():.4f}; "
          f"{diff.sum()} of 20000 directions differ")
    for k in np.nonzero(diff)[0][:5]:
        print(f"  wo {np.round(v[k], 4)}: scalar {s[k]:.6g}, llvm {l[k]:.6g}")
    print(f"  of those, below the horizon: {(v[diff, 2] < 0).sum()}")
