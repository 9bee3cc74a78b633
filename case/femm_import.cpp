// FEMM 4.2 .fem (magnetostatic) reader. Format facts from the FEMM 4.2 manual and the .fem
// reader of xfemm (cfemm/libfemm); no code taken from either.

#include "case/femm_import.hpp"

#include <cmath>
#include <map>
#include <numbers>
#include <vector>

#include "case/femm_file.hpp"
#include "case/femm_hole_areas.hpp"
#include "case/femm_material.hpp"
#include "case/femm_periodic.hpp"
#include "case/magnet_direction.hpp"
#include "case/material_library.hpp"
#include "case/region_outline.hpp"
#include "case/toml_section.hpp"
#include "core/constants.hpp"
#include "core/error.hpp"

namespace rheomag::cases {

double femm_mesh_size_to_edge(double femm_size) {
  return femm_size * std::sqrt(std::numbers::pi / std::sqrt(3.0));
}

Problem parse_femm(std::string_view text, const std::string& source) {
  using namespace femm;
  FemReader reader(text, source);
  const FemFile file = read_fem_text(text, reader);
  auto fail = [&](int line, const std::string& message) { reader.fail(line, message); };

  Problem problem;
  problem.symmetry = file.axisymmetric ? Symmetry::axisymmetric : Symmetry::planar;
  // FEMM ignores [Depth] in axisymmetric problems (its Lua idiom mi_probdef(0, "millimeters",
  // "axi", ...) writes 0); a planar problem needs a positive depth.
  if (!file.axisymmetric && !(file.depth > 0))
    fail(file.depth_line,
         "[Depth] must be positive in a planar problem, got " + format_number(file.depth));
  problem.depth = file.axisymmetric ? 1.0 : file.depth * file.unit;
  problem.outer = OuterBoundary::none;
  problem.geometry.source = source;

  // Boundary properties: index i of the file -> index in problem.boundaries (or rejected).
  for (const FemBoundary& b : file.boundaries) {
    BoundaryCondition bc;
    bc.name = b.name;
    if (b.type == 0) {
      // FEMM's solvers (static2d.cpp, staticaxi.cpp) prescribe (A_0 + A_1 x + A_2 y) cos(phi),
      // x and y in the file's length unit.
      bc.kind = BoundaryKind::prescribed_a;
      const double phase = std::cos(b.phi * std::numbers::pi / 180.0);
      bc.a_value = b.a0 * phase;
      bc.a_per_r = b.a1 * phase / file.unit;
      bc.a_per_z = b.a2 * phase / file.unit;
    } else if (b.type == 2) {
      bc.kind = BoundaryKind::mixed;
      // FEMM: (1/mu) dA/dn + c0 A + c1 = 0; rheomag: nu dA/dn + c0 A = c1.
      bc.c0 = b.c0;
      bc.c1 = -b.c1;
    }
    problem.boundaries.push_back(bc);
  }
  auto check_boundary_use = [&](int marker, int line) {
    if (marker == 0) return -1;
    if (marker < 0 || marker > static_cast<int>(file.boundaries.size()))
      fail(line, "boundary property number " + std::to_string(marker) +
                     " does not exist (the "
                     "file defines " +
                     std::to_string(file.boundaries.size()) + ")");
    const FemBoundary& b = file.boundaries[marker - 1];
    const std::string name =
        "boundary '" + b.name + "' (defined at line " + std::to_string(b.line) + ")";
    switch (b.type) {
      case 0:
        if ((b.a1 != 0.0 || b.a2 != 0.0) && file.polar)
          reader.fail(line, name +
                                ": prescribed A = A_0 + A_1 r + A_2 theta in polar coordinates "
                                "([Coordinates] = polar, line " +
                                std::to_string(file.coordinates_line) +
                                ") is not supported; only cartesian A_0 + A_1 x + A_2 y");
        break;
      case 2:
        break;
      case 1:
        reader.fail(line, name +
                              ": small skin depth boundaries (BdryType 1) describe eddy currents "
                              "at a frequency > 0 (time-harmonic only); not a magnetostatic "
                              "condition");
      case 3:
        reader.fail(line,
                    name +
                        ": strategic dual image boundaries (BdryType 3) are not supported; use "
                        "a mixed (asymptotic) boundary or rheomag's automatic open boundary");
      case 4:
      case 5:
        return -1;  // pair_periodic_edges gives each paired edge its condition, others none
      case 6:
      case 7:
        reader.fail(line, name + ": " + (b.type == 6 ? "periodic" : "antiperiodic") +
                              " air-gap elements (BdryType " + std::to_string(b.type) +
                              ") couple a rotor and a stator at an arbitrary angle (rotating "
                              "machines) and are not supported; model the air gap as a region");
      default:
        reader.fail(line, name + ": unknown BdryType " + std::to_string(b.type));
    }
    return marker - 1;
  };

  const PeriodicEdges periodic = pair_periodic_edges(file, problem, reader);

  // Points.
  for (std::size_t i = 0; i < file.points.size(); ++i) {
    const auto& [p, marker] = file.points[i];
    const int line = file.point_lines[i];
    if (file.axisymmetric && p.r < 0)
      fail(line, "axisymmetric model has a point at negative r = " + format_number(p.r));
    problem.geometry.points.push_back({p.r * file.unit, p.z * file.unit});
    if (marker == 0) continue;
    if (marker < 0 || marker > static_cast<int>(file.point_props.size()))
      fail(line, "point property number " + std::to_string(marker) +
                     " does not exist (the file defines " +
                     std::to_string(file.point_props.size()) + ")");
    const FemPointProp& prop = file.point_props[marker - 1];
    if (prop.i_im != 0.0 || prop.a_im != 0.0)
      fail(prop.line, "point property '" + prop.name +
                          "': imaginary parts (I_im, A_im) are time-harmonic only");
    // FEMM: a point with no current is a prescribed A (A_re), else a point current I_re [A].
    PointCondition condition;
    condition.name = prop.name;
    condition.point = static_cast<int>(i);
    condition.prescribed = prop.i_re == 0.0;
    condition.a_value = prop.a_re;
    condition.current = prop.i_re;
    problem.point_conditions.push_back(condition);
  }
  const int point_count = static_cast<int>(file.points.size());
  auto check_point = [&](int index, int line) {
    if (index < 0 || index >= point_count)
      fail(line, "point number " + std::to_string(index) +
                     " does not exist (points are numbered "
                     "0 to " +
                     std::to_string(point_count - 1) + ")");
  };

  for (std::size_t i = 0; i < file.segments.size(); ++i) {
    const FemSegment& s = file.segments[i];
    check_point(s.n0, s.line);
    check_point(s.n1, s.line);
    if (s.n0 == s.n1) fail(s.line, "segment joins point " + std::to_string(s.n0) + " to itself");
    mesh::Segment segment;
    segment.a = s.n0;
    segment.b = s.n1;
    segment.boundary = check_boundary_use(s.marker, s.line);
    if (periodic.segment_condition[i] >= 0) segment.boundary = periodic.segment_condition[i];
    const double max_length = periodic.segment_max_length[i];
    segment.max_length = max_length > 0 ? max_length * file.unit : 0.0;
    problem.geometry.segments.push_back(segment);
  }
  for (std::size_t i = 0; i < file.arcs.size(); ++i) {
    const FemArc& a = file.arcs[i];
    check_point(a.n0, a.line);
    check_point(a.n1, a.line);
    if (a.n0 == a.n1)
      fail(a.line, "arc segment joins point " + std::to_string(a.n0) + " to itself");
    if (!(a.degrees > 0.0 && a.degrees <= 180.0))
      fail(a.line, "arc angle must be in (0, 180] degrees, got " + format_number(a.degrees));
    if (!(periodic.arc_max_degrees[i] >= 0.01))
      fail(a.line,
           "arc maximum segment angle must be at least 0.01 degrees (FEMM's minimum), got " +
               format_number(periodic.arc_max_degrees[i]) +
               (periodic.arc_condition[i] >= 0 ? " (the finer of the two paired arcs)" : ""));
    int boundary = check_boundary_use(a.marker, a.line);
    if (periodic.arc_condition[i] >= 0) boundary = periodic.arc_condition[i];
    std::vector<mesh::Point> pieces;
    append_arc(pieces, problem.geometry.points[a.n0], problem.geometry.points[a.n1], a.degrees,
               periodic.arc_max_degrees[i]);
    int previous = a.n0;
    for (std::size_t k = 0; k < pieces.size(); ++k) {
      int current = a.n1;
      if (k + 1 < pieces.size()) {
        problem.geometry.points.push_back(pieces[k]);
        current = static_cast<int>(problem.geometry.points.size()) - 1;
      }
      problem.geometry.segments.push_back({previous, current, boundary, 0.0});
      previous = current;
    }
  }

  // Materials, circuits, regions.
  std::map<int, int> material_of_block;  // file block index (0-based) -> problem material
  for (std::size_t i = 0; i < file.circuits.size(); ++i) {
    const FemCircuit& c = file.circuits[i];
    if (c.type != 0 && c.type != 1)
      fail(c.line, "circuit '" + c.name + "': unknown CircuitType " + std::to_string(c.type));
    problem.circuits.push_back({c.name, c.amps, c.type == 0});
  }
  std::map<std::string, int> name_count;
  for (const FemLabel& l : file.labels)
    if (l.block > 0 && l.block <= static_cast<int>(file.blocks.size()))
      ++name_count[file.blocks[l.block - 1].name];
  std::map<std::string, int> name_seen;

  for (const FemLabel& h : file.holes) {
    mesh::RegionSeed seed;
    seed.seed = {h.x * file.unit, h.y * file.unit};
    seed.name = "hole";
    seed.hole = true;
    seed.where = source + ":" + std::to_string(h.line);
    problem.geometry.regions.push_back(seed);
    problem.regions.push_back({});
  }
  for (const FemLabel& l : file.labels) {
    mesh::RegionSeed seed;
    seed.seed = {l.x * file.unit, l.y * file.unit};
    seed.where = source + ":" + std::to_string(l.line);
    RegionData data;
    if (l.block < 0 || l.block > static_cast<int>(file.blocks.size()))
      fail(l.line, "block type " + std::to_string(l.block) + " does not exist (the file defines " +
                       std::to_string(file.blocks.size()) + " block properties)");
    if (l.block == 0) {  // <No Mesh>
      seed.name = "no_mesh";
      seed.hole = true;
      problem.geometry.regions.push_back(seed);
      problem.regions.push_back(data);
      continue;
    }
    // FEMM's external region (Kelvin transformation) is a disk standing for the outside of a
    // circle, joined to it by a periodic pair. The planar map is conformal: the field equation
    // and the energy density keep their form, and FEMM's planar solver treats the region as any
    // other. Axisymmetric external regions scale the permeability with position
    // (KelvinExterior), from the header's [extRo], [extRi] and [extZo].
    const FemBlock& external_block = file.blocks[l.block - 1];
    if ((l.external & 1) != 0 && file.axisymmetric) {
      if (!(file.ext_ro > 0.0 && file.ext_ri > 0.0))
        fail(file.ext_line > 0 ? file.ext_line : l.line,
             "block label in an axisymmetric external region needs [extRo] > 0 and [extRi] > 0 "
             "(the radii of the external disk and of the domain's boundary); got extRo = " +
                 format_number(file.ext_ro) + ", extRi = " + format_number(file.ext_ri));
      if (!external_block.bh.empty() || external_block.h_c != 0.0 || external_block.j != 0.0 ||
          l.circuit > 0)
        fail(l.line, "block '" + external_block.name +
                         "' in an axisymmetric external region must be a linear material "
                         "without magnet, current or circuit (the region stands for the space "
                         "outside the model)");
      problem.kelvin =
          KelvinExterior{file.ext_ri * file.unit, file.ext_ro * file.unit, file.ext_zo * file.unit};
      data.kelvin_exterior = true;
    }
    const FemBlock& block = file.blocks[l.block - 1];
    auto found = material_of_block.find(l.block - 1);
    if (found == material_of_block.end()) {
      found =
          material_of_block.emplace(l.block - 1, static_cast<int>(problem.materials.size())).first;
      problem.materials.push_back(femm_material(block, source, reader, problem.warnings));
      if (file.axisymmetric) {
        std::string note =
            axisymmetric_lamination_note(block, source + ":" + std::to_string(block.line));
        if (!note.empty()) problem.warnings.push_back(std::move(note));
      }
    }
    data.current_density = block.j * 1e6;  // MA/m^2 -> A/m^2
    if (block.h_c != 0.0) {
      data.magnetisation = {l.magdir, l.magdir_expression, file.unit};
      const MagnetDirectionField check(data.magnetisation,
                                       source + ":" + std::to_string(l.line));  // parses
    } else if (!l.magdir_expression.empty()) {
      data.magnetisation.expression.clear();  // FEMM ignores a direction without H_c
    }
    data.material = found->second;
    if (l.circuit < 0 || l.circuit > static_cast<int>(file.circuits.size()))
      fail(l.line, "circuit number " + std::to_string(l.circuit) + " does not exist");
    if (l.circuit > 0) {
      const FemCircuit& c = file.circuits[l.circuit - 1];
      if (l.turns == 0) fail(l.line, "block label in circuit '" + c.name + "' has 0 turns");
      data.circuit = l.circuit - 1;
      data.turns = l.turns;
      // FEMM's rule (fsolver.cpp): a label of more than one turn, or of litz or wire, is a
      // winding; any other is a solid conductor, whose share follows its conductivity.
      data.solid_conductor = std::abs(l.turns) <= 1 && block.lam_type <= 2;
      if (c.type == 0 && l.turns != 1)
        problem.warnings.push_back(
            reader.where(l.line) + ": block label with " + std::to_string(l.turns) +
            " turns in parallel circuit '" + c.name +
            "': FEMM shares a parallel circuit's current among its labels and ignores their "
            "turns (and their sign), and so does rheomag; for N x the current, use a series "
            "circuit (CircuitType 1)");
    }
    // FEMM's default label (flag bit 2) gives its block to every area without a label; it may
    // lie outside the geometry.
    if ((l.external & 2) != 0)
      problem.geometry.default_region = static_cast<int>(problem.geometry.regions.size());
    seed.name = block.name;
    if (name_count[block.name] > 1) seed.name += "_" + std::to_string(++name_seen[block.name]);
    seed.mesh_size = l.size > 0 ? femm_mesh_size_to_edge(l.size * file.unit) : 0.0;
    problem.geometry.regions.push_back(seed);
    problem.regions.push_back(data);
  }
  if (file.labels.empty()) fail(reader.line_number(), "the model has no block labels");
  drop_labels_in_hole_areas(problem);
  return problem;
}

Problem read_femm_file(const std::filesystem::path& path) {
  return parse_femm(read_input_file(path.string()), path.string());
}

}  // namespace rheomag::cases
