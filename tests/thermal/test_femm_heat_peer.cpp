// Side by side with FEMM's heat-flow solver (xfemm's femmcli, hsolver inside, built from source
// outside the repository as docs/femm.md says; the test runs when RHEOMAG_FEMMCLI names it): an
// axisymmetric steel body (k 40 W/(m K), r 0-30 mm, z 0-20 mm) holding a heated winding block
// (k 0.8 W/(m K), 2 MW/m^3, r 10-20 mm, z 5-12 mm), convection h = 15 W/(m^2 K) to 20 C on the
// rim and the top, the bottom insulated. The same model is written as FEMM Lua, solved by both,
// and the temperature rises at three points must agree within 1 % (issue 32).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "mesh/mesher.hpp"
#include "thermal/heat_solver.hpp"

namespace rheomag::thermal {
namespace {

namespace fs = std::filesystem;

constexpr double kB = 0.03, kH = 0.02;                              // body [m]
constexpr double kR0 = 0.01, kR1 = 0.02, kZ0 = 0.005, kZ1 = 0.012;  // winding block [m]
constexpr double kKBody = 40.0, kKCoil = 0.8, kQ = 2e6, kHConv = 15.0, kAmbient = 20.0;
const std::vector<mesh::Point> kProbes{{0.0001, 0.01}, {0.015, 0.0085}, {0.025, 0.015}};

cases::Problem body_problem() {
  cases::Problem p;
  p.symmetry = cases::Symmetry::axisymmetric;
  p.outer = cases::OuterBoundary::none;
  p.boundaries = {{"convection"}, {"insulated"}};
  cases::Material m;
  m.name = "body";
  p.materials = {m};
  p.geometry.source = "peer body";
  p.geometry.points = {{0, 0},     {kB, 0},    {kB, kH},   {0, kH},
                       {kR0, kZ0}, {kR1, kZ0}, {kR1, kZ1}, {kR0, kZ1}};
  p.geometry.segments = {{0, 1, 1},  {1, 2, 0},  {2, 3, 0},  {3, 0, -1},
                         {4, 5, -1}, {5, 6, -1}, {6, 7, -1}, {7, 4, -1}};
  mesh::RegionSeed body, coil;
  body.seed = {0.005, 0.015};
  body.name = "body";
  body.mesh_size = 0.0007;
  coil.seed = {0.015, 0.008};
  coil.name = "coil";
  coil.mesh_size = 0.0004;
  p.geometry.regions = {body, coil};
  p.regions = {{0}, {0}};
  return p;
}

/// FEMM's temperatures [K] at kProbes from a Lua model of the same body.
std::vector<double> femm_temperatures(const std::string& femmcli, const fs::path& dir) {
  std::ofstream lua(dir / "heat.lua");
  lua.precision(17);
  lua << "newdocument(2)\nhi_probdef(\"meters\", \"axi\", 1e-10, 1, 25)\n"
      << "hi_addmaterial(\"body\", " << kKBody << ", " << kKBody << ", 0, 0)\n"
      << "hi_addmaterial(\"coil\", " << kKCoil << ", " << kKCoil << ", " << kQ << ", 0)\n"
      << "hi_addboundprop(\"conv\", 2, 0, 0, " << kAmbient + 273.15 << ", " << kHConv << ", 0)\n";
  const auto rectangle = [&](double r0, double z0, double r1, double z1) {
    lua << "hi_addnode(" << r0 << "," << z0 << ") hi_addnode(" << r1 << "," << z0 << ") hi_addnode("
        << r1 << "," << z1 << ") hi_addnode(" << r0 << "," << z1 << ")\n"
        << "hi_addsegment(" << r0 << "," << z0 << "," << r1 << "," << z0 << ") "
        << "hi_addsegment(" << r1 << "," << z0 << "," << r1 << "," << z1 << ") "
        << "hi_addsegment(" << r1 << "," << z1 << "," << r0 << "," << z1 << ") "
        << "hi_addsegment(" << r0 << "," << z1 << "," << r0 << "," << z0 << ")\n";
  };
  rectangle(0, 0, kB, kH);
  rectangle(kR0, kZ0, kR1, kZ1);
  lua << "hi_selectsegment(" << kB << "," << kH / 2 << ") hi_selectsegment(" << kB / 2 << "," << kH
      << ")\nhi_setsegmentprop(\"conv\", 0.0003, 0, 0, 0, \"<None>\")\nhi_clearselected()\n"
      << "hi_addblocklabel(0.005,0.015) hi_selectlabel(0.005,0.015) "
      << "hi_setblockprop(\"body\", 0, 0.0004, 0) hi_clearselected()\n"
      << "hi_addblocklabel(0.015,0.008) hi_selectlabel(0.015,0.008) "
      << "hi_setblockprop(\"coil\", 0, 0.0002, 0) hi_clearselected()\n"
      << "hi_saveas(\"heat.feh\")\nhi_analyze()\nhi_loadsolution()\n";
  for (std::size_t k = 0; k < kProbes.size(); ++k)
    lua << "print(\"T" << k << "\", ho_getpointvalues(" << kProbes[k].r << ", " << kProbes[k].z
        << "))\n";
  lua << "quit()\n";
  lua.close();
  const std::string command =
      "cd '" + dir.string() + "' && '" + femmcli + "' --lua-script=heat.lua 2>&1";
  std::map<std::string, double> values;
  FILE* pipe = popen(command.c_str(), "r");
  char line[512];
  while (pipe && std::fgets(line, sizeof line, pipe)) {
    std::istringstream in(line);
    std::string key;
    double value = 0.0;
    if (in >> key >> value) values[key] = value;
  }
  if (pipe) pclose(pipe);
  std::vector<double> t;
  for (std::size_t k = 0; k < kProbes.size(); ++k) {
    const auto it = values.find("T" + std::to_string(k));
    t.push_back(it == values.end() ? NAN : it->second);
  }
  return t;
}

TEST(FemmHeatPeer, TemperatureRisesAgreeWithin1Percent) {
  const char* femmcli = std::getenv("RHEOMAG_FEMMCLI");
  if (!femmcli || !fs::exists(femmcli))
    GTEST_SKIP() << "set RHEOMAG_FEMMCLI to xfemm's femmcli (built as docs/femm.md says) to "
                    "compare with FEMM's heat-flow solver";
  const cases::Problem problem = body_problem();
  mesh::MeshOptions options;
  options.order = 2;
  const mesh::Mesh mesh = mesh::generate_mesh(problem.geometry, options);
  HeatModel model;
  model.regions = {{true, kKBody, 3.5e6, 0.0}, {true, kKCoil, 2e6, kQ}};
  model.surfaces = {{"convection", SurfaceKind::convection, kHConv, kAmbient},
                    {"insulated", SurfaceKind::insulated}};
  model.surface_of_region = {1, 1};  // edges without a marker (none here but the axis) insulated
  model.surface_of_boundary = {0, 1};
  HeatSolver solver(problem, mesh, model);
  const HeatSolution s = solver.steady();
  const fs::path dir = fs::temp_directory_path() / "rheomag_femm_heat_peer";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::vector<double> femm = femm_temperatures(femmcli, dir);
  for (std::size_t k = 0; k < kProbes.size(); ++k) {
    ASSERT_TRUE(std::isfinite(femm[k])) << "femmcli printed no temperature " << k;
    const double ours = temperature_at(mesh, s.temperature, kProbes[k]) - kAmbient;
    const double theirs = femm[k] - 273.15 - kAmbient;
    EXPECT_NEAR(ours, theirs, 0.01 * std::abs(theirs))
        << "probe " << k << " (r " << kProbes[k].r << ", z " << kProbes[k].z << ")";
    std::printf("probe %zu: rheomag rise %.6f K, FEMM %.6f K (%+.3f %%)\n", k, ours, theirs,
                100.0 * (ours - theirs) / theirs);
  }
}

}  // namespace
}  // namespace rheomag::thermal
