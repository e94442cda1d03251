# Verity's check of the Beckmann roughconductor alpha_u 1, alpha_v 1e-4 (and swapped) at normal
# incidence, 10^6 samples on equal cells, three seeds each. Before 2026-11-29 (afternoon) every
# run FAILED: the quadrature read a sliver of the lobe against a cell's edge from its tail
# alone (Mitsuba sets D to 0 below 1e-20), a pdf integral of 0.841022 against erf(1) = 0.842701,
# and the cells beside it expected no sample. Finding 17; docs/checks.md, "A rule whose nodes
# all read zero".
import os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..'))
import mitsuba as mi, drjit as dr
mi.set_variant('llvm_rgb'); mi.set_log_level(mi.LogLevel.Error); dr.set_thread_count(1)
import verity
from check_mitsuba_bsdfs import Adapter, rgb
for au, av in ((1.0, 1e-4), (1e-4, 1.0)):
    ad = Adapter(mi, dr, {'type': 'roughconductor', 'distribution': 'beckmann', 'alpha_u': au,
                          'alpha_v': av, 'eta': rgb(0.2), 'k': rgb(3.5)})
    for seed in range(3):
        r = verity.check_bsdf(ad.sample, ad.eval, ad.pdf, wi=(0.0, 0.0, 1.0), alpha=0.01,
                              name=f"beckmann {au:g} x {av:g}, 0 deg, {seed}", threads=1)
        lines = [l.strip() for l in str(r).splitlines() if "chi-square:" in l or "pdf integral:" in l]
        print(f"alpha_u {au:g}, alpha_v {av:g}, seed {seed}: {r.verdict}")
        for l in lines:
            print("   ", l)
