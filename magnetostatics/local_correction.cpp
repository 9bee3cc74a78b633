#include "magnetostatics/local_correction.hpp"

#include <memory>
#include <vector>

#include "magnetostatics/local_newton.hpp"

namespace rheomag::magnetostatics {
namespace {

/// A patch of the nodal 2D problem: the nodal values `a` change with its unknowns.
class NodalPatch : public LocalPatch {
 public:
  NodalPatch(const Assembler& assembler, const DofMap& dofs, const Eigen::VectorXd& source,
             Eigen::VectorXd& a, Patch patch)
      : assembler_(assembler), dofs_(dofs), source_(source), a_(a), patch_(std::move(patch)) {}
  const std::vector<int>& rows() const override { return patch_.rows; }
  int unknowns() const override { return static_cast<int>(patch_.dofs.size()); }
  Eigen::VectorXd values() const override {
    Eigen::VectorXd v(unknowns());
    for (int k = 0; k < unknowns(); ++k) v[k] = a_[dofs_.node_of_dof[patch_.dofs[k]]];
    return v;
  }
  void set_values(const Eigen::VectorXd& values) override {
    for (int k = 0; k < unknowns(); ++k) a_[dofs_.node_of_dof[patch_.dofs[k]]] = values[k];
  }
  void assemble(Eigen::VectorXd& internal, SparseMatrix* tangent) const override {
    assembler_.assemble_patch(patch_, a_, internal, tangent);
  }
  double potential() const override {
    double work = 0.0;
    for (int d : patch_.dofs) work += source_[d] * a_[dofs_.node_of_dof[d]];
    return assembler_.patch_energy(patch_, a_) - work;
  }

 private:
  const Assembler& assembler_;
  const DofMap& dofs_;
  const Eigen::VectorXd& source_;
  Eigen::VectorXd& a_;
  Patch patch_;
};

}  // namespace

int correct_locally(const Assembler& assembler, const DofMap& dofs, const Eigen::VectorXd& source,
                    const NewtonOptions& options, Eigen::VectorXd& a, Eigen::VectorXd& r,
                    double& norm) {
  const PatchBuilder build = [&](const std::vector<int>& seeds, int layers) {
    return std::make_unique<NodalPatch>(assembler, dofs, source, a, assembler.patch(seeds, layers));
  };
  return correct_locally(build, options, r, norm);
}

}  // namespace rheomag::magnetostatics
