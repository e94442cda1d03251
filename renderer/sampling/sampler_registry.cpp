#include "sampling/sampler_registry.h"

#include "sampling/halton_sampler.h"
#include "sampling/independent_sampler.h"
#include "sampling/sobol_sampler.h"
#include "sampling/stratified_sampler.h"

namespace verity {

// An explicit list rather than self-registering static objects: verity_renderer is a static
// library, and the linker drops an object file that nothing references, together with the
// registrar it holds. A function-local table is built on first use, in a fixed order. A new
// type adds its entry function here.
const Registry<SamplerType>& samplerTypes() {
  static const Registry<SamplerType> types("sampler type", {
                                                               independentSamplerType(),
                                                               stratifiedSamplerType(),
                                                               haltonSamplerType(),
                                                               sobolSamplerType(),
                                                           });
  return types;
}

}  // namespace verity
