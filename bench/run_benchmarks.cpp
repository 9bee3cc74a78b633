// The main() of every Google Benchmark program in bench/ (those without their own): the threads
// the rheomag program uses, then the benchmarks.

#include <benchmark/benchmark.h>

#include <cstdlib>

#include "core/blas_threads.hpp"
#include "magnetostatics/assembly.hpp"

/// Runs the benchmarks named on the command line with the rheomag program's threads (app/main.cpp):
/// single-threaded OpenBLAS unless OPENBLAS_NUM_THREADS is set (its spinning threads made solves
/// up to 20x slower on a shared machine, docs/performance.md), and element assembly on OpenMP
/// threads only when OMP_NUM_THREADS is set.
int main(int argc, char** argv) {
  rheomag::prefer_single_threaded_blas();
  if (std::getenv("OMP_NUM_THREADS") != nullptr) rheomag::magnetostatics::set_assembly_threads(0);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
