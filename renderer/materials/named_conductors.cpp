#include "materials/named_conductors.h"

namespace verity {

// Linear interpolation in wavelength between the two tabulated points on either side of
// 650, 550 and 450 nm. Au, Ag, Cu: P. B. Johnson and R. W. Christy, "Optical constants of
// the noble metals", Phys. Rev. B 6, 4370 (1972), room temperature, points at 617/660,
// 549/582 and 431/451 nm. Al: A. D. Rakić, "Algorithm for the determination of intrinsic
// optical constants of metal films: application to aluminum", Appl. Opt. 34, 4755 (1995),
// points at 620/652, 517/564 and 443/477 nm. (Both as tabulated by the refractiveindex.info
// database, main/Au/Johnson etc.) Their normal-incidence
// reflectances ((η−1)² + κ²)/((η+1)² + κ²), R G B: Au 0.957 0.792 0.408, Ag 0.990 0.983
// 0.980, Cu 0.935 0.624 0.538, Al 0.906 0.915 0.922.
const std::vector<NamedConductor>& namedConductors() {
  static const std::vector<NamedConductor> table = {
      {"Ag", "silver (Johnson and Christy 1972)", Color3(0.0522f, 0.0596f, 0.0400f),
       Color3(4.409f, 3.597f, 2.648f)},
      {"Al", "aluminium (Rakić 1995)", Color3(1.558f, 1.015f, 0.6332f),
       Color3(7.712f, 6.627f, 5.454f)},
      {"Au", "gold (Johnson and Christy 1972)", Color3(0.1556f, 0.4241f, 1.383f),
       Color3(3.602f, 2.472f, 1.915f)},
      {"Cu", "copper (Johnson and Christy 1972)", Color3(0.2378f, 1.007f, 1.240f),
       Color3(3.626f, 2.582f, 2.393f)},
  };
  return table;
}

const NamedConductor* findNamedConductor(const std::string& name) {
  for (const NamedConductor& c : namedConductors())
    if (name == c.name) return &c;
  return nullptr;
}

std::string namedConductorList() {
  std::string list;
  for (const NamedConductor& c : namedConductors())
    list += (list.empty() ? "" : ", ") + std::string(c.name);
  return list;
}

}  // namespace verity
