#pragma once
// One optimiser design -> its quantities: the base case with the design values (typed edits),
// its field from the shared design evaluator on the morphed mesh of the first design (fixed
// topology; re-meshed only when a morph would invert elements), gap pressure drops from the FE
// gap field, coil resistance, L/R, power, peak steel |B|, the envelope, walls, temperature rise
// and rise time; a damper's force and a brake's torque on the same field (valve::SolvedDamper,
// valve::SolvedBrake), the device's mass. A wire_gauge variable is relaxed continuously (turns from
// the mesh's window).

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "case/case_key.hpp"
#include "design/design_evaluator.hpp"
#include "design/quantities.hpp"
#include "fluid/fluid.hpp"
#include "optimise/spec.hpp"
#include "transient/quasi_static.hpp"
#include "valve/brake.hpp"
#include "valve/damper.hpp"
#include "valve/valve_chain.hpp"

namespace rheomag::optimise {

/// Evaluates designs of one base case for the optimiser. Design values are in the case file's
/// units.
class OptimiseEvaluator {
 public:
  /// `base` is the case with its [optimise] table; `spec` read from it.
  OptimiseEvaluator(cases::Case base, OptimiseSpec spec);
  /// The case with design `x` set (InputError if the template rejects the dimensions).
  cases::Case case_at(const std::vector<double>& x) const;
  /// All quantities of design `x` (one nonlinear FE solve). Throws InputError for an invalid
  /// design and ConvergenceError if Newton fails. `neighbour`: x is a finite-difference
  /// neighbour of the last design evaluated without it; response_model = "quasi_static" then
  /// builds its table on that design's grid from its states (same mesh topology), so the
  /// stencil's differences are smooth in the design and its static solves start close.
  design::Quantities evaluate(const std::vector<double>& x, bool neighbour = false);
  /// Makes the next evaluate() generate a fresh mesh (the one `rheomag solve` would use for that
  /// design) and use it as the reference of later morphs.
  void remesh_next() { designs_.remesh_next(); }
  /// With a wire_gauge variable: true evaluates the winding as the written case has it (the
  /// case's whole turns from wire and fill_factor), false (default) the continuous relaxation.
  void exact_winding(bool exact) { exact_winding_ = exact; }
  /// response_model = "quasi_static": the factor on the reduction's response_time (the
  /// transient runs' value over the reduction's at a checked design; 1 until one is checked).
  void set_response_correction(double factor) { response_correction_ = factor; }
  double response_correction() const { return response_correction_; }
  /// The field of the last evaluate() call.
  const design::EvaluatedField& last_field() const { return designs_.last(); }
  /// FE solves done so far.
  int fe_solves() const { return designs_.fe_solves(); }
  /// Meshes generated so far (1 + re-meshes after a morph failed).
  int meshes() const { return static_cast<int>(designs_.meshes_built()); }
  const OptimiseSpec& spec() const { return spec_; }
  const cases::Case& base() const { return base_; }

 private:
  cases::Case base_;
  OptimiseSpec spec_;
  fluid::Fluid fluid_;
  valve::ValveOptions valve_;    ///< the base case's [valve] options (re-read if a variable is one)
  bool valve_varies_ = false;    ///< a design variable is a [valve] key
  bool current_varies_ = false;  ///< a design variable is the first circuit's (on-state) current
  int gauge_index_ = -1;         ///< index of the wire_gauge variable (-1: none)
  bool exact_winding_ = false;   ///< whole turns as the case derives them (no relaxation)
  double response_correction_ = 1.0;       ///< see set_response_correction
  transient::QuasiStaticStart reference_;  ///< the last non-neighbour design's quasi-static states
  long long reference_meshes_ = -1;        ///< meshes_built() when reference_ was kept
  Eigen::VectorXd centre_field_;  ///< nodal A of the last non-neighbour design's on-state solve
  long long centre_meshes_ = -1;  ///< meshes_built() when centre_field_ was kept
  std::optional<valve::DamperOptions> damper_;  ///< [damper] of a damper case ([optimise] velocity)
  std::optional<valve::BrakeOptions> brake_;    ///< [brake] of a brake case ([optimise] speed)
  std::vector<double> region_density_;  ///< per region of the base case [kg/m^3] (mass only)
  design::DesignEvaluator designs_;
};

}  // namespace rheomag::optimise
