#include "optimise/sweep_evaluate.hpp"

#include <cstdio>
#include <sstream>

#include "magnetostatics/domain.hpp"
#include "magnetostatics/report.hpp"
#include "magnetostatics/results.hpp"
#include "mesh/error.hpp"
#include "mesh/mesher.hpp"

namespace rheomag::optimise {

namespace {

void put(std::string& s, double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%a,", v);  // exact: equal strings <=> equal doubles
  s += buffer;
}

/// True for the key of a circuit's current ("circuit.N.current").
bool is_current_key(const ResolvedKey& key) {
  return key.path.size() == 3 && key.path[0] == "circuit" && key.path[2] == "current";
}

/// The text of the base case with the design's values set, its currents too if `currents`.
std::string case_text(const SweepSpec& spec, const Design& design, bool currents) {
  toml::table table = spec.base.table;
  for (std::size_t a = 0; a < spec.axes.size(); ++a) {
    if (currents || !is_current_key(spec.axes[a].key))
      override_key(table, spec.axes[a].key, design.values[a]);
  }
  std::ostringstream text;
  text << table;
  return text.str();
}

}  // namespace

std::string design_case_text(const SweepSpec& spec, const Design& design) {
  return case_text(spec, design, true);
}

std::string geometry_signature(const magnetostatics::Problem& closed,
                               const mesh::MeshOptions& options) {
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

std::filesystem::path design_vtu_path(const std::filesystem::path& vtu_dir, long long id) {
  char name[48];
  std::snprintf(name, sizeof name, "design-%06lld.vtu", id);
  return vtu_dir / name;
}

SweepEvaluator::SweepEvaluator(const SweepSpec& spec, const RowLayout& layout,
                               std::filesystem::path vtu_dir)
    : spec_(&spec), layout_(&layout), vtu_dir_(std::move(vtu_dir)) {}

std::string SweepEvaluator::row(const Design& design) {
  try {
    return solve_row(design);
  } catch (const InputError& e) {
    return layout_->error_row(design, e.what());
  } catch (const ConvergenceError& e) {
    return layout_->error_row(design, std::string("did not converge: ") + e.what());
  } catch (const std::exception& e) {
    return layout_->error_row(design, std::string("internal error: ") + e.what());
  }
}

std::string SweepEvaluator::solve_row(const Design& design) {
  using namespace magnetostatics;
  // Every design is validated exactly as a case file.
  const Case design_case = parse_case(design_case_text(*spec_, design), spec_->base_case.string());
  std::vector<double> currents;
  for (const Circuit& circuit : design_case.problem.circuits) currents.push_back(circuit.current);
  // Same text without the currents: same problem and mesh, only the currents differ.
  const std::string solver_key = case_text(*spec_, design, false);
  if (solver_ && solver_key == solver_key_) {
    solver_->discard_factorisation();
    ++solvers_reused_;
  } else {
    solver_.reset();
    solver_key_.clear();
    Problem closed = close_domain(design_case.problem);
    mesh::MeshOptions mesh_options = options_.mesh;
    mesh_options.order = closed.order;
    mesh_options.min_gap_elements = closed.min_gap_elements;
    const std::string signature = geometry_signature(closed, mesh_options);
    std::shared_ptr<const mesh::Mesh> mesh;
    for (const auto& [key, cached] : meshes_) {
      if (key == signature) mesh = cached;
    }
    if (mesh) {
      ++reused_;
    } else {
      mesh = std::make_shared<const mesh::Mesh>(mesh::generate_mesh(closed.geometry, mesh_options));
      ++built_;
      meshes_.emplace_back(signature, mesh);
      if (meshes_.size() > kMeshCacheSize) meshes_.pop_front();
    }
    solver_ = std::make_unique<MagnetostaticSolver>(std::move(closed), *mesh, options_);
    solver_key_ = solver_key;
  }
  MagnetostaticSolver& solver = *solver_;
  const Solution solution = solver.solve(currents);
  const Results results = compute_results(solver, solution);
  const SolvedDesign solved{design_case, solver, solution, results};
  std::string line = layout_->ok_row(design, solved);
  if (!vtu_dir_.empty()) {
    write_results_vtu(design_vtu_path(vtu_dir_, design.id).string(), solver, solution, results);
  }
  return line;
}

}  // namespace rheomag::optimise
