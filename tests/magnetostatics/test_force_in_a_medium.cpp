// Force on a body surrounded by a medium other than air (issue 31: the axial force on the moving
// core of a damper, whose piston is surrounded by MR fluid): the stress tensor of the medium,
// T = H B^T - w' I, against references computed without it.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "case/case_file.hpp"
#include "core/error.hpp"
#include "magnetostatics/block_integrals.hpp"
#include "magnetostatics/solve_problem.hpp"
#include "tests/magnetostatics/coil_problem.hpp"

namespace rheomag::magnetostatics {
namespace {

/// The one component of the force integral `request` ("REGION[+REGION]:force") on a solve.
double axial_force(const SolveResult& solved, const std::string& request) {
  const auto integrals = block_integrals(*solved.solver, solved.solution, {request});
  return integrals.at(0).components.at(0).value;
}

/// Two coaxial coils (2 mm x 2 mm, mean radius 20 mm, 10 mm apart, 100 turns each at 1 A) in a
/// homogeneous linear medium of relative permeability `mu_r` (coils included), A = 0 on the
/// automatic outer boundary.
SolveResult coils_in(double mu_r) {
  cases::Material medium{"air", mu_r, {}, 0.0, "test medium"};
  medium.fluid = mu_r != 1.0;  // a linear magnetic fluid (a ferrofluid), else free space
  return solve_problem(
      test::rectangles_problem({{19e-3, 21e-3, -6e-3, -4e-3, "lower", 0, 100.0, 0.25e-3},
                                {19e-3, 21e-3, 4e-3, 6e-3, "upper", 0, 100.0, 0.25e-3}},
                               {medium}, 1.0, cases::OuterBoundary::dirichlet, 2));
}

TEST(ForceInAMedium, CoilsInALinearMediumFeelMuRTimesTheForceInAir) {
  // Reference: in a homogeneous linear medium with A = 0 on the boundary, A (and B) is mu_r
  // times the free-space solution on the same mesh, so the force at the same currents is mu_r
  // times the force in air (which Force.CoaxialCoilsMatchExactMutualInductanceGradient checks
  // against the exact mutual inductance). The air-only stress tensor nu0 (B B - |B|^2 I / 2)
  // would give mu_r^2 times. Tolerance 1e-6 (round-off of two solves on one geometry).
  const double in_air = axial_force(coils_in(1.0), "upper:force");
  const double in_medium = axial_force(coils_in(4.0), "upper:force");
  std::printf("coils: F_z %.9g N in air, %.9g N in mu_r = 4 (ratio %.9f)\n", in_air, in_medium,
              in_medium / in_air);
  EXPECT_LT(in_air, 0.0);  // parallel currents attract
  EXPECT_NEAR(in_medium / in_air, 4.0, 4e-6);
}

/// A solenoid actuator immersed in MR fluid: a 500-turn coil (r 6..10 mm, z -10..10 mm) and an
/// AISI 1010 plunger (r 0..4 mm, 20 mm long, lower end at z0 mm), the space between filled with
/// MRF-132DG (nonlinear B-H curve).
cases::Case plunger_in_fluid(double z0_mm) {
  const auto box = [](double r0, double r1, double z0, double z1) {
    char text[160];
    std::snprintf(text, sizeof text, "[[%g, %g], [%g, %g], [%g, %g], [%g, %g], [%g, %g]]", r0, z0,
                  r1, z0, r1, z1, r0, z1, r0, z0);
    return std::string(text);
  };
  const std::string text =
      "[case]\nname = \"plunger_in_fluid\"\nunits = \"mm\"\n"
      "symmetry = \"axisymmetric\"\n[solver]\norder = 2\n"
      "[geometry]\nbackground_material = \"MRF-132DG\"\n"
      "[[circuit]]\nname = \"coil\"\ncurrent = 2.0\n"
      "[[region]]\nname = \"plunger\"\nmaterial = \"AISI 1010\"\n"
      "mesh_size = 0.3\npoints = " +
      box(0, 4, z0_mm, z0_mm + 20) +
      "\n[[region]]\nname = \"coil\"\nmaterial = \"Copper\"\n"
      "coil = { circuit = \"coil\", turns = 500 }\nmesh_size = 0.6\n"
      "points = " +
      box(6, 10, -10, 10) + "\n";
  return cases::parse_case(std::string_view(text), "plunger_in_fluid.toml");
}

TEST(ForceInAMedium, PlungerInMrFluidMatchesCoenergyDerivative) {
  // Reference: virtual work at constant current, F_z = dW'/dz0, by the central difference of the
  // co-energies of two solves with the plunger moved by +-0.25 mm (each re-meshed), the same
  // reference as Force.PlungerStressTensorMatchesCoenergyDerivative but with the fluid's
  // nonlinear B-H curve around the plunger. Tolerance 1 % (issue 31).
  const double z0 = 2.0, delta = 0.25;  // mm
  const SolveResult at = solve_problem(plunger_in_fluid(z0).problem);
  const double force = axial_force(at, "plunger:force");
  const double w_plus = solve_problem(plunger_in_fluid(z0 + delta).problem).results.coenergy;
  const double w_minus = solve_problem(plunger_in_fluid(z0 - delta).problem).results.coenergy;
  const double virtual_work = (w_plus - w_minus) / (2.0 * delta * 1e-3);
  std::printf("plunger in MRF-132DG: stress tensor F_z %.6g N, dW'/dz %.6g N (%+.3f %%)\n", force,
              virtual_work, 100.0 * (force / virtual_work - 1.0));
  EXPECT_LT(virtual_work, 0.0);  // pulled into the coil (towards -z)
  EXPECT_NEAR(force, virtual_work, 0.01 * std::abs(virtual_work));
}

/// Inserts `p` into the closed outline between its consecutive points `a` and `b` (either
/// order); fails the test when they are not consecutive.
void insert_between(std::vector<mesh::Point>& outline, mesh::Point a, mesh::Point b,
                    mesh::Point p) {
  const auto same = [](mesh::Point u, mesh::Point v) {
    return std::abs(u.r - v.r) < 1e-12 && std::abs(u.z - v.z) < 1e-12;
  };
  for (std::size_t i = 0; i < outline.size(); ++i) {
    const std::size_t j = (i + 1) % outline.size();
    if ((same(outline[i], a) && same(outline[j], b)) ||
        (same(outline[i], b) && same(outline[j], a))) {
      outline.insert(outline.begin() + static_cast<std::ptrdiff_t>(j), p);
      return;
    }
  }
  ADD_FAILURE() << "no edge (" << a.r << ", " << a.z << ") - (" << b.r << ", " << b.z << ")";
}

/// cases/damper_piston.toml, its rod and rebound chamber meshed with `element_size` [m] (0:
/// automatic), with the piston and its rod moved rigidly by `dz` [m]: every point
/// within |z| <= 14 mm (the head, the gaps beside it and the ends of the chambers and tube wall
/// that meet it) and the whole rod, whose end moves in the air above the damper (the rebound
/// chamber's side is split where the rod's end now is). The [valve] and [damper] sections
/// belong to later layers and are left out.
SolveResult damper_moved_by(double dz, double element_size = 0.0) {
  const std::string path = std::string(RHEOMAG_SOURCE_DIR) + "/cases/damper_piston.toml";
  toml::table table = toml::parse_file(path);
  table.erase("valve");
  table.erase("damper");
  cases::Case c = cases::parse_case(std::move(table), path);
  const double mm = 1e-3;
  for (cases::RegionOutline& region : c.input.regions) {
    const bool rod = region.name == "rod";
    if (rod || region.name == "rebound_chamber") region.mesh_size = element_size;
    for (mesh::Point& p : region.outline)
      if (rod || std::abs(p.z) <= 14 * mm + 1e-12) p.z += dz;
    const mesh::Point side_end{6 * mm, 40 * mm}, rod_end{6 * mm, 40 * mm + dz};
    const mesh::Point rod_foot{6 * mm, 14 * mm + dz};
    if (rod && dz > 0) insert_between(region.outline, rod_foot, rod_end, side_end);
    if (region.name == "rebound_chamber" && dz < 0)
      insert_between(region.outline, rod_foot, side_end, rod_end);
  }
  cases::build_case(c);
  return solve_problem(c.problem);
}

TEST(ForceInAMedium, DamperPistonForceMatchesCoenergyDerivative) {
  // The axial magnetic force on the moving piston of cases/damper_piston.toml (head, coil,
  // sleeve and rod; MR fluid in the gaps and chambers around it, air above the rod's end).
  // Reference: dW'/dz at constant current by the central difference of two solves with the
  // piston and rod moved rigidly by +-0.2 mm (re-meshed). The rod's end meets the interface of
  // the fluid and the air, where the mask cannot both move with the rod and keep the interface
  // still: an error of the order of the element size there, which the integral reports. Measured
  // against the reference: -31 % on the automatic mesh, -10 % with 1 mm elements in the rod and
  // the rebound chamber, -7.5 % with 0.5 mm, -1.6 % with 0.25 mm. Tolerance 3 % at 0.25 mm (the
  // force is a small imbalance, so the re-meshing noise of W' weighs more than for the plunger).
  const std::string body = "pole_top+neck+pole_bottom+coil+sleeve+rod:force";
  const double delta = 0.2e-3, h = 0.25e-3;
  const SolveResult at = damper_moved_by(0.0, h);
  const BlockIntegral f = block_integrals(*at.solver, at.solution, {body}).at(0);
  const double force = f.components.at(0).value;
  const double w_plus = damper_moved_by(delta, h).results.coenergy;
  const double w_minus = damper_moved_by(-delta, h).results.coenergy;
  const double virtual_work = (w_plus - w_minus) / (2.0 * delta);
  std::printf("damper piston: stress tensor F_z %.6g N, dW'/dz %.6g N (%+.3f %%)\n%s\n", force,
              virtual_work, 100.0 * (force / virtual_work - 1.0), f.warning.c_str());
  EXPECT_NEAR(force, virtual_work, 0.03 * std::abs(virtual_work));
  EXPECT_NE(f.warning.find("(0.006, 0.04) m"), std::string::npos) << f.warning;
}

TEST(ForceInAMedium, HeadWithoutItsRodIsRefusedByName) {
  // The damper's head alone touches the steel rod: no layer of air or fluid between them for
  // the stress tensor, so it is refused naming the rod.
  const SolveResult solved = damper_moved_by(0.0);
  try {
    axial_force(solved, "pole_top+neck+pole_bottom+coil+sleeve:force");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'rod'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("neither air nor a fluid"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace rheomag::magnetostatics
