"""A rough conductor in NumPy: the GGX microfacet distribution (Walter et al. 2007, "Microfacet
Models for Refraction through Rough Surfaces", EGSR) with the height-correlated Smith masking
term and Schlick's Fresnel, sampled by its distribution of visible normals (Heitz 2018,
"Sampling the GGX Distribution of Visible Normals", JCGT 7(4)). Every function takes a batch:
wi (3,) or (N, 3), wo and u (N, 3). Local frame: normal +z.

`broken=True` plants a subtle pdf error: pdf() and sample() report the density of sampling
all normals, D(h)·h.z/(4 wo·h), while sample() draws visible normals. The weight is still
eval·cos/pdf of the density it claims, so no per-sample check sees it: the histogram does
(10⁵ samples at 50°: chi-square p < 10⁻³⁰⁰), and the pdf integral (0.849 against a valid
fraction of 0.911).
"""
import numpy as np

F0 = np.array([0.95, 0.64, 0.54])  # gold, roughly


def _z(w):
    return w[..., 2]


def _normalize(v):
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


class Ggx:
    def __init__(self, alpha, broken=False):
        self.alpha = alpha
        self.broken = broken

    def _d(self, h):
        a2 = self.alpha * self.alpha
        t = _z(h) ** 2 * (a2 - 1) + 1
        return a2 / (np.pi * t * t)

    def _lambda(self, w):
        c2 = np.clip(_z(w) ** 2, 1e-300, 1)
        return 0.5 * (np.sqrt(1 + self.alpha**2 * (1 - c2) / c2) - 1)

    def _half(self, wi, wo):
        h = _normalize(wi + wo)
        return h * np.sign(_z(h))[..., None]

    def _fresnel(self, cos):
        return F0 + (1 - F0) * (1 - np.clip(cos, 0, 1))[..., None] ** 5

    def eval(self, wi, wo):
        wi = np.broadcast_to(wi, wo.shape)
        same_side = (_z(wi) > 0) & (_z(wo) > 0)
        h = self._half(wi, wo)
        g2 = 1 / (1 + self._lambda(wi) + self._lambda(wo))
        f = (self._d(h) * g2 / (4 * np.abs(_z(wi) * _z(wo))))[..., None]
        return np.where(same_side[..., None], f * self._fresnel(np.sum(wi * h, axis=-1)), 0.0)

    def _pdf_of(self, wi, wo, h):
        if self.broken:
            return self._d(h) * _z(h) / (4 * np.abs(np.sum(wo * h, axis=-1)))
        # Heitz 2018, eq. 17 and the Jacobian of reflection, 1/(4 wo·h).
        return self._d(h) / ((1 + self._lambda(wi)) * 4 * np.abs(_z(wi)))

    def pdf(self, wi, wo):
        same_side = (_z(wi) > 0) & (_z(wo) > 0)
        return np.where(same_side, self._pdf_of(wi, wo, self._half(wi, wo)), 0.0)

    def sample(self, wi, u):
        # Heitz 2018, listing 1: the visible normal in the hemisphere configuration.
        v = _normalize(np.array([self.alpha * wi[0], self.alpha * wi[1], wi[2]]))
        lensq = v[0] ** 2 + v[1] ** 2
        t1 = np.array([-v[1], v[0], 0]) / np.sqrt(lensq) if lensq > 0 else np.array([1.0, 0, 0])
        t2 = np.cross(v, t1)
        r = np.sqrt(u[:, 1])
        phi = 2 * np.pi * u[:, 2]
        p1 = r * np.cos(phi)
        s = 0.5 * (1 + v[2])
        p2 = (1 - s) * np.sqrt(1 - p1 * p1) + s * r * np.sin(phi)
        nh = (p1[:, None] * t1 + p2[:, None] * t2
              + np.sqrt(np.maximum(0, 1 - p1 * p1 - p2 * p2))[:, None] * v)
        h = _normalize(np.stack([self.alpha * nh[:, 0], self.alpha * nh[:, 1],
                                 np.maximum(1e-7, nh[:, 2])], axis=-1))
        cos = h @ wi
        wo = 2 * cos[:, None] * h - wi
        up = _z(wo) > 0
        pdf = np.where(up, self._pdf_of(wi, wo, h), 0.0)
        if self.broken:  # the weight of the density it claims
            f = self.eval(wi, wo)
            weight = f * (np.abs(_z(wo)) / np.where(up, pdf, 1))[:, None]
        else:
            # Heitz 2018, eq. 19: f·cos/pdf = F·G2/G1(wi).
            g1 = 1 + self._lambda(wi)
            weight = self._fresnel(cos) * (g1 / (g1 + self._lambda(wo)))[:, None]
        return wo, np.where(up[:, None], weight, 0.0), pdf
