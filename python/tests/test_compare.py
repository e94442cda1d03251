"""verity.compare: two sets of renders as arrays, decided as `verity compare -a ... -b ...`
decides on the same renders written as EXR files. Each side is 8 renders of 32x32 pixels in
16x16 tiles: 4 tiles x 3 channels = 12 Welch tests, Holm at family-wise level alpha = 1%, so
a correct pair is called DIFFER with probability at most 1%. Pixels are 0.5 plus Gaussian
noise of sd 0.1: a tile's mean per render has sd 0.1/16 = 1.25% of it, and a 5% bias in one
tile is detected with power above 99.9% (t near 8 against a Bonferroni critical value near
4.5 at df 14; each test asserts the tile's detectable bias at 90% power is below 5%). The
equivalence test (two one-sided tests per tile at 1%) within 5% passes with probability
above 99.9% for equal sides, and within 1% can never pass at this noise. Seeds are fixed,
from each test's name. The same renders written as EXR files (by OpenImageIO, not by Verity)
are given to verity.compare by name too, and must give the very decision."""
import json
import os
import pathlib
import re
import subprocess
import zlib

import numpy as np
import pytest
import verity

try:
    import OpenImageIO as oiio
except ImportError as e:  # a failure, never a skip: CTest would report a pass
    raise ImportError("test_compare.py writes its EXR files with OpenImageIO: install Debian's "
                      "python3-openimageio (scripts/bootstrap does)") from e

SIZE, RENDERS = 32, 8


def renders(name, count=RENDERS, bias_tile=None, bias=0.0):
    rng = np.random.default_rng(zlib.crc32(name.encode()))
    sets = 0.5 + 0.1 * rng.standard_normal((count, SIZE, SIZE, 3))
    if bias_tile is not None:
        x, y = bias_tile
        sets[:, 16 * y:16 * (y + 1), 16 * x:16 * (x + 1), :] *= 1 + bias
    return sets


def write_exr(path, image):
    """Writes an (H, W, 3) array as 32-bit float R, G and B."""
    buf = oiio.ImageBuf(np.ascontiguousarray(image, dtype=np.float32))
    if not buf.write(str(path)):
        raise OSError(f"{path}: {buf.geterror()}")


def written(tmp_path, side, images):
    """The renders as EXR files side0.exr, side1.exr, ... in tmp_path; their names."""
    files = [str(tmp_path / f"{side}{i}.exr") for i in range(len(images))]
    for path, image in zip(files, images):
        write_exr(path, image)
    return files


def test_sets_of_the_same_image_agree():
    r = verity.compare(list(renders("agree a")), tuple(renders("agree b")))
    assert r.verdict == "AGREE" and not r.differ, str(r)
    assert len(r.tests) == 12 and not r.rejected
    assert r.equivalence is None and "verdict: AGREE" in str(r)


def test_a_5_percent_bias_in_one_tile_differs_and_names_that_tile():
    a = renders("bias a").astype(np.float32)  # one (N, H, W, 3) array
    b = renders("bias b", bias_tile=(1, 0), bias=0.05).astype(np.float32)
    r = verity.compare(a, b, tile=16, alpha=0.01)
    assert r.verdict == "DIFFER", str(r)
    assert {(t.tile_x, t.tile_y) for t in r.rejected} == {(1, 0)}
    biased = [t for t in r.tests if (t.tile_x, t.tile_y) == (1, 0)]
    assert all(t.detectable_bias < 0.05 and t.relative_difference > 0 for t in biased)
    assert 0 < r.detectable_bias < 0.05 and r.power == 0.9
    assert "rejected tiles (x,y channels): (1,0 RGB)" in str(r)


def test_a_margin_says_equivalent_or_not_shown():
    a, b = renders("margin a"), renders("margin b")
    wide = verity.compare(a, b, margin=0.05)
    assert wide.verdict == "EQUIVALENT", str(wide)
    assert wide.equivalence["verdict"] == "EQUIVALENT" and wide.claimable_margin < 0.05
    assert all(t["equivalent"] for t in wide.equivalence["tests"])
    narrow = verity.compare(a, b, margin=0.01)
    assert narrow.verdict == "EQUIVALENCE NOT SHOWN", str(narrow)
    assert narrow.equivalence["verdict"] == "not shown"
    assert "equivalence not shown" in str(narrow)


