#!/usr/bin/env python3
"""Checks Mitsuba 3's BSDF plugins as families with Verity's family check, from Python.

Each family is one Mitsuba plugin (or one of its modes) over the ranges of its parameters that
Mitsuba's loader accepts: every corner of the box of those ranges and a Latin hypercube of
points inside it, at 0, 30, 60, 85, 89.9 and 90 degrees of incidence (and from below for a
plugin that transmits or is two-sided), all at one family-wise level.

Mitsuba is not part of this repository: build it on its own (README.md says how) and put its
Python package on PYTHONPATH beside Verity's:

    PYTHONPATH=$HOME/verity/lib/python3/dist-packages:$HOME/mitsuba3/build/python \\
        python3 check_mitsuba_bsdfs.py --only roughconductor-ggx --output mitsuba3-bsdfs

Conventions. Mitsuba's local frame is Verity's (normal +z, wi and wo pointing away from the
surface, wo.z < 0 for transmission). Mitsuba's eval() returns f*|cos theta_o|, so the adapter
divides by |cos theta_o| to give Verity f; a sample's weight is f*|cos|/pdf in both. A sample
whose weight is 0 in every channel is no sample (pdf 0 for Verity), as Mitsuba's own chi2
adapter treats it. Samples whose sampled_type has a Delta flag (DeltaReflection,
DeltaTransmission, Null) are delta samples. Radiance transport (Mitsuba's default context).
Every check runs with threads=1, on the calling thread, as Dr.Jit needs.

Exit status: 0 when every family checked passed, 1 when one did not, 2 on a bad option or when
Mitsuba or Verity cannot be imported.
"""
import argparse
import json
import os
import sys
import time

try:
    import numpy as np
except ImportError:
    print("check_mitsuba_bsdfs: error: NumPy is missing: run it with a Python that has it "
          "(Debian's /usr/bin/python3 with python3-numpy)", file=sys.stderr)
    sys.exit(2)

# ----------------------------------------------------------------------------------------------
# Mitsuba through a batched adapter


# Every check runs with threads=1: Verity then runs the whole check on the calling thread,
# callables included, which Dr.Jit's thread-bound scopes need (a callable entered from another
# thread fails with "jitc_assemble(): variable ... depends on ..." unless it opens a new scope).


