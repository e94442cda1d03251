// A BSDF written in Python as the checks see it (bsdf_model.h): three callables, each called
// once per batch of N directions, never once per sample.
//   sample(wi, u) -> (wo, weight, pdf[, delta])   wi (3,), u (N, 3): u[:, 0] picks the lobe,
//                    u[:, 1:] the direction (BsdfUniforms' order); wo (N, 3), weight (N,) or
//                    (N, 3), pdf (N,) (0: no sample), delta (N,) of bool for delta lobes
//   eval(wi, wo) -> (N,) or (N, 3)   f without the cosine; wi is (3,), or (N, 3) row by row
//                    with wo for the reciprocity check's reversed evaluations
//   pdf(wi, wo)  -> (N,)             per unit solid angle
#pragma once

#include <verity/chi2/bsdf_model.h>

#include "callback.h"

namespace verity::python {

// `check` names the check in messages; the number of components is eval's at wi's mirror
// direction (one call).
chi2::BsdfModel pythonBsdf(py::object sample, py::object eval, py::object pdf,
                           const Eigen::Vector3d& wi, const std::string& check);

}  // namespace verity::python
