#pragma once
// Which enclosed area of a PSLG each region seed lies in, without meshing it.

#include <vector>

#include "mesh/pslg.hpp"

namespace rheomag::mesh {

/// The enclosed area (a face of the PSLG bounded by its segments) each of `pslg.regions` lies
/// in: seeds with the same number share an area, -1 marks a seed outside every closed boundary.
/// Unlike meshing, several seeds in one area are not an error here. Throws InputError for a PSLG
/// that cannot be triangulated (see prepare_pslg).
std::vector<int> seed_areas(const Pslg& pslg);

}  // namespace rheomag::mesh