class Adapter:
    """The three batched callables of verity.check_bsdf for one Mitsuba BSDF (a load_dict
    dictionary), in Verity's conventions."""

    def __init__(self, mi, dr, desc):
        self.mi, self.dr = mi, dr
        self.bsdf = mi.load_dict(desc)
        self.ctx = mi.BSDFContext()  # radiance transport, every lobe
        self.scalar = mi.variant().startswith("scalar")
        self.delta_bits = int(mi.BSDFFlags.Delta)

    # -- helpers
    def _float(self, x):
        """A 1-D array as a Dr.Jit Float. Dr.Jit (v3.8.0, LLVM backend) maps a contiguous
        float32 array without copying, and its kernels load whole vectors of 16 floats: up to 15
        past the array's end, a segmentation fault where the array ends at the end of mapped
        memory (the report's limit 6; repro/drjit-overread.py). So it is given the head of a
        copy padded by 16."""
        padded = np.zeros(len(x) + 16, dtype=np.float32)
        padded[:len(x)] = x
        return self.mi.Float(padded[:len(x)])

    def _vec(self, a):
        return self.mi.Vector3f(self._float(a[:, 0]), self._float(a[:, 1]), self._float(a[:, 2]))

    def _si(self, wi, n):
        mi, dr = self.mi, self.dr
        si = dr.zeros(mi.SurfaceInteraction3f, n)
        si.n = mi.Normal3f(0, 0, 1)
        si.sh_frame = mi.Frame3f(mi.Vector3f(0, 0, 1))
        si.uv = mi.Point2f(0.5, 0.5)
        si.wi = self._vec(np.broadcast_to(np.asarray(wi, dtype=np.float64), (n, 3)))
        return si

    @staticmethod
    def _np(v, n):
        """A Dr.Jit array as n doubles (a literal of width 1 broadcast)."""
        return np.broadcast_to(np.asarray(v, dtype=np.float64).reshape(-1), (n,))

    def _np3(self, v, n):
        return np.stack([self._np(v[0], n), self._np(v[1], n), self._np(v[2], n)], axis=-1)

    # -- Verity's callables
    def sample(self, wi, u):
        n = len(u)
        u = np.minimum(u.astype(np.float32), np.float32(1) - np.float32(2.0**-24))
        if self.scalar:
            return self._sample_scalar(wi, u)
        mi = self.mi
        si = self._si(wi, n)
        bs, weight = self.bsdf.sample(self.ctx, si, self._float(u[:, 0]),
                                      mi.Point2f(self._float(u[:, 1]), self._float(u[:, 2])))
        wo = self._np3(bs.wo, n)
        w = self._np3(weight, n)
        pdf = self._np(bs.pdf, n)
        kind = np.broadcast_to(np.asarray(bs.sampled_type, dtype=np.uint32).reshape(-1), (n,))
        delta = (kind & self.delta_bits) != 0
        return self._finish(wo, w, pdf, delta)

    def _finish(self, wo, w, pdf, delta):
        declined = np.all(w == 0, axis=1) | ~np.isfinite(pdf)
        pdf = np.where(declined, 0.0, pdf)
        return wo, w, pdf, delta & ~declined

    def _sample_scalar(self, wi, u):
        mi = self.mi
        n = len(u)
        wo, w = np.zeros((n, 3)), np.zeros((n, 3))
        pdf, delta = np.zeros(n), np.zeros(n, dtype=bool)
        si = self._si1(wi)
        for k in range(n):
            bs, weight = self.bsdf.sample(self.ctx, si, float(u[k, 0]),
                                          mi.Point2f(float(u[k, 1]), float(u[k, 2])))
            wo[k] = (bs.wo[0], bs.wo[1], bs.wo[2])
            w[k] = (weight[0], weight[1], weight[2])
            pdf[k] = bs.pdf
            delta[k] = (int(bs.sampled_type) & self.delta_bits) != 0
        return self._finish(wo, w, pdf, delta)

    def _si1(self, wi):
        mi, dr = self.mi, self.dr
        si = dr.zeros(mi.SurfaceInteraction3f)
        si.n = mi.Normal3f(0, 0, 1)
        si.sh_frame = mi.Frame3f(mi.Vector3f(0, 0, 1))
        si.uv = mi.Point2f(0.5, 0.5)
        si.wi = mi.Vector3f(float(wi[0]), float(wi[1]), float(wi[2]))
        return si

    def eval(self, wi, wo):
        n = len(wo)
        wi = np.asarray(wi, dtype=np.float64)
        if self.scalar:
            f = np.zeros((n, 3))
            for k in range(n):
                w = wi if wi.ndim == 1 else wi[k]
                si = self._si1(w)
                v = self.bsdf.eval(self.ctx, si, self.mi.Vector3f(*map(float, wo[k])))
                f[k] = (v[0], v[1], v[2])
        else:
            si = self._si(wi, n)
            f = self._np3(self.bsdf.eval(self.ctx, si, self._vec(wo)), n)
        cos_o = np.abs(wo[:, 2].astype(np.float32)).astype(np.float64)
        with np.errstate(divide="ignore", invalid="ignore"):
            return np.where(cos_o[:, None] > 0, f / cos_o[:, None], 0.0)

    def pdf(self, wi, wo):
        n = len(wo)
        if self.scalar:
            si = self._si1(wi)
            return np.array([float(self.bsdf.pdf(self.ctx, si, self.mi.Vector3f(*map(float, w))))
                             for w in wo])
        si = self._si(wi, n)
        return self._np(self.bsdf.pdf(self.ctx, si, self._vec(wo)), n).copy()

    def callables(self):
        return self.sample, self.eval, self.pdf


# ----------------------------------------------------------------------------------------------
# What the delta lobes should carry: Fresnel's equations written here from the textbook (Born &
# Wolf; the thin slab's r' = 2r/(1 + r) sums its internal reflections), not from Mitsuba.


