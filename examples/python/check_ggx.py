"""Checks the NumPy GGX of ggx.py with Verity's checks at the sweep's settings (10⁶ samples on
the grid of cells: cells="equal", the checks' default, costs about 20 s more per check from
NumPy, docs/python.md), once as written and once with its subtle pdf error, and exits 0 only
when the first passes and the second fails. Level: two checks of two statistical tests
each, at 0.01/4 per test (Bonferroni, 1% family-wise).

    PYTHONPATH=<prefix>/lib/python3/dist-packages python3 examples/python/check_ggx.py
"""
import sys

import numpy as np
import verity

from ggx import Ggx

ALPHA = 0.01 / 4
wi = (np.sin(np.radians(50)), 0.0, np.cos(np.radians(50)))

results = {}
for broken in (False, True):
    ggx = Ggx(alpha=0.3, broken=broken)
    name = "numpy ggx" + (" broken" if broken else "")
    results[broken] = verity.check_bsdf(ggx.sample, ggx.eval, ggx.pdf, wi=wi, alpha=ALPHA,
                                        name=name, cells="grid")
    print(results[broken], end="\n\n")

ok = results[False].passed and results[True].verdict == "FAILED"
print("example:", "the GGX passed and its broken variant failed" if ok else "UNEXPECTED verdicts")
sys.exit(0 if ok else 1)
