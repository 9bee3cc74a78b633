// OpenMP regions inside a SerialOpenMp scope run inline (magnetostatics/inline_openmp.hpp).
// References: the OpenMP rules for a serialised region (one thread, thread number 0, every loop
// iteration run once), and a direct solve of a 2D Laplacian whose exact solution is known. Checks
// that CHOLMOD's own regions land in rheomag's entry point, which is what saves libgomp's team
// and system call per supernode (docs/performance.md, "Inline OpenMP regions").

#include <dlfcn.h>
#include <gtest/gtest.h>
#include <omp.h>

#include <Eigen/CholmodSupport>
#include <Eigen/SparseCore>
#include <cmath>
#include <string>
#include <vector>

#include "magnetostatics/inline_openmp.hpp"
#include "magnetostatics/serial_openmp.hpp"

namespace {

using rheomag::magnetostatics::inline_openmp_regions;
using rheomag::magnetostatics::SerialOpenMp;

/// The OpenMP level seen inside one region opened here.
int level_inside_a_region() {
  int level = -1;
#pragma omp parallel num_threads(1)
  level = omp_get_level();
  return level;
}

TEST(InlineOpenMp, RheomagsEntryPointComesBeforeLibgomps) {
  // The dynamic linker binds CHOLMOD's GOMP_parallel to the first definition in this order: it
  // must be in the object that holds rheomag's inline_openmp.cpp (the library, or a static
  // program).
  Dl_info first{}, rheomag{};
  ASSERT_NE(dladdr(dlsym(RTLD_DEFAULT, "GOMP_parallel"), &first), 0);
  ASSERT_NE(dladdr(reinterpret_cast<void*>(&inline_openmp_regions), &rheomag), 0);
  EXPECT_EQ(std::string(first.dli_fname), std::string(rheomag.dli_fname));
}

TEST(InlineOpenMp, RegionsOutsideAScopeAreLibgompsTeams) {
  const long before = inline_openmp_regions();
  EXPECT_EQ(level_inside_a_region(), 1);
  EXPECT_EQ(inline_openmp_regions(), before);
}

TEST(InlineOpenMp, RegionsInsideAScopeRunInlineAndRunEveryIterationOnce) {
  if (!rheomag::magnetostatics::inline_openmp_enabled()) GTEST_SKIP() << "RHEOMAG_INLINE_OPENMP=0";
  std::vector<int> visits(1000, 0);
  long sum = 0;
  int threads = 0, level = -1;
  const long before = inline_openmp_regions();
  {
    const SerialOpenMp serial;
#pragma omp parallel for num_threads(4) reduction(+ : sum)
    for (int i = 0; i < 1000; ++i) {
      ++visits[i];
      sum += i + 1;
    }
#pragma omp parallel num_threads(4)
    {
      threads = omp_get_num_threads();
      level = omp_get_level();
    }
  }
  EXPECT_EQ(inline_openmp_regions(), before + 2);
  EXPECT_EQ(sum, 500500);
  for (int v : visits) ASSERT_EQ(v, 1);
  EXPECT_EQ(threads, 1);
  EXPECT_EQ(level, 0);
  EXPECT_EQ(level_inside_a_region(), 1);  // the scope has ended
}

TEST(InlineOpenMp, CholmodsRegionsRunInlineAndItsSolveIsExact) {
  if (!rheomag::magnetostatics::inline_openmp_enabled()) GTEST_SKIP() << "RHEOMAG_INLINE_OPENMP=0";
  // 5-point Laplacian on a 300 x 300 grid (Dirichlet outside): supernodes of more than 128 rows,
  // where CHOLMOD opens its regions. Right-hand side K u for a known u.
  const int n = 300, size = n * n;
  std::vector<Eigen::Triplet<double>> entries;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const int k = i * n + j;
      entries.emplace_back(k, k, 4.0);
      if (i + 1 < n) entries.emplace_back(k + n, k, -1.0);
      if (j + 1 < n) entries.emplace_back(k + 1, k, -1.0);
    }
  Eigen::SparseMatrix<double> lower(size, size);
  lower.setFromTriplets(entries.begin(), entries.end());
  Eigen::VectorXd exact(size);
  for (int k = 0; k < size; ++k) exact[k] = std::sin(0.01 * k) + 1.0;
  const Eigen::VectorXd rhs = lower.selfadjointView<Eigen::Lower>() * exact;

  const long before = inline_openmp_regions();
  Eigen::VectorXd x;
  {
    const SerialOpenMp serial;
    Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>, Eigen::Lower> llt(lower);
    ASSERT_EQ(llt.info(), Eigen::Success);
    x = llt.solve(rhs);
  }
  EXPECT_GT(inline_openmp_regions(), before) << "CHOLMOD's regions did not come to rheomag";
  // A direct solve of a matrix with condition number ~4e4: 1e-10 relative leaves a margin of
  // about 1e3 over the double-precision error.
  EXPECT_LT((x - exact).norm() / exact.norm(), 1e-10);
}

}  // namespace
