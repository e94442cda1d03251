"""check_bsdf_family on the example's NumPy GGX: a defect planted at one corner of the roughness
range is found there alone and listed first, bad parameters are refused by name, and the
family's level is split over its tests.

Level: the family's own, ALPHA = 1e-3 over its 12 statistical tests (Sidak), as test_bsdf.py's
checks are at 1e-3 each. These tests are about behaviour, not power: 10^5 samples on the grid
of cells; the planted error (the example's broken GGX) is found with chi-square p < 1e-30."""
import json
import subprocess
import sys
from pathlib import Path
from xml.etree import ElementTree

import pytest
import verity

from lobes import Ggx, Glass

ALPHA = 1e-3
FAST = dict(alpha=ALPHA, samples=100_000, cells="grid", incidences=[30, 60], interior_points=1)


def ggx_family(broken_above):
    def factory(alpha):
        g = Ggx(alpha, broken=alpha > broken_above)
        return g.sample, g.eval, g.pdf
    return factory


def test_a_defect_at_one_corner_is_found_there_and_listed_first():
    r = verity.check_bsdf_family(ggx_family(0.99), {"alpha": (0.1, 1.0, "log")}, **FAST)
    assert r.verdict == "FAILED" and not r.passed
    configurations = r.configurations
    assert len(configurations) == 6
    for c in configurations:
        assert c["result"].passed == (c["values"]["alpha"] < 0.99), str(c["result"])
    assert r.per_test_level == pytest.approx(1 - (1 - ALPHA) ** (1 / 12))
    report = str(r)
    assert report.index("FAILED       alpha=1 at 30°") < report.index("PASSED")
    data = json.loads(r.json())
    assert data["configurations"][0]["verdict"] == "FAILED"
    assert "chi-square" in data["configurations"][0]["failures"]
    assert r.markdown().index("| FAILED |") < r.markdown().index("| PASSED |")
    # JUnit for CI: one test case per configuration, the failed ones with a <failure>.
    suite = ElementTree.fromstring(r.junit("ggx family")).find("testsuite")
    assert suite.get("name") == "ggx family" and suite.get("tests") == "6"
    cases = {c.get("name"): c for c in suite.iter("testcase")}
    assert set(cases) == {c["name"] for c in configurations}
    for c in configurations:
        failure = cases[c["name"]].find("failure")
        assert (failure is None) == c["result"].passed
        if failure is not None:
            assert failure.get("type") == "FAILED" and "chi-square" in failure.get("message")
    assert suite.get("failures") == str(sum(not c["result"].passed for c in configurations))


def test_a_correct_family_passes():
    r = verity.check_bsdf_family(ggx_family(2.0), {"alpha": (0.1, 1.0, "log")}, **FAST)
    assert r.passed, str(r)


def test_bad_parameters_and_keywords_are_refused_by_name():
    with pytest.raises(ValueError, match="parameter alpha: a logarithmic range needs lo > 0"):
        verity.check_bsdf_family(ggx_family(2.0), {"alpha": (0.0, 1.0, "log")}, **FAST)
    with pytest.raises(ValueError, match=r"parameters\['alpha'\]"):
        verity.check_bsdf_family(ggx_family(2.0), {"alpha": (0.1, 1.0, "square")}, **FAST)
    with pytest.raises(TypeError, match="samples and detect exclude each other"):
        verity.check_bsdf_family(ggx_family(2.0), {"alpha": (0.1, 1.0)},
                                 **{**FAST, "detect": (0.02, 0.25)})
    with pytest.raises(TypeError, match="unknown keyword argument 'wi'"):
        verity.check_bsdf_family(ggx_family(2.0), {"alpha": (0.1, 1.0)}, **FAST, wi=(0, 0, 1))
    with pytest.raises(TypeError, match="the factory must return"):
        verity.check_bsdf_family(lambda alpha: None, {"alpha": (0.1, 1.0)}, **FAST)