def fresnel(cos_i, n):
    """Unpolarised reflectance of an interface of (complex) relative index n at |cos_i|."""
    c = complex(abs(cos_i))
    n = complex(n)
    s2 = 1 - c * c
    root = np.sqrt(n * n - s2)
    rs = (c - root) / (c + root)
    rp = (n * n * c - root) / (n * n * c + root)
    return float((abs(rs) ** 2 + abs(rp) ** 2) / 2)


def dielectric_reflectance(cos_i, eta):
    """Real index: total internal reflection gives 1 (n < 1 beyond the critical angle)."""
    n = eta if cos_i > 0 else 1 / eta
    if 1 - cos_i * cos_i > n * n:
        return 1.0
    return fresnel(cos_i, n)


def expected_delta(family, values, wi):
    """Verity's `expect` for one configuration of a delta-only family, or None."""
    c = wi[2]
    if c == 0:
        return None  # exactly grazing: Mitsuba declines, and Fresnel gives 1; nothing to state
    if family == "conductor":
        F = fresnel(c, complex(values["eta"], values["k"]))
        return {"reflection": (1.0, [F] * 3)}
    if family == "dielectric":
        eta = values["eta"]
        F = dielectric_reflectance(c, eta)
        # Radiance transport: a refracted weight carries (eta_i / eta_t)^2.
        scale = 1 / eta**2 if c > 0 else eta**2
        return {"reflection": (F, [F] * 3), "refraction": (1 - F, [(1 - F) * scale] * 3)}
    if family == "thindielectric":
        r = fresnel(c, values["eta"])
        r = 2 * r / (1 + r)
        return {"reflection": (r, [r] * 3), "pass-through": (1 - r, [1 - r] * 3)}
    return None


def delta_expectation(family, values, samples, stated):
    """The factory's `expect` for one configuration of a delta-only family: Verity calls it with
    the configuration's wi. A lobe expected in fewer than 100 of the draws is stated by its
    share alone: Verity tests no albedo of a lobe drawn fewer than 30 times (the check is then
    INCONCLUSIVE), and 100 expected draws make fewer than 30 all but impossible."""
    def expect(wi):
        e = expected_delta(family, values, wi)
        if e:
            stated.append(wi)
            e = {lobe: (share, albedo if share * samples >= 100 else None)
                 for lobe, (share, albedo) in e.items()}
        return e
    return expect


# ----------------------------------------------------------------------------------------------
# The families

# Grey values, so that a family's parameter is what the plugin computes with in every channel.
def rgb(v):
    return {"type": "rgb", "value": [float(v)] * 3}


# The envelope of the conductor spectra Mitsuba names (resources/data/ior, material=...), as its
# scalar_rgb variant converts them to RGB; measured by named_conductor_envelope() and kept here
# so that each run checks the same box. --print-conductor-envelope prints it again.
CONDUCTOR_ETA = (0.0, 0.0)
CONDUCTOR_K = (0.0, 0.0)

# A fixed conductor for the families that sweep roughness only: eta 0.2, k 3.5 (as pbrt-v4's).
FIXED_ETA, FIXED_K = 0.2, 3.5


class Family:
    """One plugin (or one mode of it) over a box of parameters. `indices(values)` gives the
    indices of refraction above and below, (1, eta), for a plugin that refracts: Verity's
    reciprocity across a refraction and its delta check's Snell direction use them."""

    def __init__(self, name, plugin, describe, params, make, from_below=False, delta_only=False,
                 indices=None):
        self.name, self.plugin, self.describe = name, plugin, describe
        self.params, self.make = params, make
        self.from_below, self.delta_only = from_below, delta_only
        self.indices = indices


def microfacet(distribution, visible, alpha=None, alpha_u=None, alpha_v=None):
    d = {"distribution": distribution, "sample_visible": bool(visible)}
    if alpha is not None:
        d["alpha"] = float(alpha)
    else:
        d["alpha_u"], d["alpha_v"] = float(alpha_u), float(alpha_v)
    return d