@pytest.mark.parametrize("margin", [None, 0.05])
def test_the_decision_is_the_commands_on_the_same_renders_as_exr(tmp_path, margin):
    command = os.environ.get("VERITY_EXECUTABLE")
    if not command:
        pytest.skip("VERITY_EXECUTABLE (the verity command) is set only by CTest's python_tests")
    a = renders("command a").astype(np.float32)
    b = renders("command b", bias_tile=(0, 1), bias=0.03).astype(np.float32)
    b[2, 5, 7, 1] = np.nan  # left out of both sides, as the command does
    files = {side: written(tmp_path, side, images) for side, images in (("a", a), ("b", b))}
    out = tmp_path / "compare.json"
    args = [command, "compare", "-a", *files["a"], "-b", *files["b"], "-o", str(out)]
    if margin:
        args += ["--margin", str(margin)]
    run = subprocess.run(args, capture_output=True, text=True)
    mine = verity.compare(a, b, margin=margin)
    assert run.returncode == {"AGREE": 0, "EQUIVALENT": 0, "DIFFER": 1,
                              "EQUIVALENCE NOT SHOWN": 3}[mine.verdict], run.stderr
    theirs, ours = json.loads(out.read_text()), mine.to_dict()
    # The same files by name: the command's JSON and summary whole, file names included.
    named = verity.compare(files["a"], [pathlib.Path(f) for f in files["b"]], margin=margin)
    assert named.to_dict() == theirs
    assert run.stdout.startswith(str(named)), (run.stdout, str(named))
    for key in ("a", "b", "side_a", "side_b"):  # file names against a[0], ...
        theirs.pop(key), ours.pop(key)
    assert ours == theirs
    assert mine.to_dict()["side_b"]["nonfinite_pixels"] == [0, 0, 1, 0, 0, 0, 0, 0]


def test_file_names_decide_as_the_same_arrays(tmp_path):
    a = renders("names a").astype(np.float32)
    b = renders("names b", bias_tile=(1, 1), bias=0.05).astype(np.float32)
    b[4, 20, 3, 0] = np.inf
    names_a, names_b = written(tmp_path, "a", a), written(tmp_path, "b", b)
    arrays = verity.compare(a, b, margin=0.05).to_dict()
    assert arrays["differ"] and arrays["side_b"]["nonfinite_pixels"][4] == 1

    def labels_apart(decision):
        sides = {key: dict(decision.pop(key)) for key in ("side_a", "side_b")}
        files = [side.pop("files") for side in sides.values()]
        decision.pop("a"), decision.pop("b")
        return decision, sides, files

    common, sides, files = labels_apart(arrays)
    for given, names in (((names_a, names_b), (names_a, names_b)),
                         ((a, names_b), (files[0], names_b)),
                         ((names_a, list(b)), (names_a, files[1]))):
        assert labels_apart(verity.compare(*given, margin=0.05).to_dict()) == (
            common, sides, list(names))


@pytest.mark.parametrize("a, b, message", [
    ([np.zeros((32, 32))] * 2, None, r"a\[0\] has shape \(32, 32\); each render must be \(H, W, 3\)"),
    (None, [np.zeros((16, 32, 3)), np.zeros((16, 32, 3))],
     r"b\[0\] has shape \(16, 32, 3\), while a\[0\] has \(32, 32, 3\)"),
    (None, [np.ones((32, 32, 3)), np.zeros((32, 16, 3))],
     r"b\[1\] has shape \(32, 16, 3\), while b\[0\] has \(32, 32, 3\)"),
    ([np.zeros((32, 32, 3))], None, r"a has 1 render\(s\); a set needs at least 2"),
    (np.zeros((32, 32, 3)), None, r"a has shape \(32, 32, 3\); give a sequence"),
    ([np.zeros((32, 32, 3), dtype=np.int32)] * 2, None, r"a\[0\] must be a float32 or float64"),
])
def test_bad_shapes_raise_value_error_with_the_shapes(a, b, message):
    good = renders("shapes")
    with pytest.raises(ValueError, match=message) as e:
        verity.compare(good if a is None else a, good if b is None else b)
    assert str(e.value).count("verity.compare") == 1, str(e.value)


def test_a_side_that_is_not_a_sequence_is_a_type_error():
    with pytest.raises(TypeError, match="b must be a sequence of"):
        verity.compare(renders("type"), 3.0)


def test_bad_options_raise_value_error_naming_them():
    a, b = renders("options a"), renders("options b")
    with pytest.raises(ValueError, match="--alpha"):
        verity.compare(a, b, alpha=0.6, margin=0.05)
    with pytest.raises(ValueError, match="--tile"):
        verity.compare(a, b, tile=0)


def test_a_file_that_cannot_be_read_raises_value_error_naming_it(tmp_path):
    files = written(tmp_path, "a", renders("missing"))
    missing = str(tmp_path / "missing.exr")
    with pytest.raises(ValueError, match=re.escape(f"verity.compare: {missing}: no such file")):
        verity.compare(files, files[:2] + [missing])
    garbage = tmp_path / "garbage.exr"
    garbage.write_text("not an image")
    with pytest.raises(ValueError, match=re.escape(f"{garbage}: cannot read OpenEXR image")):
        verity.compare([garbage, *files[1:]], renders("missing b"))


def test_a_side_mixing_file_names_and_arrays_is_a_type_error(tmp_path):
    images = renders("mixed")
    files = written(tmp_path, "a", images[:2])
    with pytest.raises(TypeError, match=r"b mixes file names and arrays \(b\[1\] is a file "
                                        r"name, b\[0\] of type ndarray\)"):
        verity.compare(images, [images[0], files[1]])
    with pytest.raises(TypeError, match="a is one file name"):
        verity.compare(files[0], images)
