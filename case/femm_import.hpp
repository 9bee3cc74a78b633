#pragma once
// Import of FEMM 4.2 magnetostatic models (.fem text files, planar or axisymmetric) into a
// Problem: points, segments, arc segments, holes, block labels, materials with B-H points,
// circuits and boundary properties, scaled from the file's length units to metres.

#include <filesystem>
#include <string>
#include <string_view>

#include "case/problem.hpp"

namespace rheomag::cases {

/// Parses .fem text (`source` names it in messages). The problem's outer boundary is
/// OuterBoundary::none: a .fem contains its own boundary. InputError "file:line: ..." on
/// malformed, truncated or unsupported content.
Problem parse_femm(std::string_view text, const std::string& source);

/// Reads and parses a .fem file.
Problem read_femm_file(const std::filesystem::path& path);

/// FEMM block-label mesh size d (the file's column) -> our target element edge length: FEMM
/// limits triangle areas to pi d^2 / 4; an equilateral triangle of that area has edge
/// sqrt(4 A / sqrt 3) = d sqrt(pi / sqrt 3) ~ 1.347 d.
double femm_mesh_size_to_edge(double femm_size);

}  // namespace rheomag::cases
