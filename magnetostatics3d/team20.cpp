#include "magnetostatics3d/team20.hpp"

#include <algorithm>
#include <chrono>

#include "magnetostatics/reluctivity.hpp"
#include "magnetostatics3d/body_force.hpp"
#include "magnetostatics3d/edge_solver.hpp"

namespace rheomag::magnetostatics3d {
namespace {

constexpr double kMm = 1e-3;
constexpr double kTurns = 1000.0;
enum Team20Region { kAir = 0, kYoke = 1, kPole = 2 };

/// The steel's B-H table of the problem's definition (B [T], H [A/m]).
cases::Material team20_steel() {
  cases::Material steel;
  steel.name = "TEAM 20 steel";
  steel.source = "TEAM problem 20 definition, B-H table";
  steel.bh = {{0.0, 0.0},      {0.01, 27.0},     {0.025, 58.0},   {0.05, 100.0},   {0.1, 153.0},
              {0.15, 185.0},   {0.2, 205.0},     {0.3, 233.0},    {0.4, 255.0},    {0.5, 285.0},
              {0.6, 320.0},    {0.7, 355.0},     {0.8, 405.0},    {0.9, 470.0},    {1.0, 555.0},
              {1.1, 673.0},    {1.2, 836.0},     {1.3, 1065.0},   {1.35, 1220.0},  {1.4, 1420.0},
              {1.45, 1720.0},  {1.5, 2130.0},    {1.55, 2670.0},  {1.6, 3480.0},   {1.65, 4500.0},
              {1.7, 5950.0},   {1.75, 7650.0},   {1.8, 10100.0},  {1.85, 13000.0}, {1.9, 15900.0},
              {1.95, 21100.0}, {2.0, 26300.0},   {2.05, 32900.0}, {2.1, 42700.0},  {2.15, 61700.0},
              {2.2, 84300.0},  {2.25, 110000.0}, {2.3, 135000.0}};
  return steel;
}

Eigen::AlignedBox3d box_mm(double x0, double y0, double z0, double x1, double y1, double z1) {
  return {Eigen::Vector3d(x0, y0, z0) * kMm, Eigen::Vector3d(x1, y1, z1) * kMm};
}

}  // namespace

BandCoil team20_coil() {
  BandCoil c;
  c.half_x = c.half_y = 37.5 * kMm;
  c.corner_radius = 23.0 * kMm;
  c.width = 18.0 * kMm;
  c.z0 = 26.7 * kMm;
  c.z1 = 123.3 * kMm;
  c.turns = kTurns;
  return c;
}

GridSpec team20_grid(const Team20Options& options) {
  const double h = options.step;
  const double gap = std::min(0.5 * h, 0.75 * kMm);  // two or more layers across the 1.5 mm gap
  const double side = std::min(h, 1.0 * kMm);        // the 1 mm gap beside the pole's top
  GridSpec g;
  g.lines[0] = graded_axis(0.0, {{12.5 * kMm, h, h},
                                 {13.5 * kMm, side, side},
                                 {38.5 * kMm, h, 2 * h},
                                 {63.5 * kMm, 2 * h, 2 * h},
                                 {200 * kMm, 2 * h, 8 * h}});
  g.lines[1] = graded_axis(
      0.0,
      {{5 * kMm, h, h}, {12.5 * kMm, h, h}, {37.5 * kMm, h, 2 * h}, {250 * kMm, 2 * h, 10 * h}});
  g.lines[2] = graded_axis(-100 * kMm, {{0.0, 10 * h, 2 * h},
                                        {25 * kMm, 2 * h, gap},
                                        {26.5 * kMm, gap, gap},
                                        {75 * kMm, gap, 2 * h},
                                        {125 * kMm, 2 * h, side},
                                        {150 * kMm, side, 2 * h},
                                        {250 * kMm, 2 * h, 10 * h}});
  g.boxes = {{box_mm(0, 0, 0, 63.5, 12.5, 25), kYoke},
             {box_mm(38.5, 0, 25, 63.5, 12.5, 150), kYoke},
             {box_mm(13.5, 0, 125, 63.5, 12.5, 150), kYoke},
             {box_mm(0, 0, 26.5, 12.5, 5, 125), kPole}};
  g.background_region = kAir;
  g.sides = {FaceKind::symmetry, FaceKind::outer, FaceKind::symmetry,
             FaceKind::outer,    FaceKind::outer, FaceKind::outer};
  return g;
}

std::vector<Team20Result> solve_team20(const std::vector<double>& ampere_turns,
                                       const Team20Options& options) {
  const auto start = std::chrono::steady_clock::now();
  const TetMesh mesh = grid_mesh(team20_grid(options));
  cases::Material air;
  air.name = "air";
  std::vector<magnetostatics::Reluctivity> laws{magnetostatics::Reluctivity(air),
                                                magnetostatics::Reluctivity(team20_steel())};
  EdgeSolver solver(mesh, std::move(laws), {0, 1, 1},
                    Eigen::VectorXd::Zero(static_cast<Eigen::Index>(mesh.edges.size())),
                    {band_coil_loads(team20_coil(), mesh)}, options.newton);
  // The quarter model holds a quarter of the force, the flux linkage and the pole's volume.
  std::vector<Team20Result> out;
  for (double at : ampere_turns) {
    const EdgeSolution s = solver.solve({at / kTurns});
    Team20Result r;
    r.ampere_turns = at;
    r.force_z = 4.0 * body_force(mesh, s.b, {false, false, true}, {true, false, false})[2];
    r.flux_linkage = 4.0 * solver.load(0).dot(s.a);
    double volume = 0.0, bz = 0.0;
    for (int t = 0; t < static_cast<int>(mesh.tets.size()); ++t)
      if (mesh.region[t] == kPole) {
        volume += mesh.volume(t);
        bz += mesh.volume(t) * s.b[t][2];
      }
    r.pole_mean_bz = bz / volume;
    r.tetrahedra = mesh.tets.size();
    r.dofs = solver.dofs().free_count();
    r.newton_iterations = s.newton.iterations;
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    out.push_back(r);
  }
  return out;
}

}  // namespace rheomag::magnetostatics3d
