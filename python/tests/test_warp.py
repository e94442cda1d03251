"""check_warp on the five domains: NumPy warps pass, a disk sampled with r = u instead of √u
fails. Level and seeds as in test_bsdf.py; 10⁵ samples on the grid each."""
import numpy as np
import pytest
import verity

from lobes import WARPS, polar_disk

ALPHA = 1e-3


@pytest.mark.parametrize("domain", sorted(WARPS))
def test_a_correct_warp_passes(domain):
    sample, pdf = WARPS[domain]
    r = verity.check_warp(domain, sample, pdf, name=f"py {domain}", alpha=ALPHA, samples=100_000,
                          cells="grid")
    assert r.passed, str(r)


def test_a_disk_with_a_wrong_radius_fails():
    r = verity.check_warp("disk", lambda u: polar_disk(u, broken=True), WARPS["disk"][1],
                          name="py disk broken", alpha=ALPHA, samples=100_000, cells="grid")
    assert r.verdict == "FAILED" and "chi-square" in r.failures, str(r)


def test_a_rejection_sampler_declines_with_nan_rows():
    def rejection(u):
        p = 2 * u - 1
        return np.where((np.sum(p * p, axis=1) <= 1)[:, None], p, np.nan)

    r = verity.check_warp("disk", rejection, lambda p: np.full(len(p), 1 / 4), name="py rejection",
                          alpha=ALPHA, samples=100_000, cells="grid")
    assert r.passed, str(r)
    assert abs(r.valid / r.samples - np.pi / 4) < 0.01


def test_an_unknown_domain_is_named():
    with pytest.raises(ValueError, match="domain 'ball'"):
        verity.check_warp("ball", *WARPS["sphere"], alpha=ALPHA)
