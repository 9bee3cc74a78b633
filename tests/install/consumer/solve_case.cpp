// An outside program using the installed rheomag: solves a case file and prints the first
// circuit's inductance [H] with 17 significant digits and the library's version.

#include <cstdio>
#include <exception>

#include "case/case_file.hpp"
#include "core/blas_threads.hpp"
#include "core/version.hpp"
#include "identify/fit_model_json.hpp"
#include "magnetostatics/solve_problem.hpp"
#include "valve/valve_chain.hpp"  // registers the [valve] section of the bundled cases

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: solve_case CASE.toml\n");
    return 2;
  }
  rheomag::prefer_single_threaded_blas();  // as the CLI: the same sums, the same last digits
  try {
    const rheomag::cases::Case c = rheomag::cases::load_case(argv[1]);
    const auto solved = rheomag::magnetostatics::solve_problem(c.problem);
    std::printf("%s %.17g\n", rheomag::version_text().c_str(),
                solved.results.circuits.at(0).inductance);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "solve_case: %s\n", e.what());
    return 1;
  }
  return 0;
}
