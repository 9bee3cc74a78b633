#pragma once
// FEMM's rule for an area that holds a <No Mesh> label and other labels: it is not meshed.

#include "case/problem.hpp"

namespace rheomag::cases {

/// FEMM's mesher removes the areas of its holes (<No Mesh> labels, [NumHoles] points) before it
/// gives the other areas their blocks, so an area holding a hole and a block label stays
/// unmeshed. Removes from `problem` every seed that shares an area with a hole seed (the first
/// hole of the area stays; the default label is kept, it may lie anywhere) and adds a warning
/// naming both labels for each removed block label. Nothing changes when no area holds two seeds.
void drop_labels_in_hole_areas(Problem& problem);

}  // namespace rheomag::cases
