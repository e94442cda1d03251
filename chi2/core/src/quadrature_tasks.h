// The quadrature's computations (quadrature.cpp), for the partition's (partition.cpp) to await:
// the same integrals as integrateRectangle and integrateCell, given a Density (density.h). The
// bounds and options are taken by value: a computation may start after its caller's temporaries.
#pragma once

#include <verity/chi2/quadrature.h>

#include "density.h"

namespace verity::chi2 {

Task<CellIntegral> rectangleIntegral(Density& f, const DensityFeatures& features,
                                     const Domain& domain, CellBounds rectangle,
                                     QuadratureOptions options);
Task<CellIntegral> cellIntegral(Density& f, const DensityFeatures& features, const Domain& domain,
                                int cell, QuadratureOptions options);

}  // namespace verity::chi2
