// The uniform random numbers an adapter hands to the sampling routine under test. They are
// multiples of 2⁻²⁴ in [0, 1) (uniform01 in subject.h), so that a routine in single
// precision sees exactly the numbers a routine in double precision sees.
#pragma once

#include <verity/chi2/vector_access.h>

#include <type_traits>

namespace verity::chi2 {

// Two uniforms, for a warp of the unit square. Converts implicitly to the caller's own 2D
// point type, so that a routine taking `const Point2&` accepts it as it is.
struct Uniform2 {
  double x = 0, y = 0;

  double operator[](int i) const { return i == 0 ? x : y; }
  template <class P, class = std::enable_if_t<!std::is_arithmetic_v<P>>>
  operator P() const {
    return makeVector2<P>(x, y);
  }
};

// What a BSDF's sample() receives: `lobe` chooses among its lobes (a component, reflection
// against transmission), `xy` samples the direction within the chosen lobe. Drawn from the
// generator in the order lobe, xy.x, xy.y.
struct BsdfUniforms {
  double lobe = 0;
  Uniform2 xy;
};

}  // namespace verity::chi2