def families():
    a_range = (1e-4, 1.0, "log")  # Mitsuba clamps alpha to 1e-4 (microfacet.h)
    eta_range = (1.0001, 3.0, "log")
    R = (0.01, 1.0)               # 0 itself: every weight 0, which Mitsuba means as "no sample"
    out = []
    out.append(Family("diffuse", "diffuse", "reflectance R", {"R": R},
                      lambda R: {"type": "diffuse", "reflectance": rgb(R)}))
    out.append(Family("conductor", "conductor", "eta, k over the named metals (delta only)",
                      {"eta": CONDUCTOR_ETA, "k": CONDUCTOR_K},
                      lambda eta, k: {"type": "conductor", "eta": rgb(eta), "k": rgb(k)},
                      delta_only=True))
    for dist in ("beckmann", "ggx"):
        for vis in (True, False):
            tag = f"roughconductor-{dist}" + ("" if vis else "-all-normals")
            out.append(Family(
                tag, "roughconductor",
                f"{dist}, sample_visible={vis}: alpha; eta, k over the named metals",
                {"alpha": a_range, "eta": CONDUCTOR_ETA, "k": CONDUCTOR_K},
                (lambda d, v: lambda alpha, eta, k: {
                    "type": "roughconductor", **microfacet(d, v, alpha=alpha),
                    "eta": rgb(eta), "k": rgb(k)})(dist, vis)))
        out.append(Family(
            f"roughconductor-{dist}-anisotropic", "roughconductor",
            f"{dist}, sample_visible=True, eta {FIXED_ETA}, k {FIXED_K}: alpha_u, alpha_v",
            {"alpha_u": a_range, "alpha_v": a_range},
            (lambda d: lambda alpha_u, alpha_v: {
                "type": "roughconductor", **microfacet(d, True, alpha_u=alpha_u, alpha_v=alpha_v),
                "eta": rgb(FIXED_ETA), "k": rgb(FIXED_K)})(dist)))
    out.append(Family("dielectric", "dielectric", "int_ior (ext_ior 1), both sides (delta only)",
                      {"eta": eta_range},
                      lambda eta: {"type": "dielectric", "int_ior": float(eta), "ext_ior": 1.0},
                      from_below=True, delta_only=True, indices=lambda v: (1.0, v["eta"])))
    out.append(Family("thindielectric", "thindielectric",
                      "int_ior (ext_ior 1), both sides (delta only)", {"eta": eta_range},
                      lambda eta: {"type": "thindielectric", "int_ior": float(eta),
                                   "ext_ior": 1.0},
                      from_below=True, delta_only=True))  # straight through: no Snell
    for dist in ("beckmann", "ggx"):
        for vis in (True, False):
            tag = f"roughdielectric-{dist}" + ("" if vis else "-all-normals")
            out.append(Family(
                tag, "roughdielectric",
                f"{dist}, sample_visible={vis}: alpha, int_ior (ext_ior 1), both sides",
                {"alpha": a_range, "eta": eta_range},
                (lambda d, v: lambda alpha, eta: {
                    "type": "roughdielectric", **microfacet(d, v, alpha=alpha),
                    "int_ior": float(eta), "ext_ior": 1.0})(dist, vis),
                from_below=True, indices=lambda v: (1.0, v["eta"])))
    out.append(Family("plastic", "plastic", "diffuse_reflectance R, int_ior (ext_ior 1)",
                      {"R": R, "eta": eta_range},
                      lambda R, eta: {"type": "plastic", "diffuse_reflectance": rgb(R),
                                      "int_ior": float(eta), "ext_ior": 1.0}))
    for dist in ("beckmann", "ggx"):
        out.append(Family(
            f"roughplastic-{dist}", "roughplastic",
            f"{dist}, sample_visible=True: alpha, diffuse_reflectance R, int_ior (ext_ior 1)",
            {"alpha": a_range, "R": R, "eta": eta_range},
            (lambda d: lambda alpha, R, eta: {
                "type": "roughplastic", **microfacet(d, True, alpha=alpha),
                "diffuse_reflectance": rgb(R), "int_ior": float(eta), "ext_ior": 1.0})(dist)))
    out.append(Family(
        "principled", "principled",
        "roughness, metallic, spec_trans, base_color 0.8 (eta 1.5 through specular 0.5)",
        {"roughness": (0.0, 1.0), "metallic": (0.0, 1.0), "spec_trans": (0.0, 1.0)},
        lambda roughness, metallic, spec_trans: {
            "type": "principled", "base_color": rgb(0.8), "roughness": float(roughness),
            "metallic": float(metallic), "spec_trans": float(spec_trans)},
        from_below=True, indices=lambda v: (1.0, 1.5)))
    out.append(Family(
        "principled-coat", "principled",
        "roughness 0.3; anisotropic, clearcoat, clearcoat_gloss, sheen",
        {"anisotropic": (0.0, 1.0), "clearcoat": (0.0, 1.0), "clearcoat_gloss": (0.0, 1.0),
         "sheen": (0.0, 1.0)},
        lambda anisotropic, clearcoat, clearcoat_gloss, sheen: {
            "type": "principled", "base_color": rgb(0.8), "roughness": 0.3,
            "anisotropic": float(anisotropic), "clearcoat": float(clearcoat),
            "clearcoat_gloss": float(clearcoat_gloss), "sheen": float(sheen)}))
    out.append(Family(
        "blendbsdf", "blendbsdf",
        "weight between diffuse (R 0.8) and a GGX roughconductor of alpha (eta 0.2, k 3.5)",
        {"weight": (0.0, 1.0), "alpha": a_range},
        lambda weight, alpha: {
            "type": "blendbsdf", "weight": float(weight),
            "a": {"type": "diffuse", "reflectance": rgb(0.8)},
            "b": {"type": "roughconductor", **microfacet("ggx", True, alpha=alpha),
                  "eta": rgb(FIXED_ETA), "k": rgb(FIXED_K)}}))
    out.append(Family(
        "twosided", "twosided",
        "one GGX roughconductor of alpha (eta 0.2, k 3.5) on both sides, both sides",
        {"alpha": a_range},
        lambda alpha: {"type": "twosided", "material": {
            "type": "roughconductor", **microfacet("ggx", True, alpha=alpha),
            "eta": rgb(FIXED_ETA), "k": rgb(FIXED_K)}},
        from_below=True))
    out.append(Family(
        "twosided-two", "twosided",
        "front diffuse (R 0.8), back a GGX roughconductor of alpha (eta 0.2, k 3.5), both sides",
        {"alpha": a_range},
        lambda alpha: {"type": "twosided",
                       "front": {"type": "diffuse", "reflectance": rgb(0.8)},
                       "back": {"type": "roughconductor", **microfacet("ggx", True, alpha=alpha),
                                "eta": rgb(FIXED_ETA), "k": rgb(FIXED_K)}},
        from_below=True))
    return out


