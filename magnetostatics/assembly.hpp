#pragma once
// Global assembly: scatters element kernels into the free-dof residual and sparse tangent.

#include <Eigen/Sparse>
#include <vector>

#include "case/problem.hpp"
#include "magnetostatics/circuit_currents.hpp"
#include "magnetostatics/dof_map.hpp"
#include "magnetostatics/element_kernel.hpp"
#include "magnetostatics/reluctivity.hpp"
#include "mesh/mesh.hpp"

namespace rheomag::magnetostatics {

/// Sparse matrix type of the tangent: column-major, only the lower triangle is stored.
using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

/// Sets the number of threads of the element assembly for the whole process: 1 (the default) =
/// serial, 0 = OpenMP's default team (OMP_NUM_THREADS, else one per core). The results are the
/// same for any number (see Assembler). Serial by default: on a shared machine a second thread
/// that does not get its core makes the assembly slower, not faster (docs/performance.md).
void set_assembly_threads(int threads);
/// The setting of set_assembly_threads.
int assembly_threads();

/// Triangles an assembly covers: every one, those whose material has a constant reluctivity
/// (with the mixed boundary edges, which are linear too), or those with a B-H curve. The linear
/// and nonlinear sets add up to all (a solver can assemble the linear part once and reuse it).
enum class ElementSet { all, linear, nonlinear };

/// A set of free dofs with every triangle and mixed-boundary edge touching them (the patch of a
/// local correction): the residual rows of `dofs` are complete over `elements` and `edges`.
struct Patch {
  std::vector<int> dofs;      ///< free dofs of the patch (the local unknowns), ascending
  std::vector<int> elements;  ///< triangles with at least one node in `dofs`
  std::vector<int> edges;     ///< mixed (Robin) boundary edges with a node in `dofs`
  std::vector<int> rows;  ///< free dofs of those triangles and edges: `dofs` first, then the rest
};

/// Assembles the residual R(A) = K(A) A + (Robin terms) - (sources are added by the caller) and
/// its exact tangent over one mesh. The sparsity pattern and the element-to-matrix scatter map
/// are built once in the constructor and reused for every assembly. Assembly runs on the OpenMP
/// threads (OMP_NUM_THREADS, default one per core): the triangles are cut into fixed chunks of
/// consecutive triangles, chunks sharing no free dof get one colour, and the chunks of a colour
/// are assembled in parallel, colour after colour (see set_assembly_threads). Every matrix and
/// residual entry thus receives its contributions in the same order for any number of threads
/// (bitwise the same result). The triangles without a B-H curve are assembled once, in the
/// constructor: later assemblies start from their matrix (residual by a sparse product) and
/// visit only the nonlinear triangles (equal to a full assembly to rounding).
class Assembler {
 public:
  /// Checks that every triangle's region has a material (InputError otherwise).
  Assembler(const cases::Problem& problem, const mesh::Mesh& mesh, const DofMap& dofs);

  /// Free-dof residual of the internal forces plus mixed (Robin) boundary terms at the nodal
  /// values `a` (all nodes, prescribed ones included); also the lower-triangular tangent when
  /// `tangent` is not null (it must be a copy of pattern()), over the triangles of `set`.
  void assemble(const Eigen::VectorXd& a, Eigen::VectorXd& residual, SparseMatrix* tangent,
                ElementSet set = ElementSet::all) const;

  /// The tangent's sparsity pattern (lower triangle, free dofs), values zero.
  const SparseMatrix& pattern() const { return pattern_; }

  /// Source vector of circuit `c` at 1 A, over all nodes: sum over its regions of the current
  /// density per ampere (turns / region area for a winding; region_currents()) times
  /// integral N_i dV. Also the flux-linkage functional: lambda_c = F_c . A.
  Eigen::VectorXd circuit_source(int c) const;
  /// Current-independent source over all nodes: fixed current densities J of the regions
  /// (integral J N_i dV, with what a circuit takes back of them: region_currents()) and permanent
  /// magnets, integral H_c m . G_i dV with G_i the B operator
  /// of N_i (from H = nu B - H_c m in the weak form integral H . B(v) dV = integral J v dV), m
  /// evaluated at each triangle's centroid. InputError naming the region for a bad direction.
  Eigen::VectorXd fixed_source() const;

