#include "magnetostatics3d/ams_solver.hpp"

#define OMPI_SKIP_MPICXX 1  // the C API only (the deprecated C++ bindings warn under -Wextra)
#define MPICH_SKIP_MPICXX 1
#include <HYPRE.h>
#include <HYPRE_parcsr_ls.h>
#include <_hypre_parcsr_mv.h>
#include <mpi.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <numeric>
#include <vector>

#include "core/error.hpp"
#include "magnetostatics3d/discrete_gradient.hpp"

namespace rheomag::magnetostatics3d {
namespace {

void finalize_hypre_and_mpi() {
  int finalized = 0;
  MPI_Finalized(&finalized);
  if (finalized) return;
  HYPRE_Finalize();
  MPI_Finalize();
}

/// MPI (one process) and hypre, initialised once; MPI is finalised at exit only if initialised
/// here (a program started under mpirun, e.g. a sweep, owns its MPI). OpenMPI's singleton start
/// probes every transport and starts a helper daemon (0.4 s); one process needs neither, so
/// unless the environment says otherwise it starts isolated with the self transport (0.05 s).
void ensure_hypre() {
  static const bool ready = [] {
    int initialized = 0;
    MPI_Initialized(&initialized);
    if (!initialized) {
      setenv("OMPI_MCA_ess_singleton_isolated", "1", 0);
      setenv("OMPI_MCA_pml", "ob1", 0);
      setenv("OMPI_MCA_btl", "self", 0);
      int provided = 0;
      if (MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS)
        throw ConvergenceError("AMS: MPI could not be initialised for hypre");
      std::atexit(finalize_hypre_and_mpi);
    }
    HYPRE_Init();
    return true;
  }();
  (void)ready;
}

/// The preconditioner is set up by AmsCg::set_matrix, not by each PCG set-up.
HYPRE_Int keep_preconditioner(HYPRE_Solver, HYPRE_Matrix, HYPRE_Vector, HYPRE_Vector) {
  return 0;
}

/// A hypre vector of n values (one process) and its storage.
struct Vector {
  HYPRE_IJVector ij = nullptr;
  HYPRE_ParVector par = nullptr;
  double* data = nullptr;

  explicit Vector(int n) {
    HYPRE_IJVectorCreate(MPI_COMM_SELF, 0, n - 1, &ij);
    HYPRE_IJVectorSetObjectType(ij, HYPRE_PARCSR);
    HYPRE_IJVectorInitialize(ij);
    HYPRE_IJVectorAssemble(ij);
    void* object = nullptr;
    HYPRE_IJVectorGetObject(ij, &object);
    par = static_cast<HYPRE_ParVector>(object);
    data = hypre_VectorData(hypre_ParVectorLocalVector(reinterpret_cast<hypre_ParVector*>(par)));
    std::fill(data, data + n, 0.0);
  }
  ~Vector() { HYPRE_IJVectorDestroy(ij); }
  Vector(const Vector&) = delete;
  Vector& operator=(const Vector&) = delete;
};

/// A hypre CSR matrix (one process) from row starts, column indices and values.
HYPRE_IJMatrix make_matrix(int rows, int columns, const int* row_start, const int* column,
                           const double* value) {
  HYPRE_IJMatrix ij = nullptr;
  HYPRE_IJMatrixCreate(MPI_COMM_SELF, 0, rows - 1, 0, columns - 1, &ij);
  HYPRE_IJMatrixSetObjectType(ij, HYPRE_PARCSR);
  std::vector<HYPRE_Int> sizes(rows), row_index(rows), zeros(rows, 0);
  for (int r = 0; r < rows; ++r) sizes[r] = row_start[r + 1] - row_start[r];
  std::iota(row_index.begin(), row_index.end(), 0);
  HYPRE_IJMatrixSetDiagOffdSizes(ij, sizes.data(), zeros.data());
  HYPRE_IJMatrixInitialize(ij);
  HYPRE_IJMatrixSetValues(ij, rows, sizes.data(), row_index.data(), column, value);
  HYPRE_IJMatrixAssemble(ij);
  return ij;
}

HYPRE_ParCSRMatrix parcsr(HYPRE_IJMatrix ij) {
  void* object = nullptr;
  HYPRE_IJMatrixGetObject(ij, &object);
  return static_cast<HYPRE_ParCSRMatrix>(object);
}

/// The local CSR block of a one-process matrix (all of it).
hypre_CSRMatrix* local_block(HYPRE_IJMatrix ij) {
  return hypre_ParCSRMatrixDiag(reinterpret_cast<hypre_ParCSRMatrix*>(parcsr(ij)));
}

}  // namespace

struct AmsCg::Hypre {
  int edges = 0;
  HYPRE_IJMatrix gradient = nullptr;
  HYPRE_IJMatrix matrix = nullptr;
  std::vector<int> slot;  // hypre's value index of each value of the matrix given
  std::unique_ptr<Vector> x, y, z, b, solution;
  HYPRE_Solver ams = nullptr;
  HYPRE_Solver pcg = nullptr;
  // The kernel: gradients of the nodes off the fixed edges (G_I), and BoomerAMG-preconditioned
  // CG on G_I^T G_I (identity at the other nodes) to project right-hand sides out of it.
  Eigen::SparseMatrix<double, Eigen::RowMajor, int> interior_gradient;
  HYPRE_IJMatrix laplacian = nullptr;
  std::unique_ptr<Vector> divergence, potential;
  HYPRE_Solver amg = nullptr;
  HYPRE_Solver laplace_pcg = nullptr;

