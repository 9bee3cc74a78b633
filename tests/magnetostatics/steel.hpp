#pragma once
// Test helper: the AISI 1010 material of the bundled materials library (cases/materials).

#include "case/material_library.hpp"
#include "case/problem.hpp"

namespace rheomag::test {

/// AISI 1010 steel with its B-H table (DoSA-2D curve, see cases/materials/aisi1010.toml).
inline cases::Material aisi1010() {
  return cases::MaterialLibrary::standard().get("AISI 1010", "test").magnetic;
}

}  // namespace rheomag::test
