#pragma once
// The options of `rheomag solve` (app/cmd_solve.cpp) and its --3d branch (app/solve_3d.cpp).

#include <optional>
#include <string>
#include <vector>

#include "case/case_file.hpp"

namespace rheomag::app {

/// What `rheomag solve` was asked on its command line.
struct SolveCommandOptions {
  std::string case_path;
  std::vector<std::string> settings;  // --set KEY=VALUE
  std::vector<double> currents;       // --current: one, or a list solved in turn [A]
  std::vector<double> sweep;
  std::string vtk, ans, plot;  // .vtu, FEMM .ans, picture (.png / .svg)
  std::optional<int> order;
  std::vector<double> points;          // r1, z1, r2, z2, ... [m]
  std::vector<std::string> integrals;  // REGION:KIND
  std::vector<std::string> lines;      // x1,y1:x2,y2
  int line_points = 101;
  bool json = false, three_d = false, full = false;
  std::string mesher = "tetgen";
  std::string linear_solver = "cholmod";  // --3d: LinearSolver3d by name
  std::string max_memory;                 // --max-memory text ("8G"); empty: the default limit
};

/// `solve --3d`: the case revolved about z with its [[feature]] cuts (magnetostatics3d).
void run_solve_3d(const SolveCommandOptions& o, const cases::Case& c);

}  // namespace rheomag::app
