# Beckmann roughconductor without visible normals (sample_visible false), eta 0.2, k 3.5, at
# normal incidence: how many samples return exactly the mirror direction (sin theta_m rounded
# to 0, finding 12's line), and a sample's pdf against pdf().
import os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..'))
import numpy as np, mitsuba as mi, drjit as dr
mi.set_variant('llvm_rgb'); mi.set_log_level(mi.LogLevel.Error); dr.set_thread_count(1)
from check_mitsuba_bsdfs import Adapter, rgb
wi = np.array([0.0, 0.0, 1.0])
q = [0.001, 0.5, 0.999]
for alpha in (1e-4, 2.1e-3, 0.04):
    ad = Adapter(mi, dr, {'type': 'roughconductor', 'distribution': 'beckmann', 'alpha': alpha,
                          'sample_visible': False, 'eta': rgb(0.2), 'k': rgb(3.5)})
    wo, w, pdf, _ = ad.sample(wi, np.random.default_rng(3).random((1_000_000, 3)))
    ok = pdf > 0
    mirror = np.mean((wo[ok, 0] == 0) & (wo[ok, 1] == 0))
    r = pdf[ok] / ad.pdf(wi, wo[ok])
    print(f"alpha {alpha:g}: {mirror:.1%} of 10^6 samples exactly the mirror direction; "
          f"a sample's pdf / pdf() at the 0.1%, 50%, 99.9% quantiles: {np.round(np.quantile(r, q), 4)}")
