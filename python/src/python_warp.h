// A warp written in Python as the checks see it (warp_model.h), each callable called once
// per batch of N points:
//   sample(u) -> points     u (N, 2) in [0, 1); points (N, 2) on the square, disk and
//                           triangle (barycentric b0, b1), (N, 3) unit vectors on the
//                           hemisphere and sphere; a row of NaN declines (a rejection miss)
//   pdf(points) -> (N,)     per unit area, or per unit solid angle
#pragma once

#include <verity/chi2/warp_model.h>

#include "callback.h"

namespace verity::python {

// The domain named "square", "disk", "triangle", "hemisphere" or "sphere"; ValueError else.
chi2::WarpDomain warpDomain(const std::string& name);

chi2::WarpModel pythonWarp(chi2::WarpDomain domain, py::object sample, py::object pdf,
                           const std::string& check);

}  // namespace verity::python
