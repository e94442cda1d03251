# roughdielectric, GGX, sample_visible false (all normals), eta 1.5, from above: does it share
# roughconductor's collapse onto the specular directions at small alpha (finding 12)? One
# check per alpha at 30 degrees, and the share of samples whose microfacet normal is exactly
# the macro normal (wo exactly the mirror or the straight refraction of wi).
import math, os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..'))
import numpy as np, mitsuba as mi, drjit as dr, verity
mi.set_variant('llvm_rgb'); mi.set_log_level(mi.LogLevel.Error); dr.set_thread_count(1)
from check_mitsuba_bsdfs import Adapter

eta, deg = 1.5, 30.0
t = math.radians(deg)
wi = (float(np.float32(math.sin(t))), 0.0, float(np.float32(math.cos(t))))
for alpha in (1e-4, 2e-3, 0.04):
    ad = Adapter(mi, dr, {'type': 'roughdielectric', 'distribution': 'ggx', 'alpha': alpha,
                          'sample_visible': False, 'int_ior': eta, 'ext_ior': 1.0})
    r = verity.check_bsdf(*ad.callables(), wi=wi, alpha=0.01, samples=500_000, threads=1,
                          exterior_index=1.0, interior_index=eta,
                          name=f'roughdielectric ggx all normals alpha {alpha} at {deg}')
    u = np.random.default_rng(1).random((200_000, 3))
    wo, w, pdf, _ = ad.sample(np.array(wi), u)
    ok = pdf > 0
    refl = ok & (wo[:, 2] > 0); tran = ok & (wo[:, 2] < 0)
    # the exact specular directions of the float wi, as Mitsuba's own formulas give them
    mirror = np.array([-wi[0], -wi[1], wi[2]], dtype=np.float32)
    exact_r = np.all(wo[refl].astype(np.float32) == mirror, axis=1).mean()
    wt = wo[tran]; s_t = np.hypot(wt[:, 0], wt[:, 1]) / np.linalg.norm(wt, axis=1)
    s_exact = wi[0] / eta
    exact_t = np.mean(np.abs(s_t - s_exact) < 1e-7)
    cs = r.chi_square
    d = r.defects.get('sample pdf != pdf()', {})
    print(f"alpha {alpha:g}: {r.verdict} ({', '.join(r.failures) or 'none'}); chi-square "
          f"{cs['statistic']:.0f} on {cs['dof']} dof; sample pdf != pdf() in "
          f"{d.get('count', 0)} samples; of 200,000 draws {exact_r:.1%} of the reflections are "
          f"the mirror direction exactly, {exact_t:.1%} of the refractions Snell's direction "
          f"(to 1e-7 in sin)")
