#include "optimise/run.hpp"

#include "design/response_time.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <sstream>
#include <string>

#include "case/femm_export.hpp"
#include "case/femm_sidecar.hpp"
#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/output_set.hpp"
#include "magnetostatics/domain.hpp"
#include "magnetostatics/report.hpp"
#include "optimise/continuous.hpp"

namespace rheomag::optimise {

namespace {

std::string bound_text(const Constraint& c) {
  std::string text;
  if (std::isfinite(c.lower)) text += number_text(c.lower) + " <= ";
  text += design::quantity_name(c.quantity);
  if (std::isfinite(c.upper)) text += " <= " + number_text(c.upper);
  return text;
}

// Every combination of the discrete choices (one empty combination without choices).
std::vector<std::vector<std::pair<std::string, std::string>>> combinations(
    const std::vector<DiscreteChoice>& choices) {
  std::vector<std::vector<std::pair<std::string, std::string>>> out(1);
  for (const auto& choice : choices) {
    std::vector<std::vector<std::pair<std::string, std::string>>> next;
    for (const auto& partial : out)
      for (const auto& value : choice.values) {
        auto extended = partial;
        extended.emplace_back(choice.key, value);
        next.push_back(std::move(extended));
      }
    out = std::move(next);
  }
  return out;
}

std::string choice_text(const std::vector<std::pair<std::string, std::string>>& choice) {
  std::string text;
  for (const auto& [key, value] : choice) text += (text.empty() ? "" : ", ") + key + " = " + value;
  return text;
}

/// An Ipopt iteration callback reporting `stage`, the iteration against the limit (a bound) and
/// the evaluator's FE solves so far; empty without a progress callback.
std::function<void(int)> iteration_progress(const ProgressCallback& progress,
                                            std::chrono::steady_clock::time_point start,
                                            const std::string& stage, int max_iterations,
                                            const OptimiseEvaluator& evaluator) {
  if (!progress) return {};
  return [=, &evaluator](int iteration) {
    ProgressEvent e;
    e.stage = stage + " (" + std::to_string(evaluator.fe_solves()) + " FE solves)";
    e.done = iteration;
    e.total = max_iterations;
    e.total_is_bound = true;
    e.elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    progress(e);
  };
}

/// Progress of a transient check: `what` and the run's own stage ("switch-on, ..."; its
/// elapsed time, from which the time left of that run is estimated); empty without a progress
/// callback.
ProgressCallback check_progress(const ProgressCallback& progress, const std::string& what) {
  if (!progress) return {};
  return [=](const ProgressEvent& e) {
    ProgressEvent step = e;
    step.stage = what + " by its transient runs, " + e.stage;
    progress(step);
  };
}

}  // namespace

OptimiseResult run_optimisation(const cases::Case& c, const OptimiseOptions& options) {
  const auto start_time = std::chrono::steady_clock::now();
  OptimiseResult result;
  result.spec = read_optimise_spec(c);
  OptimiseSpec& spec = result.spec;
  std::vector<HistoryRow> history;
  std::vector<double> x0;
  for (const auto& v : spec.variables) x0.push_back(v.initial);

  // The case as written: the initial design, and the normalisers of a weighted sum.
  auto evaluator = std::make_unique<OptimiseEvaluator>(c, spec);
  design::Quantities q0;
  try {
    q0 = evaluator->evaluate(x0);
  } catch (const ConvergenceError& e) {
    throw ConvergenceError(c.source.string() +
                           ": the initial design did not converge: " + e.what());
  }
  if (spec.terms.size() > 1)
    for (auto& term : spec.terms) {
      const double v = std::abs(quantity_value(q0, term.quantity));
      term.scale = v > 0.0 ? v : 1.0;
    }
  result.initial = report_design(spec, x0, q0);
  const double objective_scale =
      std::abs(result.initial.objective) > 0.0 ? std::abs(result.initial.objective) : 1.0;
  IpoptSettings settings;
  settings.max_iterations = spec.max_iterations;
  settings.tolerance = spec.tolerance;
  settings.print_level = options.print_level;

  // Each combination of the discrete choices: the continuous optimum (warm-started from the
  // previous combination's), its counts rounded. The best combination is kept.
  int solves_done = 0, meshes_done = 0;
  std::unique_ptr<OptimiseEvaluator> best_evaluator;
  DesignReport best_continuous;
  std::vector<double> start = x0;
  for (const auto& choice : combinations(spec.choices)) {
    std::unique_ptr<OptimiseEvaluator> e;
    cases::Case cc = c;
    const design::Quantities* start_q = nullptr;
    if (choice.empty()) {
      e = std::move(evaluator);
      start_q = &q0;
    } else {
      std::vector<cases::CaseEdit> edits;
      for (const auto& [key, value] : choice)
        for (const DiscreteChoice& d : spec.choices)
          if (d.key == key) edits.push_back({d.target, value});
      cc = cases::with(c, edits);
      e = std::make_unique<OptimiseEvaluator>(cc, spec);
    }
    const int before = e->fe_solves();
    settings.on_iteration = iteration_progress(
        options.progress, start_time,
        "optimising" + (choice.empty() ? "" : " " + choice_text(choice)), spec.max_iterations, *e);
    const ContinuousOptimum continuous =
        optimise_continuous(*e, spec, start, start_q, objective_scale, settings, history);
    CombinationResult combination;
    combination.choice = choice;
    combination.optimal = round_counts(*e, spec, continuous.report, history);
    combination.status = continuous.status;
    combination.converged = continuous.converged;
    combination.iterations = continuous.iterations;
    combination.fe_solves = e->fe_solves() - before;
    start = continuous.report.x;
    const bool best = result.combinations.empty() ||
                      better_design(combination.optimal, result.combinations[result.chosen].optimal,
                                    spec.maximise);
    result.combinations.push_back(combination);
    if (best) {
      result.chosen = result.combinations.size() - 1;
      if (best_evaluator) {
        solves_done += best_evaluator->fe_solves();
        meshes_done += best_evaluator->meshes();
      }
      best_evaluator = std::move(e);
      best_continuous = continuous.report;
    } else {
      solves_done += e->fe_solves();
      meshes_done += e->meshes();
    }
  }
  settings.on_iteration = {};  // it refers to the last combination's evaluator
  if (evaluator) {  // the case as written, when only enumerated combinations were optimised
    solves_done += evaluator->fe_solves();
    meshes_done += evaluator->meshes();
  }
  const CombinationResult& chosen = result.combinations[result.chosen];
  result.optimal = chosen.optimal;
  result.status = chosen.status;
  result.converged = chosen.converged;
  for (const auto& k : result.combinations) result.iterations += k.iterations;
  if (spec.response_model == ResponseModel::quasi_static &&
      uses(spec, design::Quantity::response_time)) {
    OptimumState state{best_continuous, result.optimal, result.status, result.converged, 0};
    settings.on_iteration =
        iteration_progress(options.progress, start_time, "optimising with the checked response",
                           spec.max_iterations, *best_evaluator);
    result.response_check =
        check_response_time(*best_evaluator, spec, state, objective_scale, settings, history,
                            check_progress(options.progress, "checking the optimum"));
    settings.on_iteration = {};
    best_continuous = state.continuous;
    result.optimal = result.combinations[result.chosen].optimal = state.rounded;
    result.status = state.status;
    result.converged = state.converged;
    result.iterations += state.iterations;
    solves_done += result.response_check->fe_solves;
  }
  if (!result.optimal.feasible) {
    for (const auto& s : result.optimal.constraints)
      if (!s.satisfied || s.active)
        result.conflicts.push_back(bound_text(s.constraint) + " (" + s.constraint.where +
                                   "): value " + number_text(s.value) +
                                   (s.satisfied ? ", at its bound" : ", VIOLATED"));
    for (const auto& key : result.optimal.variables_at_bounds)
      result.conflicts.push_back("design variable " + key + " at its bound");
  }

  // The optimum, its field, history and front replace an earlier run's files as a set.
  OutputSet files(options.out_dir, "--out");
  // Each file written into the set under its destination's name (messages name the destination).
  const auto text_file = [&files](const std::filesystem::path& path, const std::string& text) {
    files.write(path.filename().string(),
                [&](const std::filesystem::path& to) { write_file_atomically(to, text); });
  };
  const std::string stem = c.name.empty() ? c.source.stem().string() : c.name;
  // A .fem base gives a .fem design (and its sidecar): a TOML case cannot hold a FEMM model.
  result.case_file = options.out_dir / (stem + (c.femm ? "_optimal.fem" : "_optimal.toml"));
  result.history_file = options.out_dir / (stem + "_history.csv");
  result.vtu_file = options.out_dir / (stem + "_optimal.vtu");
  std::string header = "# Optimal design of " + c.source.filename().string() +
                       " by rheomag optimise (" + result.status + ")\n";
  if (!chosen.choice.empty()) header += "# Chosen: " + choice_text(chosen.choice) + "\n";
  const cases::Case best = best_evaluator->case_at(result.optimal.x);
  if (c.femm) {
    const cases::Problem closed = magnetostatics::close_domain(best.problem);
    text_file(result.case_file, cases::write_femm(closed, {}));
    const std::string sidecar = cases::femm_sidecar_text(best, closed);
    if (!sidecar.empty()) text_file(cases::femm_sidecar_path(result.case_file), header + sidecar);
  } else {
    text_file(result.case_file, header + cases::case_file_text(best) + "\n");
  }
  const auto& field = best_evaluator->last_field();
  files.write(result.vtu_file.filename().string(), [&](const std::filesystem::path& to) {
    magnetostatics::write_results_vtu(to.string(), *field.solver, field.solution, field.results);
  });

  // The epsilon-constraint front of the chosen combination, each level a continuous optimum.
  if (spec.pareto) {
    OptimiseEvaluator& e = *best_evaluator;
    settings.on_iteration =
        iteration_progress(options.progress, start_time, "Pareto front", spec.max_iterations, e);
    // With the reduction standing in for the transient runs, each level's optimum is checked by
    // them too (its field is the evaluator's last).
    const bool check = spec.response_model == ResponseModel::quasi_static &&
                       uses(spec, design::Quantity::response_time);
    int check_solves = 0;
    const OptimiseFrom optimise = [&](const OptimiseSpec& level, const std::vector<double>& from,
                                      double scale) {
      DesignReport r =
          optimise_continuous(e, level, from, nullptr, scale, settings, history).report;
      if (check)
        r.response_time_transient = transient_response_time(
            e, spec, r, &check_solves, check_progress(options.progress, "checking a Pareto level"));
      return r;
    };
    result.pareto = pareto_front(spec, best_continuous, optimise,
                                 [&e, &check_solves] { return e.fe_solves() + check_solves; });
    solves_done += check_solves;
    for (const auto& path : write_pareto(files.staged(""), spec, *result.pareto))
      result.pareto_files.push_back(options.out_dir / path.filename());
  }
  text_file(result.history_file, history_csv(spec, history));
  files.commit(
      [](const std::string& name) { return name == "pareto.csv" || name == "pareto.png"; });
  result.fe_solves = solves_done + best_evaluator->fe_solves();
  result.meshes = meshes_done + best_evaluator->meshes();
  result.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_time).count();
  return result;
}