  ~Hypre() {
    if (laplace_pcg) HYPRE_ParCSRPCGDestroy(laplace_pcg);
    if (amg) HYPRE_BoomerAMGDestroy(amg);
    if (laplacian) HYPRE_IJMatrixDestroy(laplacian);
    if (pcg) HYPRE_ParCSRPCGDestroy(pcg);
    if (ams) HYPRE_AMSDestroy(ams);
    if (matrix) HYPRE_IJMatrixDestroy(matrix);
    if (gradient) HYPRE_IJMatrixDestroy(gradient);
  }

  /// G_I, G_I^T G_I and its solver, for the nodes off the `fixed` edges.
  void build_projection(const Eigen::SparseMatrix<double, Eigen::RowMajor, int>& g,
                        const std::vector<bool>& fixed) {
    const int nodes = static_cast<int>(g.cols());
    std::vector<bool> boundary(nodes, false);
    for (int e = 0; e < edges; ++e)
      if (fixed[e])
        for (Eigen::SparseMatrix<double, Eigen::RowMajor, int>::InnerIterator it(g, e); it; ++it)
          boundary[it.col()] = true;
    interior_gradient = g;
    interior_gradient.prune([&](int, int node, double) { return !boundary[node]; });
    Eigen::SparseMatrix<double, Eigen::RowMajor, int> identity(nodes, nodes);
    std::vector<Eigen::Triplet<double, int>> ones;
    for (int n = 0; n < nodes; ++n)
      if (boundary[n]) ones.emplace_back(n, n, 1.0);
    identity.setFromTriplets(ones.begin(), ones.end());
    Eigen::SparseMatrix<double, Eigen::RowMajor, int> l =
        Eigen::SparseMatrix<double, Eigen::RowMajor, int>(interior_gradient.transpose() *
                                                          interior_gradient) +
        identity;
    l.makeCompressed();
    laplacian = make_matrix(nodes, nodes, l.outerIndexPtr(), l.innerIndexPtr(), l.valuePtr());
    divergence = std::make_unique<Vector>(nodes);
    potential = std::make_unique<Vector>(nodes);
    HYPRE_BoomerAMGCreate(&amg);
    HYPRE_BoomerAMGSetCoarsenType(amg, 10);  // HMIS
    HYPRE_BoomerAMGSetInterpType(amg, 6);    // ext+i
    HYPRE_BoomerAMGSetPMaxElmts(amg, 4);
    HYPRE_BoomerAMGSetRelaxType(amg, 8);  // l1-Gauss-Seidel
    HYPRE_BoomerAMGSetStrongThreshold(amg, 0.25);
    HYPRE_BoomerAMGSetMaxIter(amg, 1);
    HYPRE_BoomerAMGSetTol(amg, 0.0);
    HYPRE_BoomerAMGSetPrintLevel(amg, 0);
    HYPRE_ParCSRPCGCreate(MPI_COMM_SELF, &laplace_pcg);
    HYPRE_PCGSetTwoNorm(laplace_pcg, 1);
    HYPRE_PCGSetTol(laplace_pcg, 1e-10);
    HYPRE_PCGSetMaxIter(laplace_pcg, 500);
    HYPRE_PCGSetPrecond(laplace_pcg, reinterpret_cast<HYPRE_PtrToSolverFcn>(HYPRE_BoomerAMGSolve),
                        reinterpret_cast<HYPRE_PtrToSolverFcn>(HYPRE_BoomerAMGSetup), amg);
    HYPRE_ParCSRPCGSetup(laplace_pcg, parcsr(laplacian), divergence->par, potential->par);
  }

