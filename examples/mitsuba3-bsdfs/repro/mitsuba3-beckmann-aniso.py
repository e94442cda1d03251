# Beckmann roughconductor (visible normals) alpha_u 1, alpha_v 1e-4 (and swapped), eta 0.2,
# k 3.5, at normal incidence, where the visible-normal density is the slope density itself:
# slopes x/alpha_u and y/alpha_v normal with variance 1/2 each. Are Mitsuba's samples so
# distributed, and is pdf() the density D(m) cos(theta_m) / (4 <wo, m>) written in double?
import math, os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..'))
import numpy as np, mitsuba as mi, drjit as dr
mi.set_variant('llvm_rgb'); mi.set_log_level(mi.LogLevel.Error); dr.set_thread_count(1)
from check_mitsuba_bsdfs import Adapter, rgb
n = 2_000_000
wi = np.array([0.0, 0.0, 1.0])
for au, av in ((1.0, 1e-4), (1e-4, 1.0)):
    ad = Adapter(mi, dr, {'type': 'roughconductor', 'distribution': 'beckmann', 'alpha_u': au,
                          'alpha_v': av, 'eta': rgb(0.2), 'k': rgb(3.5)})
    u = np.random.default_rng(2).random((n, 3))
    wo, w, pdf, _ = ad.sample(wi, u)
    ok = pdf > 0
    # the slopes of every draw (a declined one, below the horizon, keeps its wo)
    h = wi + wo; h /= np.linalg.norm(h, axis=1, keepdims=True)
    sx, sy = -h[:, 0] / h[:, 2] / au, -h[:, 1] / h[:, 2] / av
    # each slope coordinate / alpha ~ N(0, 1/2): compare quantiles of sqrt(2) * slope
    q = np.array([0.001, 0.01, 0.1, 0.5, 0.9, 0.99, 0.999])
    from statistics import NormalDist
    ref = np.array([NormalDist().inv_cdf(x) for x in q])
    print(f"alpha_u {au:g}, alpha_v {av:g}: {ok.mean():.4f} of draws valid (wo above the horizon)")
    print("  quantiles of sqrt(2) x-slope/alpha_u, every draw:", np.round(np.quantile(math.sqrt(2) * sx, q), 3))
    print("  quantiles of sqrt(2) y-slope/alpha_v, every draw:", np.round(np.quantile(math.sqrt(2) * sy, q), 3))
    print("  a standard normal's:                             ", np.round(ref, 3))
    wo, pdf, h, sx, sy = wo[ok], pdf[ok], h[ok], sx[ok], sy[ok]
    D = np.exp(-(sx**2 + sy**2)) / (math.pi * au * av * h[:, 2]**4)
    p_double = D * h[:, 2] / (4 * np.sum(wo * h, axis=1))
    r = ad.pdf(wi, wo) / p_double
    print("  pdf() / the density in double, quantiles 0.1%..99.9%:", np.round(np.quantile(r, q), 5))
    print("  a sample's pdf / pdf():", np.round(np.quantile(pdf / ad.pdf(wi, wo), q), 5))
