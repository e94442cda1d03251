"""Every option of the C++ checks is a keyword: the seed and name make a check reproducible,
a detection target chooses the sample count, and a budget too small for it is INCONCLUSIVE.
Level and seeds as in test_bsdf.py."""
import numpy as np
import pytest
import verity

from lobes import Lambert

WI = (0.3, 0.2, 0.9)


def check(**options):
    lobe = Lambert()
    return verity.check_bsdf(lobe.sample, lobe.eval, lobe.pdf, wi=WI,
                             **{"alpha": 1e-3, "cells": "grid", **options})


def test_a_seed_reproduces_the_statistic_and_another_changes_it():
    a = check(name="py seed", samples=20_000, seed=7)
    b = check(name="py seed", samples=20_000, seed=7)
    c = check(name="py seed", samples=20_000, seed=8)
    assert a.chi_square["statistic"] == b.chi_square["statistic"]
    assert a.chi_square["statistic"] != c.chi_square["statistic"]


def test_a_detection_target_chooses_the_samples():
    r = check(name="py detect", detect=(0.05, 0.25))
    assert r.passed, str(r)
    assert 10_000 < r.samples < 1_000_000
    assert "5% density error over cells holding 1/4 of the mass" in str(r)


def test_a_budget_too_small_for_the_target_is_inconclusive():
    r = check(name="py budget", detect=(0.01, 0.25), max_samples=1_000)
    assert r.verdict == "INCONCLUSIVE", str(r)
    assert "more than the budget" in r.inconclusive_reason


def test_a_subsample_of_the_comparisons_is_stated():
    r = check(name="py audited", samples=200_000, audited_samples=1)
    assert r.passed, str(r)
    assert r.compared_samples["samples"] == 65_536  # one whole stream
    assert r.compared_samples["reach"] == pytest.approx(1 - 0.1 ** (1 / 65_536), rel=1e-9)
    assert "the first 65536 of the 200000 samples" in str(r)
    assert check(name="py audited", samples=200_000).compared_samples["samples"] == 200_000
    with pytest.raises(ValueError, match="audited_samples = 0"):
        check(name="py audited", audited_samples=0)


def test_equal_probability_cells_and_a_resolution():
    r = check(name="py equal", samples=100_000, cells="equal", resolution=8)
    assert r.passed, str(r)
    assert r.chi_square["cells"] == 8 * 16


def test_indices_of_refraction_scale_the_reciprocity_check():
    # A diffuse transmitter with the same f both ways is reciprocal only between equal
    # indices: across 1 | 1.5, eval(wi, wo)·ηo² and eval(wo, wi)·ηi² differ by 2.25.
    def sample(wi, u):
        wo, weight, pdf = Lambert().sample(wi, u)
        return wo * [1, 1, -1], weight, pdf

    def eval_(wi, wo):
        wi = np.broadcast_to(wi, wo.shape)
        return np.where(wi[..., 2] * wo[..., 2] < 0, 0.8 / np.pi, 0.0)

    def pdf(wi, wo):
        return np.where(wo[..., 2] < 0, -wo[..., 2] / np.pi, 0.0)

    def run(**indices):
        return verity.check_bsdf(sample, eval_, pdf, wi=WI, name="py transmitter", alpha=1e-3,
                                 cells="grid", samples=20_000, **indices)

    assert run().passed
    r = run(exterior_index=1.0, interior_index=1.5)
    assert r.verdict == "FAILED" and "reciprocity" in r.failures, str(r)
    with pytest.raises(ValueError, match="interior_index = -1"):
        run(interior_index=-1)
