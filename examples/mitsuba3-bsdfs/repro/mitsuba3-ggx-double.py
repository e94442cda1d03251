# Independent check of Mitsuba's roughconductor (GGX, visible normals) at grazing incidence:
# Mitsuba's own sampler against a pdf written here in double precision from the textbook
# formulas (Heitz 2018's visible-normal density; D and G1 in forms free of 1 - cos^2), and
# against Mitsuba's float pdf(), on the same samples (same check names -> same seeds).
#   PYTHONPATH=$VERITY/lib/python3/dist-packages:$MITSUBA_BUILD/python \
#     nice -n 15 /usr/bin/python3 examples/mitsuba3-bsdfs/repro/mitsuba3-ggx-double.py [alpha] [incidence...]
import sys, math, numpy as np
import os; sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..'))
import mitsuba as mi
mi.set_variant('llvm_rgb'); mi.set_log_level(mi.LogLevel.Error)
import drjit as dr
dr.set_thread_count(1)
import verity
from check_mitsuba_bsdfs import Adapter, microfacet, rgb

ALPHA = float(sys.argv[1]) if len(sys.argv) > 1 else 1e-4
INCIDENCES = [float(x) for x in sys.argv[2:]] or [89.9, 90.0]
LEVEL = 6.98e-05  # the roughconductor-ggx family's per-test level

def ggx_pdf_double(wi, wo, a):
    # wi renormalised in double: the float wi of 89.9 deg is 2.7e-8 short of unit length, and
    # the half vector's Jacobian 1/(4 wo.h) turns that into a density 0.9% off near grazing
    # (about |wi| - 1 over cos^2 theta). The sampler reflects about m, which only scales wo.
    wi = np.asarray(wi, float)
    wi = np.broadcast_to(wi / np.linalg.norm(wi), wo.shape)
    h = wi + wo
    h = h / np.linalg.norm(h, axis=1, keepdims=True)
    h = np.where(h[:, 2:3] < 0, -h, h)
    D = 1 / (np.pi * a * a * ((h[:, 0]**2 + h[:, 1]**2) / (a * a) + h[:, 2]**2) ** 2)
    def g1(v):
        return 2 * v[:, 2] / (v[:, 2] + np.sqrt(a * a * (v[:, 0]**2 + v[:, 1]**2) + v[:, 2]**2))
    wih = np.sum(wi * h, axis=1)
    woh = np.sum(wo * h, axis=1)
    ok = (wi[:, 2] > 0) & (wo[:, 2] > 0) & (wih > 0) & (woh > 0)
    with np.errstate(all='ignore'):
        p = g1(wi) * wih * D / wi[:, 2] / (4 * woh)
    return np.where(ok, p, 0.0)

for inc in INCIDENCES:
    t = math.radians(inc)
    wi = np.array([np.float32(math.sin(t)), 0, np.float32(math.cos(t))], dtype=np.float64)
    desc = {"type": "roughconductor", **microfacet("ggx", True, alpha=ALPHA),
            "eta": rgb(7.50891), "k": rgb(9.22381)}
    a = Adapter(mi, dr, desc)
    name = f"alpha={ALPHA:g} eta=7.50891 k=9.22381 at {inc:g}° from above"
    for label, pdf in (("Mitsuba's float pdf()", a.pdf),
                       ("double-precision pdf", lambda w, o: ggx_pdf_double(w, o, ALPHA))):
        r = verity.check_bsdf(a.sample, a.eval, pdf, wi=tuple(wi), alpha=LEVEL, name=name,
                              detect=(0.02, 0.25), reciprocity=False)
        cs, pi = r.chi_square, r.pdf_integral
        print(f"{name}: {label}: {r.verdict} {r.failures} X2 {cs['statistic']:.0f} on "
              f"{cs['dof']} dof, p {cs['p_value']:.3g}; integral {pi['integral']:.6f}, valid "
              f"{pi['valid_fraction_interval'][0]:.6f}..{pi['valid_fraction_interval'][1]:.6f}, quadrature error {pi['quadrature_error']:.2g}; {r.samples} samples",
              flush=True)
    # the same samples' pdfs, three ways
    u = np.random.default_rng(1).random((200000, 3))
    wo, w, ps, delta = a.sample(wi, u)
    ok = ps > 0
    pm = a.pdf(wi, wo[ok])
    pd = ggx_pdf_double(wi, wo[ok], ALPHA)
    for lab, x in (("sample pdf / double", ps[ok] / pd), ("pdf() / double", pm / pd)):
        q = np.quantile(x, [0.001, 0.01, 0.5, 0.99, 0.999])
        print(f"   {lab}: quantiles 0.1%..99.9% {np.round(q, 4)}")
