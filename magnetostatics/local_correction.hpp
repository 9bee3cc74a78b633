#pragma once
// Local Newton corrections (nonlinear elimination) where the residual concentrates.

#include <Eigen/Core>

#include "magnetostatics/assembly.hpp"
#include "magnetostatics/dof_map.hpp"
#include "magnetostatics/newton.hpp"

namespace rheomag::magnetostatics {

/// After a global Newton step of a saturating problem most of |R| often sits on a few dofs at
/// re-entrant iron corners, where the B-H knee makes the global step overshoot; the global Newton
/// then needs several more steps for that corner alone. This makes up to
/// options.local_iterations Newton steps on a patch around those dofs (the other dofs fixed; at
/// most options.local_max_share of all dofs, else fewer rings or none): the
/// patch's tangent is factorised (small sparse Cholesky) and each step is accepted when it lowers
/// the patch's residual rows or its energy (Armijo, halving up to max_backtracks times); a
/// further step is made only after one that at least halved |R|.
/// `a` holds all nodal values, `source` the free-dof source; `r` = R(a) over the free dofs and
/// `norm` = |r| are updated in place. Returns the number of local steps made.
int correct_locally(const Assembler& assembler, const DofMap& dofs, const Eigen::VectorXd& source,
                    const NewtonOptions& options, Eigen::VectorXd& a, Eigen::VectorXd& r,
                    double& norm);

}  // namespace rheomag::magnetostatics
