#pragma once
// Block integrals over named regions of a solved field (`rheomag solve --integral REGION:KIND`),
// FEMM's mo_blockintegral kinds that matter for MR devices, as values, JSON and text.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/enum_names.hpp"
#include "magnetostatics/results.hpp"
#include "magnetostatics/solver.hpp"

namespace rheomag::magnetostatics {

/// What a block integral computes (FEMM's mo_blockintegral number in brackets).
enum class IntegralKind {
  a_dot_j,    ///< integral A . J dV [Wb A] (0)
  energy,     ///< stored energy integral integral_0^B H dB dV [J] (2)
  coenergy,   ///< co-energy integral integral_0^H B dH dV [J] (17)
  area,       ///< meridian (cross-section) area [m^2] (5)
  volume,     ///< volume: 2 pi r dA, or the depth times the area [m^3] (10)
  average_b,  ///< volume average of B [T] ((8, 9) / 10)
  flux,       ///< mean flux through the loops (axisymmetric) or between the conductor and A = 0
              ///< (planar) of the region's cross-section [Wb] (1 / 5)
  force,      ///< weighted-stress-tensor force [N] (18, 19)
  torque,     ///< weighted-stress-tensor torque about the origin, planar [N m] (22)
};

/// Names of the kinds as `--integral` writes them.
inline constexpr auto kIntegralKindNames = enum_names<IntegralKind>({
    {IntegralKind::a_dot_j, "a_dot_j"},
    {IntegralKind::energy, "energy"},
    {IntegralKind::coenergy, "coenergy"},
    {IntegralKind::area, "area"},
    {IntegralKind::volume, "volume"},
    {IntegralKind::average_b, "average_b"},
    {IntegralKind::flux, "flux"},
    {IntegralKind::force, "force"},
    {IntegralKind::torque, "torque"},
});

/// One named component of a block integral (e.g. "f_z") and its value in SI units.
struct IntegralComponent {
  std::string name;
  double value = 0.0;
};

/// One block integral over one or more regions.
struct BlockIntegral {
  std::vector<std::string> regions;  ///< the regions integrated over (a body of several)
  IntegralKind kind = IntegralKind::energy;
  std::string unit;                           ///< SI unit of every component
  std::string femm;                           ///< FEMM's Lua call(s) giving the same number
  std::vector<IntegralComponent> components;  ///< one value, or the vector's components
  std::string warning;  ///< what limits the accuracy of this value ("" = nothing known)
};

/// Evaluates `requests`, each "REGION:KIND" or "REGION+REGION...:KIND" (regions by name, as the
/// solve summary lists them). InputError for a malformed request, an unknown kind (listing the
/// kinds), an unknown region (listing the regions) or a torque of an axisymmetric problem.
std::vector<BlockIntegral> block_integrals(const MagnetostaticSolver& solver,
                                           const Solution& solution,
                                           const std::vector<std::string>& requests);

/// The integrals as a JSON array of {regions, kind, unit, femm, values: {component: value}}.
nlohmann::json integrals_json(const std::vector<BlockIntegral>& integrals);

/// The integrals as text: a blank line, then one line per integral (nothing without any).
std::string integrals_text(const std::vector<BlockIntegral>& integrals);

}  // namespace rheomag::magnetostatics
