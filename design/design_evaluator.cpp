// Cached meshes are keyed by the exact mesher input; morphed meshes follow the geometry's
// breakpoints (morph_mesh.hpp).

#include "design/design_evaluator.hpp"

#include <cstdio>

#include "magnetostatics/domain.hpp"
#include "mesh/mesher.hpp"

namespace rheomag::design {

namespace {

void put(std::string& s, double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%a,", v);  // exact: equal strings <=> equal doubles
  s += buffer;
}

}  // namespace

std::string geometry_signature(const cases::Problem& closed, const mesh::MeshOptions& options) {
  const mesh::Pslg& g = closed.geometry;
  std::string s = "order " + std::to_string(closed.order) + " gap " +
                  std::to_string(closed.min_gap_elements) + " default " +
                  std::to_string(g.default_region) + " ";
  put(s, options.min_angle);
  put(s, options.default_size);
  put(s, options.grading);
  s += std::to_string(options.max_elements) + "\npoints ";
  for (const mesh::Point& p : g.points) {
    put(s, p.r);
    put(s, p.z);
  }
  s += "\nsegments ";
  for (const mesh::Segment& seg : g.segments) {
    s += std::to_string(seg.a) + "," + std::to_string(seg.b) + "," + std::to_string(seg.boundary) +
         ",";
    put(s, seg.max_length);
  }
  s += "\nregions ";
  for (const mesh::RegionSeed& r : g.regions) {
    put(s, r.seed.r);
    put(s, r.seed.z);
    put(s, r.mesh_size);
    s += std::to_string(static_cast<int>(r.gap)) + (r.hole ? "h" : "m") + r.name + "\n";
  }
  return s;
}

DesignEvaluator::DesignEvaluator(MeshPolicy policy, magnetostatics::SolveOptions options)
    : policy_(policy), options_(std::move(options)) {}

std::shared_ptr<const mesh::Mesh> DesignEvaluator::mesh_for(const cases::Problem& closed) {
  mesh::MeshOptions mesh_options = options_.mesh;
  mesh_options.order = closed.order;
  mesh_options.min_gap_elements = closed.min_gap_elements;
  if (policy_ == MeshPolicy::morphed) {
    return nullptr;  // handled by solve(): the morph needs the design's own breakpoints
  }
  const std::string signature = geometry_signature(closed, mesh_options);
  for (const auto& [key, cached] : cache_)
    if (key == signature) {
      ++reused_;
      return cached;
    }
  auto mesh =
      std::make_shared<const mesh::Mesh>(mesh::generate_mesh(closed.geometry, mesh_options));
  ++built_;
  cache_.emplace_back(signature, mesh);
  if (cache_.size() > kMeshCacheSize) cache_.pop_front();
  return mesh;
}

const EvaluatedField& DesignEvaluator::solve(const cases::Case& design,
                                             const std::vector<double>& currents, bool same_problem,
                                             const ProblemAdjustment& adjust,
                                             const Eigen::VectorXd* initial_guess) {
  using magnetostatics::MagnetostaticSolver;
  if (same_problem && last_.solver) {
    last_.solver->discard_factorisation();
    ++solvers_reused_;
  } else {
    last_.solver.reset();
    cases::Problem closed = magnetostatics::close_domain(design.problem);
    mesh::Mesh mesh;
    if (policy_ == MeshPolicy::cached) {
      mesh = *mesh_for(closed);
    } else {
      const Breakpoints breakpoints = geometry_breakpoints(design.problem.geometry);
      std::optional<mesh::Mesh> morphed;
      if (have_reference_)
        morphed = morph_mesh(reference_mesh_, reference_breakpoints_, breakpoints);
      if (morphed) {
        mesh = std::move(*morphed);
      } else {
        mesh::MeshOptions mesh_options = options_.mesh;
        mesh_options.order = closed.order;
        mesh_options.min_gap_elements = closed.min_gap_elements;
        reference_mesh_ = mesh::generate_mesh(closed.geometry, mesh_options);
        reference_breakpoints_ = breakpoints;
        have_reference_ = true;
        ++built_;
        initial_guess = nullptr;  // a new mesh: another numbering
        mesh = reference_mesh_;
      }
    }
    if (adjust) adjust(closed, mesh);
    last_.solver =
        std::make_shared<MagnetostaticSolver>(std::move(closed), std::move(mesh), options_);
  }
  if (policy_ == MeshPolicy::cached ||
      (initial_guess &&
       static_cast<std::size_t>(initial_guess->size()) != last_.solver->mesh().nodes.size()))
    initial_guess = nullptr;  // another mesh
  last_.solution = last_.solver->solve(currents, initial_guess);
  ++fe_solves_;
  last_.results = magnetostatics::compute_results(*last_.solver, last_.solution);
  return last_;
}

}  // namespace rheomag::design