def named_conductor_envelope(mi):
    """(eta range, k range) over the conductor spectra Mitsuba names, as RGB in this variant."""
    names = ["Ag", "Al", "AlAs", "AlSb", "Au", "Be", "Cr", "CsI", "Cu", "Cu2O", "CuO", "Hg",
             "HgTe", "Ir", "K", "Li", "MgO", "Mo", "Na_palik", "Nb", "Ni_palik", "Rh", "Se",
             "Se-e", "SiC", "SnTe", "Ta", "Te", "Te-e", "ThF4", "TiC", "TiN", "TiO2", "TiO2-e",
             "VC", "VN", "V_palik", "W", "a-C", "d-C"]
    eta, k = [], []
    for n in names:
        p = mi.traverse(mi.load_dict({"type": "conductor", "material": n}))
        e = np.ravel(np.asarray(p["eta.value"], dtype=np.float64))
        kk = np.ravel(np.asarray(p["k.value"], dtype=np.float64))
        # A channel that the RGB conversion clamped to eta 0 (AlSb's red: Mitsuba warns
        # "clamping out-of-gamut color") is not a measured index: left out of the box.
        keep = e > 0
        eta += [float(x) for x in e[keep]]
        k += [float(x) for x in kk[keep]]
    return (min(eta), max(eta)), (min(k), max(k))