std::string objective_change_text(const OptimiseResult& r) {
  std::string unit;
  if (r.spec.terms.size() == 1 && r.spec.objective != "weighted_sum")
    unit = " " + std::string(design::quantity_unit(r.spec.terms.front().quantity));
  const std::string start = number_text(r.initial.objective) + unit,
                    end = number_text(r.optimal.objective) + unit;
  std::string text = std::string(r.optimal.feasible ? "feasible" : "INFEASIBLE") +
                     " optimum; objective " + (r.spec.maximise ? "max " : "min ") +
                     r.spec.objective + ": ";
  if (r.initial.feasible) return text + start + " -> " + end;
  text += start + " at the infeasible start -> " + end;
  if (!r.optimal.feasible) return text + " (no design meets every constraint)";
  std::string names;
  for (const Violation& v : violations(r.initial))
    names += (names.empty() ? "" : ", ") + bound_text(v.constraint);
  const bool worse = r.spec.maximise ? r.optimal.objective < r.initial.objective
                                     : r.optimal.objective > r.initial.objective;
  return text + " at the feasible optimum" +
         (worse ? " (not a loss: the start's value needs " + names +
                      " broken; no feasible design reaches it)"
                : " (the start broke " + names + ")");
}

std::string format_summary(const OptimiseResult& r) {
  std::ostringstream out;
  out << "Ipopt: " << r.status << " after " << r.iterations << " iterations, " << r.fe_solves
      << " FE solves, " << r.meshes << " mesh(es), " << number_text(r.seconds) << " s\n\n";
  char line[240];
  if (r.combinations.size() > 1) {
    out << "discrete choices (each the continuous optimum, counts rounded):\n";
    for (std::size_t k = 0; k < r.combinations.size(); ++k) {
      const auto& m = r.combinations[k];
      std::snprintf(line, sizeof line, "  %-58s %-10s %14.6g %6d solves%s\n",
                    choice_text(m.choice).c_str(), m.optimal.feasible ? "feasible" : "INFEASIBLE",
                    m.optimal.objective, m.fe_solves, k == r.chosen ? "  <- best" : "");
      out << line;
    }
    out << "\n";
  }
  std::snprintf(line, sizeof line, "%-28s %14s %14s\n", "design variable", "initial", "optimal");
  out << line;
  for (std::size_t i = 0; i < r.spec.variables.size(); ++i) {
    std::snprintf(line, sizeof line, "%-28s %14.6g %14.6g\n", r.spec.variables[i].key.c_str(),
                  r.initial.x[i], r.optimal.x[i]);
    out << line;
  }
  std::snprintf(line, sizeof line, "\n%-28s %14s %14s\n", "quantity", "initial", "optimal");
  out << line;
  for (design::Quantity q : design::all_quantities()) {
    const double a = r.initial.quantities[q], b = r.optimal.quantities[q];
    if (std::isnan(a) || std::isnan(b)) continue;
    const std::string label =
        design::quantity_name(q) + " [" + std::string(design::quantity_unit(q)) + "]";
    std::snprintf(line, sizeof line, "%-28s %14.6g %14.6g\n", label.c_str(), a, b);
    out << line;
  }
  const std::vector<Violation> broken = violations(r.initial);
  out << "\nstarting design (the case as written): "
      << (broken.empty() ? "feasible\n" : "INFEASIBLE, it breaks\n");
  for (const Violation& v : broken) out << "  " << violation_text(v) << "\n";
  if (!r.spec.constraints.empty()) out << "\nconstraints (optimal design):\n";
  for (const auto& s : r.optimal.constraints)
    out << "  " << bound_text(s.constraint) << ": " << number_text(s.value)
        << (s.satisfied ? (s.active ? "  active" : "  inactive") : "  VIOLATED") << "\n";
  for (const auto& key : r.optimal.variables_at_bounds) out << "  bound active: " << key << "\n";
  out << "\n" << objective_change_text(r) << "\n";
  if (r.response_check) {
    const ResponseCheck& c = *r.response_check;
    out << "response_time at the optimum: " << number_text(c.reduced * 1e3)
        << " ms by the quasi-static reduction (response_model; scaled by "
        << number_text(c.correction) << " after " << c.rounds << " re-optimisation(s)), "
        << number_text(c.transient * 1e3) << " ms by the transient runs ("
        << number_text(100.0 * (c.reduced / c.transient - 1.0)) << " %)\n";
  }
  if (!r.conflicts.empty()) {
    out << "No feasible design found within the bounds; the conflicting constraints at the "
           "least-violating design:\n";
    for (const auto& c : r.conflicts) out << "  " << c << "\n";
  }
  if (r.pareto) {
    const std::string q = design::quantity_name(r.pareto->pareto.quantity);
    out << "\nPareto front (" << r.spec.objective << " with " << q << " limited):\n";
    const bool checked = r.response_check.has_value();
    std::snprintf(line, sizeof line, "  %14s %14s %14s %9s %7s%s\n", ("eps " + q).c_str(),
                  r.spec.objective.c_str(), q.c_str(), "feasible", "solves",
                  checked ? "  response_time by transient runs" : "");
    out << line;
    for (const auto& p : r.pareto->points) {
      std::snprintf(line, sizeof line, "  %14.6g %14.6g %14.6g %9s %7d", p.epsilon,
                    p.design.objective, p.design.quantities[r.pareto->pareto.quantity],
                    p.design.feasible ? "yes" : "no", p.fe_solves);
      out << line;
      if (p.design.response_time_transient)
        out << "  " << number_text(*p.design.response_time_transient);
      out << "\n";
    }
    if (r.pareto->points.size() > 1 && r.pareto->points.back().design.strict_vertex)
      out << "  (last level: the " << q << " optimum itself, every variable pressed on a bound: "
          << "no other design meets that level)\n";
  }
  out << "\nwritten: " << r.case_file.string() << ", " << r.history_file.string() << ", "
      << r.vtu_file.string();
  for (const auto& f : r.pareto_files) out << ", " << f.string();
  out << "\n";
  return out.str();
}

}  // namespace rheomag::optimise
