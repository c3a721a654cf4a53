#include <doctest/doctest.h>

#include <cstdint>
#include <vector>

#include "partition/large_block_allocator.hpp"

using namespace furrow;

TEST_CASE("large block allocator: huge-page aligned large blocks keep their contents like std::vector") {
  // 6 MB of doubles (a large block) and 1 kB (the ordinary heap), filled,
  // grown across the threshold and compared with a std::vector oracle.
  for (std::size_t n : {std::size_t{786432}, std::size_t{128}}) {
    std::vector<double, LargeBlockAllocator<double>> v(n, 0.0);
    std::vector<double> oracle(n, 0.0);
    for (std::size_t k = 0; k < n; ++k) v[k] = oracle[k] = 0.5 * double(k) - 3.0;
    if (n * sizeof(double) >= kLargeBlockBytes)
      CHECK(reinterpret_cast<std::uintptr_t>(v.data()) % (std::uintptr_t{2} << 20) == 0);
    v.resize(n + kLargeBlockBytes / sizeof(double), 7.0);
    oracle.resize(n + kLargeBlockBytes / sizeof(double), 7.0);
    REQUIRE(v.size() == oracle.size());
    bool same = true;
    for (std::size_t k = 0; k < v.size(); ++k) same = same && v[k] == oracle[k];
    CHECK(same);
  }
}
