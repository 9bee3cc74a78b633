// FEMM's pairing of the edges that carry one (anti)periodic property (see femm_periodic.hpp).

#include "case/femm_periodic.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "case/toml_section.hpp"

namespace rheomag::cases::femm {

PeriodicEdges pair_periodic_edges(const FemFile& file, Problem& problem, FemReader& reader) {
  PeriodicEdges out;
  out.segment_condition.assign(file.segments.size(), -1);
  out.arc_condition.assign(file.arcs.size(), -1);
  for (const FemSegment& s : file.segments) out.segment_max_length.push_back(s.max_length);
  for (const FemArc& a : file.arcs) out.arc_max_degrees.push_back(a.max_side_degrees);
  const int count = static_cast<int>(file.boundaries.size());
  auto periodic = [&](int marker) {
    return marker >= 1 && marker <= count &&
           (file.boundaries[marker - 1].type == 4 || file.boundaries[marker - 1].type == 5);
  };
  struct Use {
    bool arc;
    int index, line;
  };
  std::vector<std::vector<Use>> uses(file.boundaries.size());
  for (std::size_t i = 0; i < file.segments.size(); ++i)
    if (periodic(file.segments[i].marker))
      uses[file.segments[i].marker - 1].push_back(
          {false, static_cast<int>(i), file.segments[i].line});
  for (std::size_t i = 0; i < file.arcs.size(); ++i)
    if (periodic(file.arcs[i].marker))
      uses[file.arcs[i].marker - 1].push_back({true, static_cast<int>(i), file.arcs[i].line});
  const auto& points = file.points;
  auto valid_point = [&](int n) { return n >= 0 && n < static_cast<int>(points.size()); };
  for (int b = 0; b < count; ++b) {
    const std::vector<Use>& use = uses[b];
    if (use.empty()) continue;  // an unused property is harmless
    const FemBoundary& bdry = file.boundaries[b];
    const std::string name = std::string(bdry.type == 4 ? "periodic" : "antiperiodic") +
                             " boundary '" + bdry.name + "' (BdryType " +
                             std::to_string(bdry.type) + ", defined at line " +
                             std::to_string(bdry.line) + ")";
    if (use.size() == 1) {
      // FEMM's mesher drops a property that pairs nothing; the edge gets no condition.
      problem.warnings.push_back(reader.where(use[0].line) + ": " + name +
                                 " is used by this edge only; it pairs nothing, so the edge gets "
                                 "no condition, as in FEMM (which drops such a property)");
      continue;
    }
    if (use.size() != 2) {
      std::string lines;
      for (const Use& u : use) lines += (lines.empty() ? "" : ", ") + std::to_string(u.line);
      reader.fail(use.back().line, name + " is used by " + std::to_string(use.size()) +
                                       " edge(s) (lines " + lines +
                                       "); it must pair exactly two edges, two segments or two "
                                       "arcs, as in FEMM: give each pair its own property");
    }
    if (use[0].arc != use[1].arc)
      reader.fail(use[1].line, name +
                                   " pairs a segment with an arc; it must pair two segments "
                                   "or two arcs, as in FEMM");
    if (!use[0].arc) {
      const FemSegment& s0 = file.segments[use[0].index];
      const FemSegment& s1 = file.segments[use[1].index];
      if (!valid_point(s0.n0) || !valid_point(s0.n1) || !valid_point(s1.n0) || !valid_point(s1.n1))
        continue;  // the segment loop names the bad point
      auto length = [&](const FemSegment& s) {
        return std::hypot(points[s.n1].first.r - points[s.n0].first.r,
                          points[s.n1].first.z - points[s.n0].first.z);
      };
      const double l0 = length(s0), l1 = length(s1);
      if (std::abs(l0 - l1) > 1e-6 * std::max(l0, l1))
        reader.fail(use[1].line, name + " pairs segments of different lengths (" +
                                     format_number(l0) + " at line " + std::to_string(s0.line) +
                                     ", " + format_number(l1) +
                                     " in the file's length unit); the paired edges must have "
                                     "the same length");
      double size = std::min(s0.max_length > 0 ? s0.max_length : s1.max_length,
                             s1.max_length > 0 ? s1.max_length : s0.max_length);
      out.segment_max_length[use[0].index] = out.segment_max_length[use[1].index] = size;
    } else {
      const FemArc& a0 = file.arcs[use[0].index];
      const FemArc& a1 = file.arcs[use[1].index];
      if (!valid_point(a0.n0) || !valid_point(a0.n1) || !valid_point(a1.n0) || !valid_point(a1.n1))
        continue;
      if (std::abs(a0.degrees - a1.degrees) > 1e-6)
        reader.fail(use[1].line, name + " pairs arcs of different angles (" +
                                     format_number(a0.degrees) + " deg at line " +
                                     std::to_string(a0.line) + ", " + format_number(a1.degrees) +
                                     " deg); the paired arcs must span the same angle");
      out.arc_max_degrees[use[0].index] = out.arc_max_degrees[use[1].index] =
          std::min(a0.max_side_degrees, a1.max_side_degrees);
    }
    BoundaryCondition& first = problem.boundaries[b];
    first.kind = bdry.type == 4 ? BoundaryKind::periodic : BoundaryKind::antiperiodic;
    first.pairs_by_angle = use[0].arc;  // FEMM pairs arcs of one angle, whatever their radii
    BoundaryCondition second = first;
    second.partner = b;
    first.partner = static_cast<int>(problem.boundaries.size());
    problem.boundaries.push_back(second);
    (use[0].arc ? out.arc_condition : out.segment_condition)[use[0].index] = b;
    (use[1].arc ? out.arc_condition : out.segment_condition)[use[1].index] = first.partner;
  }
  return out;
}

}  // namespace rheomag::cases::femm
