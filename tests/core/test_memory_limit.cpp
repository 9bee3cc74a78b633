// The default memory bound of the meshers follows what the process may really use (issue #36:
// under `ulimit -v 4G` a 3D case planned for 3/4 of the machine's 24 GB and ended in "CHOLMOD
// error: out of memory"): an address-space limit lowers it.

#include <gtest/gtest.h>
#include <sys/resource.h>

#include "core/memory_limit.hpp"

// With the soft address-space limit set to 2 GiB, the default is 3/4 of it (1.5 GiB), exactly;
// the limit is restored afterwards (a soft limit may be raised back to the hard one).
TEST(MemoryLimit, AddressSpaceLimitLowersTheDefault) {
  struct rlimit saved {};
  ASSERT_EQ(::getrlimit(RLIMIT_AS, &saved), 0);
  const double two_gib = 2.0 * 1024 * 1024 * 1024;
  if (saved.rlim_cur != RLIM_INFINITY && static_cast<double>(saved.rlim_cur) < two_gib)
    GTEST_SKIP() << "the address space is already limited below 2 GiB";
  struct rlimit lowered = saved;
  lowered.rlim_cur = static_cast<rlim_t>(two_gib);
  ASSERT_EQ(::setrlimit(RLIMIT_AS, &lowered), 0);
  const double available = rheomag::available_memory_bytes();
  const double limit = rheomag::default_memory_limit();
  ASSERT_EQ(::setrlimit(RLIMIT_AS, &saved), 0);
  EXPECT_LE(available, two_gib);
  EXPECT_DOUBLE_EQ(limit, 0.75 * available);
  // Without the limit it is back to the machine's (or cgroup's) memory, which is more here.
  EXPECT_GE(rheomag::available_memory_bytes(), available);
}