# ----------------------------------------------------------------------------------------------
# Running


def fail(message):
    print(f"check_mitsuba_bsdfs: {message}", file=sys.stderr)
    sys.exit(2)


def parse_args(argv, names):
    p = argparse.ArgumentParser(
        description="Checks Mitsuba 3's BSDF plugins as families with Verity's family check.",
        epilog="families: " + ", ".join(names))
    p.add_argument("--only", action="append", metavar="NAME",
                   help="check this family (repeatable); all of them by default")
    size = p.add_mutually_exclusive_group()
    size.add_argument("--detect", metavar="EPS[,MASS]",
                      help="size each check to find a density error EPS over MASS of the "
                           "distribution (default 0.02,0.25)")
    size.add_argument("--samples", type=int, metavar="N",
                      help="draw N samples in each check instead of sizing it by --detect")
    p.add_argument("--max-samples", type=int, metavar="N",
                   help="with --detect: the most samples a check may draw; one whose target "
                        "needs more is never PASSED (Verity's default, 100000000)")
    p.add_argument("--delta-samples", type=int, default=100_000, metavar="N",
                   help="samples of each check of a family with only delta lobes, where "
                        "--detect has no histogram to size (100000)")
    p.add_argument("--no-delta-expectations", action="store_true",
                   help="do not state the delta-only families' shares and albedos from "
                        "Fresnel's equations (only their directions are then checked)")
    p.add_argument("--interior-points", type=int, default=4, metavar="N",
                   help="points inside each box, beside its corners (4)")
    p.add_argument("--incidences", metavar="A,B,...",
                   help="incidence angles in degrees (default 0,30,60,85,89.9,90)")
    p.add_argument("--alpha", type=float, default=0.01,
                   help="each family's family-wise level (0.01)")
    p.add_argument("--variant", default=None,
                   help="Mitsuba variant: llvm_rgb when the build has it, else scalar_rgb")
    p.add_argument("--threads", type=int, default=1,
                   help="Dr.Jit's worker threads for the llvm variant (1)")
    p.add_argument("--output", metavar="DIR", default="mitsuba3-bsdfs",
                   help="where the reports go (mitsuba3-bsdfs)")
    p.add_argument("--list", action="store_true", help="list the families and exit")
    p.add_argument("--progress", action="store_true",
                   help="print to stderr, with the time, each parameter set as it is made")
    a = p.parse_args(argv)
    if a.only:
        unknown = [n for n in a.only if n not in names]
        if unknown:
            fail(f"--only {unknown[0]}: no such family (families: {', '.join(names)})")
    if a.detect is not None:
        try:
            parts = [float(x) for x in a.detect.split(",")]
            if len(parts) not in (1, 2):
                raise ValueError
        except ValueError:
            fail(f"--detect {a.detect}: give EPS or EPS,MASS, e.g. 0.02 or 0.02,0.25")
        eps, mass = parts[0], parts[1] if len(parts) == 2 else 0.25
        if not (0 < eps < 1 and 0 < mass <= 0.5):
            fail(f"--detect {a.detect}: EPS must lie in (0, 1) and MASS in (0, 0.5]")
        a.detect = (eps, mass)
    if a.max_samples is not None and (a.samples is not None or a.max_samples < 1000):
        fail(f"--max-samples {a.max_samples}: give at least 1000, and not with --samples")
    if a.samples is not None and a.samples < 1000:
        fail(f"--samples {a.samples}: give at least 1000")
    if a.delta_samples < 1000:
        fail(f"--delta-samples {a.delta_samples}: give at least 1000")
    if a.interior_points < 0:
        fail(f"--interior-points {a.interior_points}: give 0 or more")
    if not (0 < a.alpha < 1):
        fail(f"--alpha {a.alpha}: give a level in (0, 1)")
    if a.threads < 1:
        fail(f"--threads {a.threads}: give 1 or more")
    if a.incidences is not None:
        try:
            a.incidences = [float(x) for x in a.incidences.split(",")]
        except ValueError:
            fail(f"--incidences {a.incidences}: give degrees separated by commas, e.g. 0,45,89.9")
        if not all(0 <= x <= 90 for x in a.incidences):
            fail(f"--incidences: every angle must lie in [0, 90]")
    return a