  /// b minus its Euclidean projection on the kernel G_I y (G_I^T G_I y = G_I^T b).
  Eigen::VectorXd consistent(const Eigen::VectorXd& b) {
    const Eigen::VectorXd c = interior_gradient.transpose() * b;
    if (c.norm() == 0.0) return b;
    std::memcpy(divergence->data, c.data(), sizeof(double) * c.size());
    std::fill(potential->data, potential->data + c.size(), 0.0);
    HYPRE_ParCSRPCGSolve(laplace_pcg, parcsr(laplacian), divergence->par, potential->par);
    HYPRE_ClearAllErrors();
    return b - interior_gradient * Eigen::Map<const Eigen::VectorXd>(potential->data, c.size());
  }

  /// Creates the matrix with the pattern and values of `m` and finds where hypre keeps each
  /// value (it stores a row's diagonal first).
  void create(const Eigen::SparseMatrix<double>& m) {
    // Symmetric and column-major: its columns are its rows.
    const int* start = m.outerIndexPtr();
    const int* column = m.innerIndexPtr();
    matrix = make_matrix(edges, edges, start, column, m.valuePtr());
    const hypre_CSRMatrix* block = local_block(matrix);
    const HYPRE_Int* row_start = hypre_CSRMatrixI(block);
    const HYPRE_Int* col = hypre_CSRMatrixJ(block);
    std::vector<int> position(edges, -1);
    slot.resize(m.nonZeros());
    for (int r = 0; r < edges; ++r) {
      for (int p = row_start[r]; p < row_start[r + 1]; ++p) position[col[p]] = p;
      for (int q = start[r]; q < start[r + 1]; ++q) slot[q] = position[column[q]];
      for (int p = row_start[r]; p < row_start[r + 1]; ++p) position[col[p]] = -1;
    }
    if (std::find(slot.begin(), slot.end(), -1) != slot.end())
      throw ConvergenceError("AMS: hypre dropped entries of the matrix");
  }

