#pragma once
// Local Newton corrections (nonlinear elimination) of the nodal 2D problem.

#include <Eigen/Core>

#include "magnetostatics/assembly.hpp"
#include "magnetostatics/dof_map.hpp"
#include "magnetostatics/newton.hpp"

namespace rheomag::magnetostatics {

/// Local Newton steps where the residual concentrates (local_newton.hpp), on patches of
/// triangles (Assembler::patch). `a` holds all nodal values, `source` the free-dof source; `r` =
/// R(a) over the free dofs and `norm` = |r| are updated in place. Returns the number of local steps
/// made.
int correct_locally(const Assembler& assembler, const DofMap& dofs, const Eigen::VectorXd& source,
                    const NewtonOptions& options, Eigen::VectorXd& a, Eigen::VectorXd& r,
                    double& norm);

}  // namespace rheomag::magnetostatics
