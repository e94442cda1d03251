"""The module of a checks-only build (VERITY_CHECKS_ONLY: no renderer, no image comparison), as
package_checks_only installs it (cmake/TestInstalledPackage.cmake): it must load from the
installed prefix, run a check, and say that verity.compare is not in it. Run as a program,
not by pytest, whose suite (the other files here) needs the full module. One warp check that
must pass: two statistical tests at ALPHA = 1e-3, a false failure rate under 0.2%; its seed is
its name's. 10⁵ samples on the grid, as test_warp.py."""
import os

import numpy as np
import verity

from lobes import WARPS

ALPHA = 1e-3

prefix = os.path.realpath(os.environ["VERITY_EXPECTED_PREFIX"])
assert os.path.realpath(verity.__file__).startswith(prefix), (verity.__file__, prefix)

r = verity.check_warp("square", *WARPS["square"], name="py checks-only square", alpha=ALPHA,
                      samples=100_000, cells="grid")
assert r.passed, str(r)

renders = np.zeros((2, 16, 16, 3))
try:
    verity.compare(renders, renders)
except NotImplementedError as e:
    assert "VERITY_CHECKS_ONLY" in str(e), str(e)
else:
    raise AssertionError("verity.compare ran in a module built without the image comparison")
print("checks-only module: imported from", prefix, "- check_warp passed, compare not built")