  /// A fresh AMS set-up for the current matrix, as PCG's preconditioner.
  void build_ams() {
    if (ams) HYPRE_AMSDestroy(ams);
    HYPRE_AMSCreate(&ams);
    HYPRE_AMSSetDimension(ams, 3);
    HYPRE_AMSSetTol(ams, 0.0);
    HYPRE_AMSSetMaxIter(ams, 1);  // one cycle: a preconditioner
    HYPRE_AMSSetCycleType(ams, 13);
    HYPRE_AMSSetPrintLevel(ams, 0);
    HYPRE_AMSSetDiscreteGradient(ams, parcsr(gradient));
    HYPRE_AMSSetCoordinateVectors(ams, x->par, y->par, z->par);
    HYPRE_AMSSetBetaPoissonMatrix(ams, nullptr);  // no mass term
    HYPRE_AMSSetSmoothingOptions(ams, 2, 1, 1.0, 1.0);
    const int coarsening = 10, aggressive_levels = 1, relax = 8, interpolation = 6, p_max = 4;
    const double theta = 0.5;
    HYPRE_AMSSetAlphaAMGOptions(ams, coarsening, aggressive_levels, relax, theta, interpolation,
                                p_max);
    HYPRE_AMSSetBetaAMGOptions(ams, coarsening, aggressive_levels, relax, theta, interpolation,
                               p_max);
    HYPRE_AMSSetAlphaAMGCoarseRelaxType(ams, relax);
    HYPRE_AMSSetBetaAMGCoarseRelaxType(ams, relax);
    HYPRE_AMSSetup(ams, parcsr(matrix), b->par, solution->par);
    // The auxiliary problems are singular (no mass term): hypre's set-up may flag that, its
    // cycles handle it (MFEM's HypreAMS ignores those errors likewise).
    HYPRE_ClearAllErrors();
    if (!pcg) {
      HYPRE_ParCSRPCGCreate(MPI_COMM_SELF, &pcg);
      HYPRE_PCGSetTwoNorm(pcg, 1);  // |r| <= tol |b| in the Euclidean norm
      HYPRE_PCGSetPrintLevel(pcg, 0);
      HYPRE_PCGSetLogging(pcg, 1);
    }
    HYPRE_PCGSetPrecond(pcg, reinterpret_cast<HYPRE_PtrToSolverFcn>(HYPRE_AMSSolve),
                        keep_preconditioner, ams);
  }
};

AmsCg::AmsCg(const TetMesh& mesh, const std::vector<bool>& fixed)
    : hypre_(std::make_unique<Hypre>()) {
  ensure_hypre();
  Hypre& h = *hypre_;
  h.edges = static_cast<int>(mesh.edges.size());
  const int nodes = static_cast<int>(mesh.nodes.size());
  const Eigen::SparseMatrix<double, Eigen::RowMajor, int> g = discrete_gradient(mesh);
  h.gradient = make_matrix(h.edges, nodes, g.outerIndexPtr(), g.innerIndexPtr(), g.valuePtr());
  h.x = std::make_unique<Vector>(nodes);
  h.y = std::make_unique<Vector>(nodes);
  h.z = std::make_unique<Vector>(nodes);
  for (int n = 0; n < nodes; ++n) {
    h.x->data[n] = mesh.nodes[n].x();
    h.y->data[n] = mesh.nodes[n].y();
    h.z->data[n] = mesh.nodes[n].z();
  }
  h.b = std::make_unique<Vector>(h.edges);
  h.solution = std::make_unique<Vector>(h.edges);
  if (fixed.size() != mesh.edges.size()) throw ConvergenceError("AMS: fixed edges not per edge");
  h.build_projection(g, fixed);
}

AmsCg::~AmsCg() = default;

void AmsCg::set_matrix(const Eigen::SparseMatrix<double>& matrix) {
  Hypre& h = *hypre_;
  if (matrix.rows() != h.edges || matrix.cols() != h.edges || !matrix.isCompressed() ||
      (h.matrix && static_cast<std::size_t>(matrix.nonZeros()) != h.slot.size()))
    throw ConvergenceError("AMS: the matrix is not over the mesh's edges or changed its pattern");
  if (!h.matrix) {
    h.create(matrix);
  } else {
    double* data = hypre_CSRMatrixData(local_block(h.matrix));
    const double* value = matrix.valuePtr();
    for (std::size_t q = 0; q < h.slot.size(); ++q) data[h.slot[q]] = value[q];
  }
  const auto start = std::chrono::steady_clock::now();
  h.build_ams();
  if (setups_ == 0) HYPRE_ParCSRPCGSetup(h.pcg, parcsr(h.matrix), h.b->par, h.solution->par);
  ++setups_;
  setup_seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

magnetostatics::CgResult AmsCg::solve(const Eigen::VectorXd& b, double tolerance,
                                      int max_iterations, Eigen::VectorXd& x) {
  Hypre& h = *hypre_;
  magnetostatics::CgResult result;
  x.setZero(h.edges);
  if (setups_ == 0) throw ConvergenceError("AMS: solve before set_matrix");
  if (b.norm() == 0.0) {
    result.converged = true;
    return result;
  }
  const Eigen::VectorXd projected = h.consistent(b);
  std::memcpy(h.b->data, projected.data(), sizeof(double) * h.edges);
  std::fill(h.solution->data, h.solution->data + h.edges, 0.0);
  HYPRE_PCGSetTol(h.pcg, tolerance);
  HYPRE_PCGSetMaxIter(h.pcg, max_iterations);
  HYPRE_ParCSRPCGSolve(h.pcg, parcsr(h.matrix), h.b->par, h.solution->par);
  HYPRE_ClearAllErrors();  // a solve that stops short is reported by `converged`
  HYPRE_Int iterations = 0, converged = 0;
  HYPRE_PCGGetNumIterations(h.pcg, &iterations);
  HYPRE_PCGGetConverged(h.pcg, &converged);
  result.iterations = iterations;
  result.converged = converged != 0;
  std::memcpy(x.data(), h.solution->data, sizeof(double) * h.edges);
  return result;
}

}  // namespace rheomag::magnetostatics3d
