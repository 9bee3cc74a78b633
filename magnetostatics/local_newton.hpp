#pragma once
// Local Newton corrections (nonlinear elimination) on a patch of unknowns, for any discretisation
// with a potential: the seeds where the residual concentrates, and the damped Newton steps.

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <functional>
#include <memory>
#include <vector>

#include "magnetostatics/newton.hpp"

namespace rheomag::magnetostatics {

/// The unknowns of largest |r_i| that hold `fraction` of |r|^2, if at most `max_dofs` of them
/// do; empty otherwise (the residual is not concentrated).
std::vector<int> concentrated_dofs(const Eigen::VectorXd& r, double fraction, int max_dofs);

/// A patch of a problem R = grad E: some unknowns (the local ones, all others held) and the
/// residual rows their elements touch.
class LocalPatch {
 public:
  virtual ~LocalPatch() = default;
  /// Rows of the global residual the patch's elements touch: its unknowns first, then the rest.
  virtual const std::vector<int>& rows() const = 0;
  /// Number of local unknowns (the first of rows()).
  virtual int unknowns() const = 0;
  /// Values of the local unknowns.
  virtual Eigen::VectorXd values() const = 0;
  /// Sets the local unknowns (the problem's state changes with them).
  virtual void set_values(const Eigen::VectorXd& values) = 0;
  /// The elements' share of the residual, one entry per row (sources excluded), and, when
  /// `tangent` is not null, the tangent over the unknowns (lower triangle, local numbering).
  virtual void assemble(Eigen::VectorXd& internal,
                        Eigen::SparseMatrix<double, Eigen::ColMajor, int>* tangent) const = 0;
  /// The elements' energy minus the sources' work on the unknowns (its differences equal E's).
  virtual double potential() const = 0;
};

/// Builds the patch of `seeds` (unknowns) grown by `layers` rings of elements.
using PatchBuilder =
    std::function<std::unique_ptr<LocalPatch>(const std::vector<int>& seeds, int layers)>;

/// After a global Newton step of a saturating problem most of |R| often sits on a few unknowns at
/// iron corners, where the B-H knee makes the global step overshoot; the global Newton then needs
/// several more steps for those corners alone. This makes up to options.local_iterations Newton
/// steps on a patch around them (the other unknowns fixed; at most options.local_max_share of all
/// unknowns, else fewer rings or none): the patch's tangent is factorised (small sparse Cholesky)
/// and each step is accepted when it lowers the patch's residual rows or its potential (Armijo,
/// halving up to max_backtracks times); a further step is made only after one that at least
/// halved |R|. `r` = R(x) and `norm` = |r| are updated in place; the state moves through the
/// patches. Returns the number of local steps made.
int correct_locally(const PatchBuilder& build, const NewtonOptions& options, Eigen::VectorXd& r,
                    double& norm);

}  // namespace rheomag::magnetostatics
