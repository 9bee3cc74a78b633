#pragma once
// Shared scaffolding of the optimise tests: the coarse annular valve case, temporary output
// directories, a run of `rheomag optimise` into one, and the analytic magnetic-circuit valve.

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include "case/case_file.hpp"
#include "core/error.hpp"
#include "optimise/evaluate.hpp"
#include "optimise/run.hpp"
#include "optimise/spec.hpp"

namespace optimise_fixture {

namespace fs = std::filesystem;
using namespace rheomag;

// Paper 000's annular valve on a coarse P1 mesh (1 element across the gap) so each FE solve is
// fast; the [optimise] table is appended per test.
inline const std::string kBase = R"(
[case]
name = "coarse_annular"
units = "mm"
fluid = "MRC-C1L"
[geometry]
template = "annular_valve"
neck_radius = 10.5
pole_length = 5.0
coil_length = 32.0
turns = 600
[[circuit]]
name = "coil"
current = 1.0
[solver]
order = 1
min_gap_elements = 1
outer_radius_factor = 3.0
[valve]
wire = "AWG 24"
)";

// Neck radius and pole length, dp_on maximised at 1 A and 6.91 ml/s.
inline const std::string kTwoVariables = R"(
[optimise]
objective = "dp_on"
current = 1.0
flow = 6.91e-6
max_iterations = 12
[[optimise.variable]]
key = "geometry.neck_radius"
lower = 8.0
upper = 12.5
[[optimise.variable]]
key = "geometry.pole_length"
lower = 3.0
upper = 8.0
)";

// L/R <= 50 ms: below the initial design's 68 ms, so it binds.
inline const std::string kTimeConstant = R"(
[[optimise.constraint]]
quantity = "time_constant"
max = 0.05
)";

// L/R <= 50 ms and length <= 43 mm (the initial design has 44 mm).
inline const std::string kTimeAndLength = kTimeConstant + R"(
[[optimise.constraint]]
quantity = "length"
max = 0.043
)";

/// The coarse case with `optimise` appended.
inline cases::Case make_case(const std::string& optimise) {
  return cases::parse_case(kBase + optimise, "coarse_annular.toml");
}

/// The InputError message of reading the [optimise] table `optimise` (appended to the coarse
/// case) and setting up its evaluator; "" if there is none.
inline std::string input_error(const std::string& optimise) {
  try {
    const auto c = make_case(optimise);
    optimise::OptimiseEvaluator evaluator(c, optimise::read_optimise_spec(c));
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

/// A fresh, empty temporary directory, removed when the object goes.
struct TempDir {
  fs::path path;
  explicit TempDir(const std::string& name)
      : path(fs::temp_directory_path() /
             ("rheomag_optimise_" + name + "_" + std::to_string(::getpid()))) {
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~TempDir() { fs::remove_all(path); }
};

/// run_optimisation of `c` writing into `dir`.
inline optimise::OptimiseResult run(const cases::Case& c, const TempDir& dir) {
  optimise::OptimiseOptions options;
  options.out_dir = dir.path;
  return optimise::run_optimisation(c, options);
}

/// Analytic magnetic-circuit valve: two pole gaps of width h in series, the steel ideal, so
/// B = mu0 N I / (2 h); linear fluid tau_y = k B; yield pressure drop of the two poles of length
/// L (slit limit, c = 2): dp = 2 c tau_y L / h = gain N L, gain = 2 c k mu0 I / h^2. Length
/// 2 L + a N (a = axial winding length per turn); time constant proportional to N (L ~ N^2,
/// R ~ N): tau = b N.
struct MagneticCircuitValve {
  double mu0 = 4e-7 * std::numbers::pi, k = 5e4, c = 2.0, current = 1.0, h = 1e-3;
  double l_max = 0.044, a = 5e-5, b = 1e-4;  // 44 mm envelope; 0.05 mm per turn; 0.1 ms/turn
  double gain() const { return 2.0 * c * k * mu0 * current / (h * h); }
  /// Quantities of design x = (pole length L [m], turns N).
  design::Quantities quantities(const std::vector<double>& x) const {
    design::Quantities q;
    q[design::Quantity::dp_on] = gain() * x[0] * x[1];
    q[design::Quantity::length] = 2.0 * x[0] + a * x[1];
    q[design::Quantity::time_constant] = b * x[1];
    return q;
  }
  /// Spec: maximise dp_on over L in [1, 20] mm, N in [50, 800], length <= l_max.
  optimise::OptimiseSpec spec() const {
    optimise::OptimiseSpec s;
    s.variables = {{"pole_length", {}, 1e-3, 20e-3, 5e-3}, {"turns", {}, 50.0, 800.0, 200.0}};
    optimise::Constraint envelope;
    envelope.quantity = design::Quantity::length;
    envelope.upper = l_max;
    s.constraints = {envelope};
    s.terms = {{design::Quantity::dp_on, 1.0, 1.0}};
    s.tolerance = 1e-9;
    s.max_iterations = 200;
    return s;
  }
};

}  // namespace optimise_fixture
