"""check_bsdf on NumPy lobes: correct ones pass, planted errors fail with the check named, and
the callables are called once per batch, never once per sample.

Level: each check that must pass runs two statistical tests at ALPHA = 1e-3 each; with the
checks of test_warp.py and test_options.py, fewer than 20 such checks run, a family-wise
level under 4% (Bonferroni). Seeds are fixed: each check's name seeds it (seedFromName).
These tests are about behaviour, not power, so they draw 10⁵ samples (2·10⁴ where only the
plumbing matters) on the grid of cells, cheaper to integrate than equal-probability cells;
each planted error is found by a wide margin at that count (the broken GGX: chi-square
p < 1e-30)."""
import os
import threading

import numpy as np
import pytest
import verity

from lobes import Counted, Ggx, Lambert

ALPHA = 1e-3
WI = (0.5, 0.0, np.sqrt(0.75))
FAST = dict(alpha=ALPHA, samples=100_000, cells="grid")


def check(lobe, name, **options):
    return verity.check_bsdf(lobe.sample, lobe.eval, lobe.pdf, wi=WI, name=name,
                             **{**FAST, **options})


def test_the_module_is_the_installed_one():
    prefix = os.environ.get("VERITY_EXPECTED_PREFIX")
    if prefix is None:
        pytest.skip("not run by CTest against an installed prefix")
    assert os.path.realpath(verity.__file__).startswith(os.path.realpath(prefix))


def test_lambert_passes_with_each_check_and_its_statistic():
    r = check(Lambert(), "py lambert")
    assert r.verdict == "PASSED" and r.passed, str(r)
    assert r.failures == []
    assert r.chi_square["ran"] and r.chi_square["dof"] > 100
    assert r.chi_square["p_value"] >= ALPHA
    assert r.pdf_integral["passed"] and abs(r.pdf_integral["integral"] - 1) < 1e-4
    assert r.defects == {}
    assert r.samples == 100_000 and r.valid == 100_000
    assert str(r) == r.report and "PASSED" in str(r) and "chi-square" in str(r)


def test_ggx_with_visible_normals_passes_in_rgb():
    r = check(Ggx(0.3), "py ggx")
    assert r.passed, str(r)


def test_ggx_with_a_subtle_pdf_error_fails_on_the_histogram():
    r = check(Ggx(0.3, broken=True), "py ggx broken")
    assert r.verdict == "FAILED", str(r)
    assert "chi-square" in r.failures
    assert r.chi_square["p_value"] < 1e-10
    # Its weight and sample pdf are consistent: only the shape is wrong.
    assert r.defects == {}


def test_a_weight_error_is_reported_with_its_first_example():
    r = check(Lambert(scale_weight=1.01), "py lambert weight")
    assert r.verdict == "FAILED"
    defect = r.defects["weight != eval*cos/pdf"]
    assert defect["count"] == r.valid
    assert "ratio 1.01" in defect["first_example"] and "wo=" in defect["first_example"]
    # A Lambertian lobe does not depend on where rounding moves wo: the error is beyond it.
    assert defect["classified"] > 0
    assert defect["beyond_rounding"] == defect["classified"]


def test_a_pdf_that_disagrees_with_the_sample_pdf_is_reported():
    r = check(Lambert(scale_pdf=1.001), "py lambert pdf")
    assert r.verdict == "FAILED"
    assert "sample pdf != pdf()" in r.defects


def test_float32_arrays_are_accepted():
    lobe = Lambert()

    def sample(wi, u):
        wo, weight, pdf = lobe.sample(wi, u.astype(np.float32))
        return wo.astype(np.float32), weight.astype(np.float32), pdf.astype(np.float32)

    r = verity.check_bsdf(sample, lambda wi, wo: lobe.eval(wi, wo).astype(np.float32),
                          lambda wi, wo: lobe.pdf(wi, wo).astype(np.float32), wi=WI,
                          name="py lambert float32", weight_tolerance=1e-3, **FAST)
    assert r.passed, str(r)


def test_each_callable_is_called_once_per_batch():
    lobe = Lambert()
    sample, eval_, pdf = Counted(lobe.sample), Counted(lobe.eval), Counted(lobe.pdf)
    r = verity.check_bsdf(sample, eval_, pdf, wi=WI, name="py lambert batches", **FAST)
    assert r.passed, str(r)
    # 10⁵ samples are two chunks of 2¹⁶; eval: the component probe, two chunks both ways, the
    # cell centres; pdf: two chunks, then the quadrature's batches of DENSITY_BATCH_POINTS and
    # a call per refinement level of its last cells.
    assert sample.calls == 2 and sample.points == 100_000
    assert eval_.calls == 6
    assert pdf.points > 2048 * 225
    assert pdf.calls <= pdf.points // verity.DENSITY_BATCH_POINTS + 40


def test_delta_lobes_are_counted_and_checked_apart():
    def mirror(wi, u):
        wo = np.tile([-wi[0], -wi[1], wi[2]], (len(u), 1))
        return wo, np.full(len(u), 0.9), np.ones(len(u)), np.ones(len(u), dtype=bool)

    zero = lambda wi, wo: np.zeros(len(wo))  # noqa: E731
    r = verity.check_bsdf(mirror, zero, zero, wi=WI, name="py mirror", alpha=ALPHA,
                          samples=20_000, expect={"reflection": (1.0, [0.9])})
    assert r.verdict == "PASSED", str(r)
    assert r.delta_samples == 20_000 and r.valid == 0
    def bent(wi, u):  # a unit vector, 0.01 from the mirror direction
        wo, *rest = mirror(wi, u)
        wo = wo + [0.01, 0, 0]
        return (wo / np.linalg.norm(wo, axis=1, keepdims=True), *rest)

    r = verity.check_bsdf(bent, zero, zero, wi=WI, name="py mirror bent", alpha=ALPHA,
                          samples=20_000)
    assert r.verdict == "FAILED" and "delta direction" in r.failures, str(r)


def test_one_thread_calls_every_callable_on_the_calling_thread():
    lobe, caller, elsewhere = Lambert(), threading.get_ident(), []

    def noted(function):
        def call(*args):
            if threading.get_ident() != caller:
                elsewhere.append(function.__name__)
            return function(*args)
        return call

    kw = dict(wi=WI, name="py lambert threads", **FAST)
    one = verity.check_bsdf(noted(lobe.sample), noted(lobe.eval), noted(lobe.pdf), threads=1, **kw)
    assert one.passed, str(one)
    assert not elsewhere
    # The same result on every core, where the callables may be called from other threads.
    every = verity.check_bsdf(noted(lobe.sample), noted(lobe.eval), noted(lobe.pdf), **kw)
    assert every.chi_square == one.chi_square and every.pdf_integral == one.pdf_integral
    if len(os.sched_getaffinity(0)) > 1:  # the cores the check's threads may use
        assert elsewhere  # the test above can fail
    with pytest.raises(ValueError, match="threads = -1: must be 0"):
        verity.check_bsdf(lobe.sample, lobe.eval, lobe.pdf, threads=-1, **kw)
