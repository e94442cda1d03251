"""The batched quadrature's benchmark (docs/python.md): the Lambertian and GGX lobes written in
NumPy (python/tests/lobes.py, examples/python/ggx.py) checked by verity.check_bsdf, against
the same lobes written in C++ and checked through the C++ adapter point by point
(verity_python_bench), at the checks' defaults (10⁶ samples, wi at 50°) on either cell layout.
Not a test: it prints a table of times.

    cmake --build build --target verity_python verity_python_bench
    PYTHONPATH=build/python python3 python/bench/batched_quadrature.py build/bin/verity_python_bench
"""
import os
import subprocess
import sys
import time

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "tests"))
import verity  # noqa: E402
from lobes import Ggx, Lambert  # noqa: E402

WI = (np.sin(np.radians(50)), 0.0, np.cos(np.radians(50)))


def numpy_times(cells):
    times = {}
    for name, lobe in (("lambert", Lambert()), ("ggx", Ggx(0.3))):
        start = time.perf_counter()
        r = verity.check_bsdf(lobe.sample, lobe.eval, lobe.pdf, wi=WI, alpha=0.01,
                              name="bench " + name, cells=cells)
        times[name] = (time.perf_counter() - start, r.verdict)
    return times


def cpp_times(program, cells):
    out = subprocess.run([program, cells], check=True, capture_output=True, text=True).stdout
    return {name: (float(seconds), verdict)
            for name, seconds, verdict in (line.split() for line in out.splitlines())}


def main():
    program = sys.argv[1]
    print(f"{'cells':6} {'lobe':8} {'NumPy (s)':>10} {'C++ (s)':>8} {'ratio':>6}  verdicts")
    for cells in ("equal", "grid"):
        py, cpp = numpy_times(cells), cpp_times(program, cells)
        for lobe in ("lambert", "ggx"):
            print(f"{cells:6} {lobe:8} {py[lobe][0]:10.2f} {cpp[lobe][0]:8.2f} "
                  f"{py[lobe][0] / cpp[lobe][0]:6.2f}  {py[lobe][1]} / {cpp[lobe][1]}")


if __name__ == "__main__":
    main()
