#pragma once
// Internal to rheomag_case: FEMM's pairing of the edges that carry one (anti)periodic property.

#include <vector>

#include "case/femm_file.hpp"
#include "case/problem.hpp"

namespace rheomag::cases::femm {

/// Edge conditions of (anti)periodic properties: FEMM pairs the two edges (two segments or two
/// arcs, never more) that carry one periodic (BdryType 4) or antiperiodic (5) property (the
/// orientation is the solver's: BoundaryCondition::partner); both edges get the finer of their two
/// subdivisions. The first edge keeps the property's condition, the second gets its own,
/// partnered with it. Entries for edges without such a property stay -1.
struct PeriodicEdges {
  std::vector<int> segment_condition, arc_condition;  // problem.boundaries index or -1
  std::vector<double> segment_max_length;             // FEMM units, <= 0 = none
  std::vector<double> arc_max_degrees;
};

/// Pairs the edges of every periodic and antiperiodic property of `file`, adds each pair's
/// second condition to `problem.boundaries`, and warns of a property only one edge carries (FEMM
/// drops it). InputError for three or more edges, a segment paired with an arc, or paired edges
/// of different lengths or angles.
PeriodicEdges pair_periodic_edges(const FemFile& file, Problem& problem, FemReader& reader);

}  // namespace rheomag::cases::femm
