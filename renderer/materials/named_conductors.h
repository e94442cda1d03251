// Complex refractive indices η + iκ of a few metals, by name, for the rough conductors'
// "conductor" key: {"type": "ggx", "conductor": "Au"} (the role of Mitsuba 3's `material`
// parameter of roughconductor and of pbrt-v4's named spectra "metal-Au-eta"/"metal-Au-k").
// Names are chemical symbols, case-sensitive. Each RGB channel holds the measured index at
// one wavelength: R 650 nm, G 550 nm, B 450 nm (sources in named_conductors.cpp).
#pragma once

#include <string>
#include <vector>

#include "core/math.h"

namespace verity {

struct NamedConductor {
  const char* name;
  const char* description;
  Color3 eta, k;
};

const std::vector<NamedConductor>& namedConductors();
// Null when no conductor has this name.
const NamedConductor* findNamedConductor(const std::string& name);
// "Ag, Al, Au, Cu": the known names, for error messages.
std::string namedConductorList();

}  // namespace verity
