# Verity rough edge: a delta lobe that no draw samples gets an albedo interval of width 0, so
# any stated albedo above 0 FAILS, however small (here 1e-9, 1e5 draws could never see it).
import numpy as np, verity
def sample(wi, u):
    n = len(u)
    wo = np.tile([-wi[0], -wi[1], wi[2]], (n, 1))         # a perfect mirror, always
    return wo, np.ones((n, 3)), np.ones(n), np.ones(n, bool)
ev = lambda wi, wo: np.zeros((len(wo), 3))
pdf = lambda wi, wo: np.zeros(len(wo))
r = verity.check_bsdf(sample, ev, pdf, wi=(0.5, 0, 0.8660254), alpha=1e-3, samples=100000,
                      name="mirror, pass-through of 1e-9 stated",
                      expect={"reflection": (1.0, [1.0] * 3), "pass-through": (1e-9, [1e-9] * 3)})
print(r)
print("verdict:", r.verdict, r.failures)
