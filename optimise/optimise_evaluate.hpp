#pragma once
// One design -> its quantities: the case with the design values, the FE field on the morphed
// mesh of the first design (fixed topology; re-meshed only when a morph would invert elements),
// gap pressure drops from the FE gap field, coil resistance, L/R, power, peak steel |B|, the
// envelope, walls, temperature rise and rise time. A wire_gauge variable is relaxed
// continuously (optimise_wire_gauge.hpp).

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "fluid/fluid.hpp"
#include "magnetostatics/case_file.hpp"
#include "magnetostatics/results.hpp"
#include "magnetostatics/solver.hpp"
#include "mesh/mesh.hpp"
#include "optimise/morph_mesh.hpp"
#include "optimise/optimise_spec.hpp"

namespace rheomag::optimise {

/// The FE solution of the last evaluated design (for the .vtu of the optimum).
struct EvaluatedField {
  std::unique_ptr<magnetostatics::MagnetostaticSolver> solver;
  magnetostatics::Solution solution;
  magnetostatics::Results results;
};

/// Evaluates designs of one base case. Design values are in the case file's units.
class DesignEvaluator {
 public:
  /// `base` is the case with its [optimise] table; `spec` read from it.
  DesignEvaluator(magnetostatics::Case base, OptimiseSpec spec);
  /// The case with design `x` set (InputError if the template rejects the dimensions).
  magnetostatics::Case case_at(const std::vector<double>& x) const;
  /// All quantities of design `x` (one nonlinear FE solve). Throws InputError for an invalid
  /// design and ConvergenceError if Newton fails.
  Quantities evaluate(const std::vector<double>& x);
  /// Makes the next evaluate() generate a fresh mesh (the one `rheomag solve` would use for that
  /// design) and use it as the reference of later morphs.
  void remesh_next() { have_mesh_ = false; }
  /// With a wire_gauge variable: true evaluates the winding as the written case has it (the
  /// case's whole turns from wire and fill_factor), false (default) the continuous relaxation.
  void exact_winding(bool exact) { exact_winding_ = exact; }
  /// The field of the last evaluate() call.
  const EvaluatedField& last_field() const { return last_; }
  /// FE solves done so far.
  int fe_solves() const { return fe_solves_; }
  /// Meshes generated so far (1 + re-meshes after a morph failed).
  int meshes() const { return meshes_; }
  const OptimiseSpec& spec() const { return spec_; }
  const magnetostatics::Case& base() const { return base_; }

 private:
  mesh::Mesh mesh_for(const magnetostatics::Problem& closed, const Breakpoints& breakpoints);

  magnetostatics::Case base_;
  OptimiseSpec spec_;
  std::vector<std::string> keys_;
  fluid::Fluid fluid_;
  int gauge_index_ = -1;         ///< index of the wire_gauge variable (-1: none)
  bool exact_winding_ = false;   ///< whole turns as the case derives them (no relaxation)
  bool need_rise_time_ = false;  ///< rise_time is used: lambda(i) samples per design
  mesh::Mesh reference_mesh_;
  Breakpoints reference_breakpoints_;
  bool have_mesh_ = false;
  EvaluatedField last_;
  int fe_solves_ = 0;
  int meshes_ = 0;
};

}  // namespace rheomag::optimise
