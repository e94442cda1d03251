"""check_stochastic_bsdf and the family's stochastic mode on a NumPy Lambertian whose eval and
sample weight are random, unbiased estimates (each multiplied by an independent factor of mean
1, as a random walk's estimate is): it passes, and the same BSDF whose sampled weights are 4%
too large fails on its total albedo.

Level: ALPHA = 1e-3 per check (each check is two tests, Holm over the cells and the total), as
test_bsdf.py's checks are. Power: 4% of an albedo of 0.8 is 0.032, while the sampled mean's
standard error is about 3e-4 (1e5-2e5 weights of spread 0.12) and the evaluated one's smaller:
some 100 standard errors, found with certainty."""
import numpy as np
import pytest
import verity

ALPHA = 1e-3
SAMPLES = 200_000


class NoisyLambertian:
    def __init__(self, albedo=0.8, bias=1.0, seed=7):
        self.albedo, self.bias = albedo, bias
        self.rng = np.random.default_rng(seed)

    def noise(self, n):
        return self.rng.uniform(0.75, 1.25, n)   # mean 1: an unbiased estimate

    def sample(self, wi, u):
        r, phi = np.sqrt(u[:, 1]), 2 * np.pi * u[:, 2]
        wo = np.stack([r * np.cos(phi), r * np.sin(phi), np.sqrt(1 - u[:, 1])], axis=1)
        weight = self.bias * self.albedo * self.noise(len(u))
        return wo, weight, wo[:, 2] / np.pi

    def eval(self, wi, wo):
        up = (wo[:, 2] > 0) & (np.broadcast_to(np.asarray(wi), wo.shape)[:, 2] > 0)
        return np.where(up, self.albedo / np.pi * self.noise(len(wo)), 0.0)


def test_a_noisy_but_unbiased_bsdf_passes_and_a_biased_one_fails():
    wi = (0.5, 0.0, np.sqrt(0.75))
    good = NoisyLambertian()
    r = verity.check_stochastic_bsdf(good.sample, good.eval, wi=wi, alpha=ALPHA, samples=SAMPLES,
                                     name="noisy lambertian")
    assert r.verdict == "PASSED", str(r)
    assert r.albedo[0]["sampled"] == pytest.approx(0.8, rel=0.01)
    assert r.albedo[0]["evaluated"] == pytest.approx(0.8, rel=0.01)
    biased = NoisyLambertian(bias=1.04)
    r = verity.check_stochastic_bsdf(biased.sample, biased.eval, wi=wi, alpha=ALPHA,
                                     samples=SAMPLES, name="noisy lambertian, weights 4% high")
    assert r.verdict == "FAILED" and "total albedo" in r.failures, str(r)


def test_a_family_in_the_stochastic_mode():
    def factory(albedo):
        b = NoisyLambertian(albedo=albedo)
        return b.sample, b.eval   # no pdf: the mean-weight check does not use one
    r = verity.check_bsdf_family(factory, {"albedo": (0.2, 0.9)}, alpha=ALPHA, stochastic=True,
                                 samples=SAMPLES // 2, incidences=[0, 60], interior_points=1)
    assert r.passed, str(r)
    results = [c["result"] for c in r.configurations]
    assert len(results) == 6 and all(isinstance(x, verity.StochasticResult) for x in results)
    with pytest.raises(TypeError, match="unknown keyword argument 'detect'"):
        verity.check_bsdf_family(factory, {"albedo": (0.2, 0.9)}, alpha=ALPHA, stochastic=True,
                                 detect=(0.02, 0.25))


def test_bad_keywords_are_refused_by_name():
    b = NoisyLambertian()
    with pytest.raises(ValueError, match="strata = 3: must be even"):
        verity.check_stochastic_bsdf(b.sample, b.eval, wi=(0, 0, 1), alpha=ALPHA, strata=3)
    with pytest.raises(TypeError, match="the keyword argument wi"):
        verity.check_stochastic_bsdf(b.sample, b.eval, alpha=ALPHA)
