// Tabulation of a case's steady valve map with the fluid chain (one FE solve per current): a
// valve case through ValveChain, a damper piston case ([damper] table) through DamperChain.

#include "coupling/valve_chain_tabulation.hpp"

#include <cmath>

#include "case/case_file.hpp"
#include "core/error.hpp"
#include "valve/damper.hpp"
#include "valve/valve_chain.hpp"

namespace rheomag::coupling {

std::shared_ptr<const lumped::ChainMapTable> tabulate_valve_chain(const std::string& case_file,
                                                                  double max_current,
                                                                  double max_flow,
                                                                  int current_points,
                                                                  int flow_points) {
  if (!(max_current > 0.0) || !(max_flow > 0.0) || current_points < 2 || flow_points < 2)
    throw InputError(case_file + ": the valve map needs a current range > 0 A and a flow > 0");
  const auto c = cases::load_case(case_file);
  auto table = std::make_shared<lumped::ChainMapTable>();
  table->case_file = case_file;
  for (int i = 0; i < current_points; ++i)
    table->current.push_back(max_current * i / (current_points - 1));
  // Log-spaced flows: the yield part varies with the Bingham number, i.e. with log Q.
  const double q_lo = 1e-3 * max_flow, q_hi = 1.5 * max_flow;
  for (int k = 0; k < flow_points; ++k)
    table->flow.push_back(q_lo * std::pow(q_hi / q_lo, static_cast<double>(k) / (flow_points - 1)));
  double resistance = 0.0;
  std::size_t count = 0;
  if (c.table.contains("damper")) {
    // A damper piston case: the pressure equivalent of the damping force, (F - F_gas) / A_eff,
    // at the piston velocity that makes each flow (mixed-mode gaps, wall shear included); its
    // tau_y = 0 gap drop is linear in the velocity, so R is again one ratio.
    valve::DamperChain chain(c, valve::read_damper_options(c));
    for (const auto& p : chain.evaluate_flows(table->current, table->flow)) {  // current-major
      const double area = p.flow / p.velocity;
      table->yield.push_back((p.force - p.force_gas) / area - p.dp_viscous);
      resistance += p.dp_viscous / p.flow;
      ++count;
    }
  } else {
    valve::ValveChain chain(c, valve::read_valve_options(c));
    for (const auto& p : chain.evaluate(table->current, table->flow)) {  // current-major
      table->yield.push_back(p.dp_yield);
      resistance += p.dp_viscous / p.flow;  // Poiseuille: the same ratio at every point
      ++count;
    }
  }
  table->viscous_resistance = resistance / static_cast<double>(count);
  return table;
}

}  // namespace rheomag::coupling
