"""NumPy lobes and warps for the tests, written as a user writes them (docs/python.md), and the
example's GGX (examples/python/ggx.py)."""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "examples", "python"))
from ggx import Ggx  # noqa: E402,F401


class Lambert:
    """f = albedo/π, cosine-weighted sampling (Malley's method): pdf = cos θ/π.
    `scale_weight` and `scale_pdf` plant a weight or a pdf() error."""

    def __init__(self, albedo=0.8, scale_weight=1.0, scale_pdf=1.0):
        self.albedo, self.scale_weight, self.scale_pdf = albedo, scale_weight, scale_pdf

    def sample(self, wi, u):
        r, phi = np.sqrt(u[:, 1]), 2 * np.pi * u[:, 2]
        wo = np.stack([r * np.cos(phi), r * np.sin(phi), np.sqrt(np.maximum(0, 1 - u[:, 1]))], -1)
        pdf = wo[:, 2] / np.pi
        weight = np.full(len(u), self.albedo * self.scale_weight)
        return wo, weight, pdf

    def eval(self, wi, wo):
        wi = np.broadcast_to(wi, wo.shape)
        return np.where((wi[..., 2] > 0) & (wo[..., 2] > 0), self.albedo / np.pi, 0.0)

    def pdf(self, wi, wo):
        return np.where(wo[..., 2] > 0, self.scale_pdf * wo[..., 2] / np.pi, 0.0)


def fresnel(cos_i, eta):
    """Unpolarised Fresnel reflectance of a dielectric of relative index eta (below / above), for
    cos θi on either side."""
    if cos_i < 0:
        eta, cos_i = 1 / eta, -cos_i
    sin2_t = (1 - cos_i * cos_i) / (eta * eta)
    if sin2_t >= 1:
        return 1.0
    cos_t = np.sqrt(1 - sin2_t)
    rs = (cos_i - eta * cos_t) / (cos_i + eta * cos_t)
    rp = (eta * cos_i - cos_t) / (eta * cos_i + cos_t)
    return (rs * rs + rp * rp) / 2


class Glass:
    """Smooth glass of relative index eta: reflection or refraction chosen by Fresnel's
    reflectance, the refraction's radiance scaled by 1/η'² (η' the index across, seen from wi).
    Delta lobes only."""

    def __init__(self, eta):
        self.eta = eta

    def sample(self, wi, u):
        r = fresnel(wi[2], self.eta)
        e = self.eta if wi[2] > 0 else 1 / self.eta
        reflect = u[:, 0] < r
        wo = np.tile([-wi[0], -wi[1], wi[2]], (len(u), 1))
        if r < 1:
            cos_t = np.sqrt(1 - (1 - wi[2] ** 2) / (e * e))
            wo[~reflect] = [-wi[0] / e, -wi[1] / e, -cos_t if wi[2] > 0 else cos_t]
        weight = np.where(reflect, 1.0, 1 / (e * e))
        pdf = np.where(reflect, r, 1 - r)
        return wo, weight, pdf, np.ones(len(u), dtype=bool)

    def expect(self, wi):
        """check_bsdf's `expect` at wi: each lobe's share and albedo."""
        r = fresnel(wi[2], self.eta)
        e = self.eta if wi[2] > 0 else 1 / self.eta
        return {"reflection": (r, [r]), "refraction": (1 - r, [(1 - r) / (e * e)])}

    @staticmethod
    def zero(wi, wo):
        return np.zeros(len(wo))


def uniform_square(u):
    return u


def polar_disk(u, broken=False):
    r = u[:, 0] if broken else np.sqrt(u[:, 0])
    phi = 2 * np.pi * u[:, 1]
    return np.stack([r * np.cos(phi), r * np.sin(phi)], -1)


def uniform_triangle(u):
    # Folding the square onto the triangle: b0 + b1 ≤ 1.
    flip = u.sum(axis=1) > 1
    return np.where(flip[:, None], 1 - u[:, ::-1], u)


def cosine_hemisphere(u):
    r, phi = np.sqrt(u[:, 0]), 2 * np.pi * u[:, 1]
    return np.stack([r * np.cos(phi), r * np.sin(phi), np.sqrt(np.maximum(0, 1 - u[:, 0]))], -1)


def uniform_sphere(u):
    z = 1 - 2 * u[:, 0]
    r, phi = np.sqrt(np.maximum(0, 1 - z * z)), 2 * np.pi * u[:, 1]
    return np.stack([r * np.cos(phi), r * np.sin(phi), z], -1)


WARPS = {
    "square": (uniform_square, lambda p: np.ones(len(p))),
    "disk": (polar_disk, lambda p: np.full(len(p), 1 / np.pi)),
    "triangle": (uniform_triangle, lambda p: np.full(len(p), 2.0)),
    "hemisphere": (cosine_hemisphere, lambda p: np.maximum(p[:, 2], 0) / np.pi),
    "sphere": (uniform_sphere, lambda p: np.full(len(p), 1 / (4 * np.pi))),
}


class Counted:
    """A callable that counts its calls and the points it was given."""

    def __init__(self, function):
        self.function, self.calls, self.points = function, 0, 0

    def __call__(self, *args):
        self.calls += 1
        self.points += len(args[-1])
        return self.function(*args)
