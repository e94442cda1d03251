"""Errors reach the caller as Python exceptions naming the check and the callable, with the
expected and received shapes; a callable's own exception is chained with its traceback;
Ctrl-C interrupts a long check. Small sample counts: only the plumbing matters here."""
import _thread
import threading
import traceback

import numpy as np
import pytest
import verity

from lobes import Lambert

WI = (0.0, 0.0, 1.0)
FAST = dict(alpha=0.01, samples=2_000, cells="grid", name="err")


def run(sample=None, eval_=None, pdf=None, **options):
    lobe = Lambert()
    return verity.check_bsdf(sample or lobe.sample, eval_ or lobe.eval, pdf or lobe.pdf, wi=WI,
                             **{**FAST, **options})


def test_a_callable_that_raises_is_chained_with_its_traceback():
    def pdf(wi, wo):
        return 1 / 0

    with pytest.raises(RuntimeError, match=r"check_bsdf 'err': pdf\(wi, wo\) raised") as e:
        run(pdf=pdf)
    assert isinstance(e.value.__cause__, ZeroDivisionError)
    frames = traceback.extract_tb(e.value.__cause__.__traceback__)
    assert any(f.name == "pdf" for f in frames)


def test_a_wrong_shape_names_the_callable_and_both_shapes():
    with pytest.raises(ValueError, match=r"pdf\(wi, wo\) returned its value of shape \(\d+, 1\), "
                                         r"expected \(\d+,\)"):
        run(pdf=lambda wi, wo: Lambert().pdf(wi, wo)[:, None])


def test_a_wrong_count_names_the_callable():
    def sample(wi, u):
        wo, weight, pdf = Lambert().sample(wi, u)
        return wo[1:], weight, pdf

    with pytest.raises(ValueError, match=r"sample\(wi, u\) returned wo of shape \(1999, 3\), "
                                         r"expected \(2000, 3\)"):
        run(sample=sample)


def test_a_wrong_dtype_is_a_type_error():
    with pytest.raises(TypeError, match=r"eval\(wi, wo\) returned its value of dtype <U1"):
        run(eval_=lambda wi, wo: np.full(len(wo), "x"))


def test_a_sample_that_is_no_tuple_is_a_type_error():
    with pytest.raises(TypeError, match=r"sample\(wi, u\) returned .*expected a tuple"):
        run(sample=lambda wi, u: u)


def test_nan_in_an_output_is_a_value_error():
    with pytest.raises(ValueError, match=r"pdf\(wi, wo\) returned NaN"):
        run(pdf=lambda wi, wo: np.full(len(wo), np.nan))


def test_options_are_checked_by_name():
    with pytest.raises(TypeError, match="alpha"):
        verity.check_bsdf(*[lambda *a: None] * 3, wi=WI)
    with pytest.raises(ValueError, match="alpha = 2"):
        run(alpha=2)
    with pytest.raises(TypeError, match="unknown keyword argument 'sample_count'"):
        run(sample_count=5)
    with pytest.raises(ValueError, match="cells"):
        run(cells="hexagons")
    with pytest.raises(ValueError, match="weightTolerance"):
        run(weight_tolerance=2)
    with pytest.raises(ValueError, match="directionRounding"):
        run(direction_rounding=-1)
    with pytest.raises(TypeError, match="samples"):
        run(samples="many")


def test_ctrl_c_interrupts_a_long_check():
    lobe = Lambert()
    timer = threading.Timer(0.5, _thread.interrupt_main)
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            verity.check_bsdf(lobe.sample, lobe.eval, lobe.pdf, wi=WI, alpha=0.01,
                              samples=10**9, cells="grid", name="interrupted")
    finally:
        timer.cancel()
