#pragma once
// Flow-mode damper built on the FE field of a piston case: the piston's annular gaps in series,
// each a mixed-mode (pressure + moving wall) gap with the local yield stress tau_y(B(z)), the rod
// and the gas accumulator -> force at a piston velocity and coil current (docs/dampers.md).

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "case/case_file.hpp"
#include "core/enum_names.hpp"
#include "fluid/device_in_field.hpp"
#include "fluid/fluid.hpp"
#include "magnetostatics/results.hpp"
#include "magnetostatics/solver.hpp"
#include "valve/coil.hpp"
#include "valve/device_chain.hpp"
#include "valve/sampled_gaps.hpp"
#include "valve/solved_device.hpp"
#include "valve/valve_chain.hpp"

namespace rheomag::valve {

/// Which wall bounds the piston's gaps from outside.
enum class GapWall {
  cylinder,  ///< the cylinder tube: the piston slides past it (mixed mode)
  piston,    ///< a flux ring on the piston: both walls move together (flow mode in its frame)
};

/// Text form of GapWall.
inline constexpr auto kGapWallNames =
    enum_names<GapWall>({{GapWall::cylinder, "cylinder"}, {GapWall::piston, "piston"}});

/// The [damper] table of a piston case (SI units).
struct DamperOptions {
  double rod_diameter = 0.0;      ///< [m]
  double bore = 0.0;              ///< cylinder bore diameter [m] (cylinder wall: from the gaps)
  double gas_pressure = 0.0;      ///< accumulator pressure at mid-stroke [Pa]
  double gas_volume = 0.0;        ///< accumulator gas volume at mid-stroke [m^3] (0: no change)
  double stroke = 0.0;            ///< total stroke [m]
  double polytropic_index = 1.0;  ///< gas law p V^k = const over the stroke
  GapWall gap_wall = GapWall::cylinder;
  std::vector<double> velocities;  ///< default piston velocities [m/s]
};

/// Reads the [damper] table of a case; InputError naming the key if it is missing or invalid.
DamperOptions read_damper_options(const cases::Case& c);

/// Gas force (pressure x rod area) at full extension and full compression [N], p V^k = const.
std::pair<double, double> gas_force_range(const DamperOptions& options);

/// One gap of the piston at one operating point.
struct DamperGapResult {
  std::string name;
  fluid::MovingGapDrop drop;  ///< field-integrated mixed-mode drop and wall force
};

/// The damper at one (current, velocity).
struct DamperPoint {
  double current = 0.0;         ///< [A]
  double velocity = 0.0;        ///< piston velocity, > 0 in compression [m/s]
  double flow = 0.0;            ///< gap flow in the outer wall's frame [m^3/s]
  double wall_velocity = 0.0;   ///< inner wall velocity along the gap flow [m/s]
  double dp = 0.0;              ///< pressure drop across the piston [Pa]
  double dp_viscous = 0.0;      ///< its tau_y = 0 value [Pa]
  double force = 0.0;           ///< force against the rod's motion, > 0 in compression [N]
  double force_pressure = 0.0;  ///< dp x effective piston area [N]
  double force_wall = 0.0;      ///< fluid shear on the piston's gap walls [N]
  double force_gas = 0.0;       ///< accumulator pressure x rod area (mid-stroke) [N]
  double inductance = 0.0;      ///< secant lambda/I of circuit 0 [H]
  std::vector<DamperGapResult> gaps;
};

/// A damper whose field is solved: gaps sampled once, then any velocity.
class SolvedDamper : public SolvedDevice {
 public:
  /// InputError if a gap is not annular, the gaps do not share the piston radius, or the rod
  /// does not fit inside the piston.
  SolvedDamper(const magnetostatics::MagnetostaticSolver& solver,
               const magnetostatics::Solution& solution, const magnetostatics::Results& results,
               const fluid::Fluid& fluid, const DamperOptions& options);
  /// The damper at piston velocity `velocity` (either sign; 0 gives the gas force).
  DamperPoint point(double velocity) const;
  /// The same damper with zero flux density in every gap (current and inductance 0).
  SolvedDamper zero_field() const;
  /// Effective piston area for the pressure drop [m^2].
  double piston_area() const { return piston_area_; }

 private:
  DamperOptions options_;
  double piston_radius_ = 0.0, rod_area_ = 0.0, piston_area_ = 0.0, flow_area_ = 0.0;
};

/// A piston case: mesh and solver once, one field solve per current.
class DamperChain : public DeviceChain {
 public:
  /// InputError if the case has no annular gap, no coil or no fluid.
  DamperChain(const cases::Case& c, DamperOptions options);
  /// current-major list of points.
  std::vector<DamperPoint> evaluate(const std::vector<double>& currents,
                                    const std::vector<double>& velocities);
  /// current-major list of points at the velocities v = Q / A_eff that make the gap flows Q.
  std::vector<DamperPoint> evaluate_flows(const std::vector<double>& currents,
                                          const std::vector<double>& flows);

 private:
  std::vector<DamperPoint> evaluate_at(const std::vector<double>& currents,
                                       const std::vector<double>& values, bool flows);
  DamperOptions options_;
};

}  // namespace rheomag::valve
