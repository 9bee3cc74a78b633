#pragma once
// Steady and transient heat conduction on a problem's mesh (axisymmetric or planar, P1 or P2):
//   div(k grad T) + q = rho c_p dT/dt  in the active regions,
// convection, a fixed temperature or insulation on their outer surfaces, symmetry on the axis.
// The matrices are assembled once; CHOLMOD's symbolic analysis is done once per solver and its
// factorisation once per steady solve or time step size, so new sources cost a substitution.

#include <Eigen/CholmodSupport>
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "case/problem.hpp"
#include "mesh/mesh.hpp"
#include "thermal/heat_model.hpp"

namespace rheomag::thermal {

/// Temperature of one region.
struct RegionTemperature {
  double mean = 0.0;    ///< volume average [deg C]
  double max = 0.0;     ///< largest nodal value [deg C]
  double volume = 0.0;  ///< [m^3] (planar: per `depth`)
};

/// A temperature field and its heat balance.
struct HeatSolution {
  double time = 0.0;                       ///< [s] (0 for a steady solution)
  Eigen::VectorXd temperature;             ///< per mesh node [deg C]; NaN outside the model
  std::vector<RegionTemperature> regions;  ///< per region (zeros for inactive ones)
  std::vector<double> surface_heat_flow;   ///< per HeatModel surface, out of the model [W]
  double source_power = 0.0;               ///< heat generated, integral q dV [W]
  double storage_power = 0.0;              ///< d/dt of the stored heat [W] (0 when steady)
  double exchange_heat_flow = 0.0;         ///< carried away by fluid flowing through regions [W]
  /// source_power - sum(surface_heat_flow) - exchange - storage, relative to source_power
  /// (or 1 W).
  double balance_error() const;
};

/// Volume of each region of `mesh` [m^3] (planar: times `depth`); index as Problem::regions.
std::vector<double> region_volumes(const cases::Problem& problem, const mesh::Mesh& mesh);

/// The temperature of nodal field `temperature` at point `p` (the shape functions of the
/// triangle holding it); NaN outside the mesh or the thermal model.
double temperature_at(const mesh::Mesh& mesh, const Eigen::VectorXd& temperature, mesh::Point p);

/// Heat conduction on one mesh with one HeatModel.
class HeatSolver {
 public:
  /// Sets up the active nodes, outer edges and matrices. InputError when no region is active,
  /// an active region has a conductivity or heat capacity <= 0, or the model has no surface
  /// that fixes the temperature level (all insulated: no steady state).
  HeatSolver(const cases::Problem& problem, const mesh::Mesh& mesh, HeatModel model);
  HeatSolver(const HeatSolver&) = delete;
  HeatSolver& operator=(const HeatSolver&) = delete;
  ~HeatSolver();

  /// Replaces each region's heat source [W/m^3] (index as Problem::regions).
  void set_sources(const std::vector<double>& region_source);
  /// The steady temperature under the current sources.
  HeatSolution steady();
  /// Called with each state of a transient; return false to stop early.
  using Observer = std::function<bool(const HeatSolution&)>;
  /// Integrates from `initial` (per node, deg C; NaN outside the model is fine) over `steps`
  /// steps of `dt` seconds (BDF2, its first step backward Euler), calling `observe` with the
  /// initial state and every step; `observe` may call set_sources for the steps that follow
  /// (sources that follow the temperature). Returns the last state.
  HeatSolution transient(const Eigen::VectorXd& initial, double dt, int steps,
                         const Observer& observe);
  /// A uniform field at `celsius` over the model (NaN outside): a transient's usual start.
  Eigen::VectorXd uniform(double celsius) const;
  /// The balance and region temperatures of a nodal field (its rate `rate` [K/s] per node, or
  /// an empty vector when steady).
  HeatSolution evaluate(const Eigen::VectorXd& temperature, const Eigen::VectorXd& rate) const;
  /// Heat capacity of each region, integral rho c_p dV [J/K] (index as Problem::regions).
  std::vector<double> region_heat_capacity() const;
  /// The model it solves.
  const HeatModel& model() const { return model_; }
  /// Number of unknown temperatures.
  int unknowns() const { return static_cast<int>(node_of_free_.size()); }

 private:
  using Matrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;
  using Factor = Eigen::CholmodSupernodalLLT<Matrix, Eigen::Lower>;
  struct OuterEdge {
    std::array<int, 3> nodes{-1, -1, -1};
    int surface = -1;
  };
  void find_outer_edges();
  void assemble();
  Eigen::VectorXd load() const;       // sources and convection to ambient, per active node
  Eigen::VectorXd free_load() const;  // load() on the free rows, minus the fixed values' share
  Eigen::VectorXd fixed_values() const;
  Eigen::VectorXd to_nodes(const Eigen::VectorXd& free_values) const;
  Factor& factor_for(double mass_scale);  // factor of K_ff + mass_scale M_ff

  const cases::Problem& problem_;
  const mesh::Mesh& mesh_;
  HeatModel model_;
  std::vector<int> active_of_node_;  // index among active nodes, -1 outside the model
  std::vector<int> node_of_active_;
  std::vector<int> free_of_active_;  // -1 for nodes of fixed-temperature surfaces
  std::vector<int> node_of_free_;
  std::vector<int> fixed_surface_of_active_;  // surface fixing the node, -1 if free
  std::vector<OuterEdge> outer_edges_;
  Matrix stiffness_, mass_;                   // over active nodes (full symmetric storage)
  Matrix stiffness_free_, mass_free_;         // free x free
  Matrix stiffness_coupling_;                 // free x fixed-node (active numbering) coupling
  std::vector<Eigen::VectorXd> region_load_;  // integral N_i dV of each active region
  Eigen::VectorXd exchange_load_;             // integral beta T_in N_i dV
  Eigen::VectorXd convection_load_;           // integral h T_amb N_i dA
  std::unique_ptr<Factor> factor_;
  double factor_scale_ = -1.0;
};

}  // namespace rheomag::thermal