def glass_family(stated_eta=None):
    """Smooth glass over its index, each configuration's expectations stated by the factory
    (for `stated_eta` at every configuration where given: a wrong statement)."""
    def factory(eta):
        g, s = Glass(eta), Glass(stated_eta or eta)
        return {"sample": g.sample, "eval": Glass.zero, "pdf": Glass.zero,
                "interior_index": eta, "expect": s.expect, "eta": eta}
    return factory


GLASS = dict(alpha=ALPHA, samples=100_000, incidences=[20, 60], from_below=True,
             interior_points=1)


def test_a_factory_states_each_configurations_expectations():
    # Each configuration: its two tests and four stated shares and albedos, one family.
    r = verity.check_bsdf_family(glass_family(), {"eta": (1.1, 2.0)}, **GLASS)
    assert r.passed, str(r)
    assert len(r.configurations) == 12
    assert r.per_test_level == pytest.approx(1 - (1 - ALPHA) ** (1 / (12 * 6)))
    # Stated for η 1.5 everywhere, the shares are wrong at the ends of the range: at 20° the
    # reflected share is 0.0024 at η 1.1 and 0.040 at 1.5, some 60 standard errors at 10^5
    # draws. From below at 60° both 2 and 1.5 reflect totally, and agree.
    wrong = verity.check_bsdf_family(glass_family(1.5), {"eta": (1.1, 2.0)}, **GLASS)
    for c in wrong.configurations:
        eta = c["values"]["eta"]
        if eta in (1.1, 2.0) and not (eta == 2.0 and c["below"] and c["incidence"] == 60):
            assert c["result"].verdict == "FAILED", str(c["result"])


def test_a_factorys_dict_is_read_by_name():
    def unknown(eta):
        return {"sample": Glass(eta).sample, "eval": Glass.zero, "pdf": Glass.zero, "colour": 1}
    with pytest.raises(TypeError, match="factory's dict: unknown keyword argument 'colour'"):
        verity.check_bsdf_family(unknown, {"eta": (1.1, 2.0)}, **GLASS)

    def raising(eta):
        return {"sample": Glass(eta).sample, "eval": Glass.zero, "pdf": Glass.zero,
                "expect": lambda wi: 1 / 0}
    with pytest.raises(RuntimeError, match=r"eta=1\.1 at 20° from above\): expect\(wi\) raised") as e:
        verity.check_bsdf_family(raising, {"eta": (1.1, 2.0)}, **GLASS)
    assert isinstance(e.value.__cause__, ZeroDivisionError)

    def no_pdf(eta):
        return {"sample": Glass(eta).sample, "eval": Glass.zero}
    with pytest.raises(TypeError, match="must return .* or a dict"):
        verity.check_bsdf_family(no_pdf, {"eta": (1.1, 2.0)}, **GLASS)


def test_a_failing_configurations_figure_is_drawn_from_python(tmp_path):
    r = verity.check_bsdf_family(ggx_family(0.99), {"alpha": (0.1, 1.0, "log")}, **FAST)
    failed = next(c for c in r.configurations if not c["result"].passed)
    data = json.loads(failed["result"].figure_json())
    assert data["verdict"] == "FAILED" and data["chi_square"]["passed"] is False
    assert sum(map(sum, data["observed"])) == data["valid"] - data["outside"]
    path = tmp_path / "alpha-1.json"
    failed["result"].write_figure_data(str(path))
    assert json.loads(path.read_text())["observed"] == data["observed"]
    # Drawn by the script installed beside the package (share/verity/plot_chi2.py).
    script = Path(__file__).resolve().parents[2] / "chi2" / "core" / "plot_chi2.py"
    subprocess.run([sys.executable, str(script), str(path), str(tmp_path / "alpha-1.png")],
                   check=True)
    assert (tmp_path / "alpha-1.png").stat().st_size > 10_000
    with pytest.raises(RuntimeError, match="no-such-folder"):
        failed["result"].write_figure_data(str(tmp_path / "no-such-folder" / "x.json"))