  /// Shape functions and B operators of triangle `e`.
  void quadrature(int e, ElementQuadrature& q) const;
  /// Meshes of at most this many triangles keep every triangle's quadrature (about 1.2 kB each)
  /// from the constructor on; larger ones recompute it at every assembly.
  static constexpr int kMaxCachedElements = 100000;
  /// Constitutive law of triangle `e`.
  const Reluctivity& law(int e) const { return laws_[material_of_element_[e]]; }
  /// Meridian-plane area of each region [m^2] (index as Problem::regions).
  const std::vector<double>& region_areas() const { return region_area_; }
  /// How each region's circuit current spreads over it (index as Problem::regions).
  const std::vector<RegionCurrent>& region_currents() const { return region_current_; }
  /// Centroid radius of triangle `e` [m] (the r of RegionCurrent::density).
  double centroid_r(int e) const;
  /// Energy of the mixed (Robin) boundary terms, integral (c0 A^2 / 2 - c1 A) dw [J]: for the
  /// open boundary (c0 = nu0 / R0, c1 = 0) the exact field energy outside R0 of a dipole field.
  double boundary_energy(const Eigen::VectorXd& a) const;
  /// Stored energy of the internal fields plus the boundary terms at the nodal values `a`:
  /// sum over triangles of integral w(B) dV + boundary_energy(a) [J] (its gradient over the free
  /// dofs is the residual of assemble).
  double energy(const Eigen::VectorXd& a) const;
  /// The patch of `seeds` (free dofs) grown by `layers` rings of triangles: dofs = the seeds and
  /// every free dof sharing a triangle with a dof of the previous ring.
  Patch patch(const std::vector<int>& seeds, int layers) const;
  /// Residual contributions of the patch's triangles and edges at `a` into `residual`, one entry
  /// per patch row (patch.rows order), and when `tangent` is not null the tangent block of the
  /// patch dofs (lower triangle, local numbering = position in patch.dofs).
  void assemble_patch(const Patch& patch, const Eigen::VectorXd& a, Eigen::VectorXd& residual,
                      SparseMatrix* tangent) const;
  /// energy(a) restricted to the patch's triangles and edges [J] (differences between two `a`
  /// that agree outside patch.dofs equal those of energy).
  double patch_energy(const Patch& patch, const Eigen::VectorXd& a) const;
  /// Lower triangle (the pattern of pattern()) of a constant-coefficient matrix over the free
  /// dofs: integral c N_i N_j dV (`curl` false: a mass matrix) or integral c G_i . G_j dV
  /// (`curl` true: as the linear stiffness), c = region_coefficient[region of the triangle].
  SparseMatrix region_matrix(const std::vector<double>& region_coefficient, bool curl) const;
  /// True when some material has a B-H curve.
  bool nonlinear() const;
  /// Number of triangles whose law is linear (kept assembled from the constructor on).
  int linear_triangles() const { return linear_triangles_; }

 private:
  struct RobinEdge {
    std::array<int, 3> nodes;
    double c0, c1;
  };
  template <class Visit>
  void for_robin_points(const RobinEdge& edge, Visit visit) const;
  void build_node_adjacency(int edge_nodes);
  void build_colouring();
  template <class Visit>
  void for_chunk_elements(int chunk, Visit visit) const;  // visit(e) for the chunk's triangles
  void robin_local(const RobinEdge& edge, const Eigen::VectorXd& a, double* r_local,
                   double* k_local) const;  // 3 residual and 3 x 3 tangent entries of one edge
  double edge_energy(const RobinEdge& edge, const Eigen::VectorXd& a) const;
  void scatter_robin(const Eigen::VectorXd& a, Eigen::VectorXd& residual,
                     SparseMatrix* tangent) const;
  int matrix_offset(int row, int col) const;  // position in pattern_ values, -1 if not stored
  // Triangle e's quadrature: the cached one, or computed into `scratch`.
  const ElementQuadrature& geometry(int e, ElementQuadrature& scratch) const;
  void build_linear_part();  // linear_values_ and linear_prescribed_ from the linear triangles
  // Residual and (when `values` is not null) tangent values of the linear triangles at `a`.
  void add_linear_part(const Eigen::VectorXd& a, Eigen::VectorXd& residual, double* values) const;

  const cases::Problem& problem_;
  const mesh::Mesh& mesh_;
  const DofMap& dofs_;
  std::vector<Reluctivity> laws_;
  std::vector<int> material_of_element_;
  std::vector<double> region_area_;
  std::vector<RegionCurrent> region_current_;
  std::vector<RobinEdge> robin_edges_;
  SparseMatrix pattern_;
  std::vector<int> element_offsets_;  // nodes^2 per element, row-major local (i, j)
  std::vector<int> robin_offsets_;    // 9 per Robin edge
  std::vector<int> node_element_start_, node_elements_;  // triangles of each node (CSR)
  std::vector<int> node_edge_start_, node_edges_;        // Robin edges of each node (CSR)
  static constexpr int kChunkElements = 256;             // triangles per assembly chunk
  std::vector<std::vector<int>> colour_chunks_;          // chunks of each colour, ascending
  std::vector<ElementQuadrature> geometry_;  // per triangle (empty above kMaxCachedElements)
  // The linear triangles' part: tangent values on pattern_ (free-free couplings) and the
  // couplings of free rows to prescribed nodes (free dofs x nodes, prescribed columns only).
  int linear_triangles_ = 0;
  std::vector<double> linear_values_;
  Eigen::SparseMatrix<double, Eigen::RowMajor, int> linear_prescribed_;
};

}  // namespace rheomag::magnetostatics
