# roughdielectric with sample_visible=false (GGX, alpha 1, eta 3): the sample weight against
# eval*|cos|/pdf, and what Walter et al.'s roughness scaling predicts for it. sample() draws the
# microfacet normal m from a distribution whose alpha is scaled by 1.2 - 0.2 sqrt(|cos theta_i|)
# (roughdielectric.cpp:271), and pdf() uses the same scaled density (:488), but the weight is
# G(wi, wo, m) (wi.m) / (cos theta_i cos theta_m) (:351), the weight of sampling m from the
# unscaled D. So weight / (eval*|cos|/pdf) should be D_scaled(m) / D(m), which is 1 only at
# normal incidence. eval() is Mitsuba's f*|cos theta_o|; the check's eval divides it out.
import math
import numpy as np
import mitsuba as mi, drjit as dr
mi.set_variant('llvm_rgb'); mi.set_log_level(mi.LogLevel.Error); dr.set_thread_count(1)

def padded(x):
    # Dr.Jit reads whole vectors past an unpadded NumPy array's end (drjit-overread.py).
    p = np.zeros(len(x) + 16, dtype=np.float32)
    p[:len(x)] = x
    return mi.Float(p[:len(x)])

def ggx_d(m, a):
    c2 = m[:, 2] ** 2
    t2 = (1 - c2) / c2
    return 1 / (math.pi * a * a * c2 * c2 * (1 + t2 / (a * a)) ** 2)

bsdf = mi.load_dict({'type': 'roughdielectric', 'distribution': 'ggx', 'alpha': 1.0,
                     'int_ior': 3.0, 'ext_ior': 1.0, 'sample_visible': False})
ctx = mi.BSDFContext()
rng = np.random.default_rng(1)
# 400,000 draws an incidence: the albedo's two estimates below differ by their bias, not noise.
n = 400000
for deg in (0, 30, 60, 85):
    t = math.radians(deg)
    wi = np.array([math.sin(t), 0.0, math.cos(t)])
    si = dr.zeros(mi.SurfaceInteraction3f, n)
    si.n = mi.Normal3f(0, 0, 1)
    si.sh_frame = mi.Frame3f(mi.Vector3f(0, 0, 1))
    si.wi = mi.Vector3f(*[padded(np.full(n, c)) for c in wi])
    u = rng.random((n, 3))
    bs, w = bsdf.sample(ctx, si, padded(u[:, 0]), mi.Point2f(padded(u[:, 1]), padded(u[:, 2])))
    wo = np.stack([np.asarray(bs.wo[k], dtype=np.float64) for k in range(3)], axis=1)
    weight = np.asarray(w[0], dtype=np.float64)
    f_cos = np.asarray(bsdf.eval(ctx, si, mi.Vector3f(*[padded(wo[:, k]) for k in range(3)]))[0],
                       dtype=np.float64)
    pdf = np.asarray(bsdf.pdf(ctx, si, mi.Vector3f(*[padded(wo[:, k]) for k in range(3)])),
                     dtype=np.float64)
    ok = (weight > 0) & (pdf > 0) & (f_cos > 0)
    ratio = weight[ok] / (f_cos[ok] / pdf[ok])
    # The generalised half vector of each sample, on the upper side.
    eta_o = np.where(wo[ok, 2] > 0, 1.0, 3.0)
    h = wi[None, :] + eta_o[:, None] * wo[ok]
    h /= np.linalg.norm(h, axis=1)[:, None]
    h *= np.sign(h[:, 2])[:, None]
    scale = 1.2 - 0.2 * math.sqrt(abs(wi[2]))
    predicted = ggx_d(h, scale) / ggx_d(h, 1.0)
    # The albedo two ways from the same draws: the mean weight (what a renderer sums) and the
    # mean of eval*|cos|/pdf (unbiased where sampling and pdf() agree, as the chi-square found).
    w_all = np.where(ok, weight, 0.0)
    e_all = np.zeros(n)
    e_all[ok] = f_cos[ok] / pdf[ok]
    bias = w_all.mean() / e_all.mean() - 1
    se = np.std(w_all - e_all * (w_all.mean() / e_all.mean())) / np.sqrt(n) / e_all.mean()
    print(f"{deg:2d} deg: alpha scale {scale:.4f}; weight / (eval*|cos|/pdf) over {ok.sum()} samples: "
          f"{ratio.min():.4f} to {ratio.max():.4f}; D_scaled(m)/D(m) predicts it within "
          f"{np.max(np.abs(ratio / predicted - 1)):.1e}; mean weight / mean eval*|cos|/pdf - 1 = "
          f"{bias:+.4f} (standard error {se:.4f})")