def import_mitsuba(variant):
    try:
        import mitsuba as mi
        import drjit as dr
    except ImportError as e:
        fail(f"cannot import Mitsuba 3 ({e}); build it as README.md says and put its build "
             "folder's python/ on PYTHONPATH")
    available = mi.variants()
    if variant is None:
        variant = "llvm_rgb" if "llvm_rgb" in available else "scalar_rgb"
    if variant not in available:
        fail(f"--variant {variant}: this Mitsuba build has {', '.join(available)}")
    if not variant.endswith("_rgb") or variant.startswith("cuda"):
        fail(f"--variant {variant}: this script adapts scalar_rgb and llvm_rgb (and their _ad_ "
             "forms)")
    try:
        mi.set_variant(variant)
    except Exception as e:  # Dr.Jit's LLVM backend may fail to find libLLVM
        fail(f"Mitsuba's variant {variant} does not start here: {e}")
    return mi, dr, variant


def import_verity():
    try:
        import verity
    except ImportError as e:
        fail(f"cannot import Verity's module ({e}); install it (docs/python.md) and put "
             "PREFIX/lib/python3/dist-packages on PYTHONPATH")
    return verity


def only_rounding(result):
    """True when a failed check failed only in per-sample comparisons, each within rounding."""
    if result.verdict != "FAILED":
        return False
    defects = result.defects
    comparisons = [d for d in defects.values() if "beyond_rounding" in d]
    if len(comparisons) != len(defects):
        return False
    if any(f in ("chi-square", "pdf integral") for f in result.failures):
        return False
    return bool(comparisons) and all(d["beyond_rounding"] == 0 and d["classified"] > 0
                                     for d in comparisons)


