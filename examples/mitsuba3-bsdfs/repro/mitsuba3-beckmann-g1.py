# Beckmann roughconductor (sample_visible true, alpha 1, eta 7.50891, k 9.22381): Verity's pdf
# integral against the sampled fraction, beside the ratio of Mitsuba's rational approximation
# of Beckmann's Smith G1(wi) (microfacet.h, smith_g1) to the exact G1 in double. The
# visible-normal density D(m) G1(wi) <wi, m> / cos(theta_i) integrates to 1 with the exact G1,
# so with the approximation pdf() integrates to the sampled fraction times that ratio.
import math, os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..'))
import numpy as np, mitsuba as mi, drjit as dr, verity
mi.set_variant('llvm_rgb'); mi.set_log_level(mi.LogLevel.Error); dr.set_thread_count(1)
from check_mitsuba_bsdfs import Adapter, rgb

def g1_approx(a):  # Mitsuba's, as written in microfacet.h
    return 1.0 if a >= 1.6 else (3.535 * a + 2.181 * a * a) / (1 + 2.276 * a + 2.577 * a * a)

def g1_exact(a):   # Smith's G1 = 1 / (1 + Lambda), Beckmann's Lambda(a) in closed form
    return 1 / (1 + (math.erf(a) - 1) / 2 + math.exp(-a * a) / (2 * a * math.sqrt(math.pi)))

alpha = 1.0
ad = Adapter(mi, dr, {'type': 'roughconductor', 'distribution': 'beckmann', 'alpha': alpha,
                      'eta': rgb(7.50891), 'k': rgb(9.22381)})
for deg in [float(x) for x in (sys.argv[1:] or ['0', '30', '60', '85', '89.9'])]:
    t = math.radians(deg)
    wi = (float(np.float32(math.sin(t))), 0.0, float(np.float32(math.cos(t))))
    r = verity.check_bsdf(*ad.callables(), wi=wi, alpha=0.01, samples=1_000_000, threads=1,
                          name=f'beckmann alpha 1 at {deg}')
    p = r.pdf_integral
    lo, hi = p['valid_fraction_interval']
    a = 1 / (alpha * math.tan(t)) if deg > 0 else math.inf
    ratio = g1_approx(a) / g1_exact(a) if deg > 0 else 1.0
    print(f"{deg:5g} deg: {r.verdict:6s} pdf integral {p['integral']:.6f} (quadrature error "
          f"{p['quadrature_error']:.1e}), sampled fraction [{lo:.6f}, {hi:.6f}]; integral / "
          f"fraction {p['integral'] / ((lo + hi) / 2):.5f}; G1 approx / exact {ratio:.5f}")
