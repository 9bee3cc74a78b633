#include "optimise/pareto_front.hpp"

#include <algorithm>

#include <unistd.h>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/interrupt.hpp"
#include "optimise/problem.hpp"

namespace rheomag::optimise {

namespace {
// SI unit of the quantity named `name` ("-" for a weighted sum).
std::string unit_of(const std::string& name) {
  const auto q = design::kQuantityNames.find(name);
  return q ? std::string(design::quantity_unit(*q)) : "-";
}

// A CSV cell: empty for a quantity the design does not give.
std::string cell(double v) {
  return std::isnan(v) ? std::string() : number_text(v);
}
}  // namespace

OptimiseSpec second_objective_spec(const OptimiseSpec& spec) {
  OptimiseSpec second = spec;
  second.objective = design::quantity_name(spec.pareto->quantity);
  second.terms = {ObjectiveTerm{spec.pareto->quantity, 1.0, 1.0}};
  second.maximise = spec.pareto->maximise;
  second.pareto.reset();
  return second;
}

ParetoFront pareto_front(const OptimiseSpec& spec, const DesignReport& objective_alone,
                         const OptimiseFrom& optimise, const std::function<int()>& solves) {
  ParetoFront front;
  front.pareto = *spec.pareto;
  front.objective_alone = objective_alone;
  const design::Quantity name = front.pareto.quantity;
  const double first_level = quantity_value(objective_alone.quantities, name);
  const double scale = std::abs(first_level) > 0.0 ? std::abs(first_level) : 1.0;
  front.second_alone = optimise(second_objective_spec(spec), objective_alone.x, scale);
  const double last_level = quantity_value(front.second_alone.quantities, name);

  const int n = front.pareto.points;
  const double objective_scale =
      std::abs(objective_alone.objective) > 0.0 ? std::abs(objective_alone.objective) : 1.0;
  std::vector<double> start = objective_alone.x;
  for (int k = 0; k < n; ++k) {
    ParetoPoint point;
    point.epsilon = first_level + (last_level - first_level) * k / (n - 1);
    if (k == 0) {  // the objective's own optimum satisfies its own level
      point.design = objective_alone;
    } else if (k == n - 1 && front.second_alone.strict_vertex) {
      // At the second objective's own level, a strict vertex is the only design in the box:
      // it is reported for the objective, with its transient check if it had one.
      const DesignReport& vertex = front.second_alone;
      point.design = report_design(spec, vertex.x, vertex.quantities);
      point.design.response_time_transient = vertex.response_time_transient;
      point.design.strict_vertex = true;
    } else {
      OptimiseSpec level = spec;
      level.pareto.reset();
      Constraint limit;
      limit.quantity = name;
      (front.pareto.maximise ? limit.lower : limit.upper) = point.epsilon;
      limit.where = "optimise.pareto level " + std::to_string(k + 1);
      level.constraints.push_back(limit);
      const int before = solves();
      // Predicted start: along the line from the previous level's optimum to the second
      // objective's, as far as this level is from the previous towards the last (the last
      // level starts on that optimum).
      const double previous = front.points.back().epsilon;
      const double along =
          last_level != previous
              ? std::clamp((point.epsilon - previous) / (last_level - previous), 0.0, 1.0)
              : 1.0;
      for (std::size_t i = 0; i < start.size(); ++i)
        start[i] += along * (front.second_alone.x[i] - start[i]);
      point.design = optimise(level, start, objective_scale);
      point.fe_solves = solves() - before;
      point.design.constraints.pop_back();  // report against the spec's own constraints
      start = point.design.x;
    }
    front.points.push_back(std::move(point));
  }
  return front;
}

std::string pareto_csv(const OptimiseSpec& spec, const ParetoFront& front) {
  std::ostringstream out;
  const std::string second = design::quantity_name(front.pareto.quantity);
  out << "epsilon " << second << ",objective " << spec.objective << "," << second
      << ",feasible,fe_solves";
  for (const auto& v : spec.variables) out << "," << v.key;
  for (design::Quantity q : design::all_quantities())
    out << "," << design::quantity_name(q) << " [" << design::quantity_unit(q) << "]";
  out << "\n";
  for (const auto& p : front.points) {
    const auto& q = p.design.quantities;
    out << number_text(p.epsilon) << "," << number_text(p.design.objective) << ","
        << cell(q[front.pareto.quantity]) << "," << (p.design.feasible ? 1 : 0) << ","
        << p.fe_solves;
    for (double x : p.design.x) out << "," << number_text(x);
    for (design::Quantity k : design::all_quantities()) out << "," << cell(q[k]);
    out << "\n";
  }
  return out.str();
}

std::vector<std::filesystem::path> write_pareto(const std::filesystem::path& dir,
                                                const OptimiseSpec& spec,
                                                const ParetoFront& front) {
  std::vector<std::filesystem::path> written;
  const auto csv = dir / "pareto.csv";
  write_file_atomically(csv, pareto_csv(spec, front));
  written.push_back(csv);
  if (std::system("command -v gnuplot > /dev/null 2>&1") != 0) return written;
  // gnuplot writes the picture to the atomic writer's temporary file.
  const auto png = dir / "pareto.png";
  const auto script = dir / ("pareto.gp.tmp-" + std::to_string(::getpid()));
  const InterruptCleanupFile script_removed_if_interrupted(script);
  const std::string second = design::quantity_name(front.pareto.quantity);
  try {
    write_file_atomically_with(png, [&](const std::filesystem::path& png_tmp) {
      std::ostringstream gp;
      gp << "set terminal pngcairo size 800,560 noenhanced\n"
         << "set output '" << png_tmp.string() << "'\n"
         << "set datafile separator ','\n"
         << "set key off\nset grid\n"
         << "set title 'Pareto front (epsilon-constraint): " << spec.objective << " vs " << second
         << "'\n"
         << "set xlabel '" << second << " [" << unit_of(second) << "]'\n"
         << "set ylabel '" << spec.objective << " [" << unit_of(spec.objective) << "]'\n"
         << "plot '" << csv.string() << "' every ::1 using 3:2 with linespoints pt 7 ps 1.2 lw 2\n";
      write_file_atomically(script, gp.str());
      const std::string command = "gnuplot '" + script.string() + "' > /dev/null 2>&1";
      const bool ok = std::system(command.c_str()) == 0;
      std::filesystem::remove(script);
      return ok;
    });
    written.push_back(png);
  } catch (const InputError&) {
    // No picture (gnuplot failed); the CSV is the result.
  }
  return written;
}

}  // namespace rheomag::optimise