def main(argv=None):
    fams = families()
    names = [f.name for f in fams]
    args = parse_args(sys.argv[1:] if argv is None else argv, names)
    if args.list:
        for f in fams:
            print(f"{f.name:36s} {f.plugin:16s} {f.describe}")
        return 0
    verity = import_verity()
    mi, dr, variant = import_mitsuba(args.variant)
    mi.set_log_level(mi.LogLevel.Error)  # the named metals' RGB conversion warns of its gamut
    if variant.startswith("llvm"):
        dr.set_thread_count(args.threads)
    global CONDUCTOR_ETA, CONDUCTOR_K
    CONDUCTOR_ETA, CONDUCTOR_K = named_conductor_envelope(mi)
    fams = [f for f in families() if not args.only or f.name in args.only]
    os.makedirs(args.output, exist_ok=True)
    rows, all_passed = [], True
    for fam in fams:
        stated = []  # the configurations whose delta lobes' shares and albedos were stated

        def factory(**values):
            if args.progress:
                print(f"  [{time.strftime('%H:%M:%S')}] {fam.name}: "
                      + " ".join(f"{k}={v:.6g}" for k, v in values.items()),
                      file=sys.stderr, flush=True)
            a = Adapter(mi, dr, fam.make(**values))
            made = dict(zip(("sample", "eval", "pdf"), a.callables()))
            if fam.indices:
                outside, inside = map(float, fam.indices(values))
                made.update(exterior_index=outside, interior_index=inside)
            if fam.delta_only and not args.no_delta_expectations:
                made["expect"] = delta_expectation(fam.name, values, args.delta_samples, stated)
                if fam.indices:
                    made["eta"] = inside / outside  # Snell's direction of the refraction
            return made
        kw = dict(alpha=args.alpha, interior_points=args.interior_points,
                  from_below=fam.from_below, threads=1)
        if args.incidences is not None:
            kw["incidences"] = args.incidences
        if fam.delta_only:
            kw["samples"] = args.delta_samples
        elif args.samples is not None:
            kw["samples"] = args.samples
        elif args.detect is not None:
            kw["detect"] = args.detect
        if args.max_samples is not None and not fam.delta_only:
            kw["max_samples"] = args.max_samples
        print(f"== {fam.name}: {fam.plugin}, {fam.describe}", flush=True)
        t0, c0 = time.perf_counter(), time.process_time()
        r = verity.check_bsdf_family(factory, fam.params, **kw)
        wall, cpu = time.perf_counter() - t0, time.process_time() - c0
        print(r, flush=True)
        with open(os.path.join(args.output, fam.name + ".md"), "w") as f:
            f.write(f"# {fam.name}\n\nMitsuba `{fam.plugin}`, variant `{variant}`: "
                    f"{fam.describe}.\n\n" + r.markdown())
        with open(os.path.join(args.output, fam.name + ".json"), "w") as f:
            f.write(r.json())
        with open(os.path.join(args.output, fam.name + ".txt"), "w") as f:
            f.write(str(r) + "\n")
        confs = r.configurations
        verdicts = [c["result"].verdict for c in confs]
        failed = [c for c in confs if c["result"].verdict == "FAILED"]
        rows.append(dict(family=fam.name, plugin=fam.plugin, describe=fam.describe,
                         configurations=len(confs), passed=verdicts.count("PASSED"),
                         failed=len(failed),
                         only_rounding=sum(only_rounding(c["result"]) for c in failed),
                         inconclusive=verdicts.count("INCONCLUSIVE"), verdict=r.verdict,
                         wall_s=wall, cpu_s=cpu, samples=sum(c["result"].samples for c in confs),
                         sizing=("samples %d" % kw["samples"]) if "samples" in kw else
                         "detect %g over %g" % (kw.get("detect") or (0.02, 0.25))
                         + (", at most %d samples" % kw["max_samples"]
                            if "max_samples" in kw else ""),
                         interior_points=args.interior_points))
        if stated:
            rows[-1]["stated_lobes"] = len(stated)
        all_passed = all_passed and r.passed
        write_summary(args.output, variant, rows, mi)
    write_summary(args.output, variant, rows, mi)
    return 0 if all_passed else 1


def write_summary(out, variant, rows, mi):
    """DIR/summary.md and .json: this run's families, and those of earlier runs into DIR that
    this one did not check (so that families run one at a time make one table)."""
    try:
        with open(os.path.join(out, "summary.json")) as f:
            earlier = json.load(f)
        if earlier.get("variant") == variant:
            names = {r["family"] for r in rows}
            order = [f.name for f in families()]
            rows = [r for r in earlier["families"] if r["family"] not in names] + rows
            rows.sort(key=lambda r: order.index(r["family"]) if r["family"] in order else 99)
    except (OSError, ValueError, KeyError):
        pass
    lines = [f"# Mitsuba 3 BSDF families\n",
             f"Mitsuba {mi.__version__}, variant `{variant}`.\n",
             "| family | plugin | configurations | passed / failed (only within rounding) / "
             "inconclusive | each check | interior points | minutes wall / CPU |",
             "|---|---|---|---|---|---|---|"]
    for r in rows:
        lines.append(f"| `{r['family']}` | `{r['plugin']}` | {r['configurations']} | "
                     f"{r['passed']} / {r['failed']} ({r['only_rounding']}) / "
                     f"{r['inconclusive']} | {r.get('sizing', '')}"
                     + (f", lobes stated at {r['stated_lobes']}" if r.get("stated_lobes") else "")
                     + " | "
                     f"{r.get('interior_points', '')} | "
                     f"{r['wall_s'] / 60:.1f} / {r['cpu_s'] / 60:.1f} |")
    with open(os.path.join(out, "summary.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    with open(os.path.join(out, "summary.json"), "w") as f:
        json.dump(dict(variant=variant, mitsuba=mi.__version__, families=rows), f, indent=1)


if __name__ == "__main__":
    sys.exit(main())
