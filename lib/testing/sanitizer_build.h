// The sanitizer builds (RTK_SANITIZE, run by CI) execute the kernels 50 to 100 times slower
// than a release build. The few tests whose brute-force loops measure figures pin those
// figures in the release build, which CI runs too; under the sanitizers they check the same
// exact properties (zero leaks, equal counts) on a sample of their rays, so that the memory and
// undefined-behaviour checks see every code path in minutes rather than an hour.
#pragma once

#include <cstddef>
#include <vector>

namespace rtk::test {

#ifdef RTK_SANITIZER_BUILD
inline constexpr bool kSanitizerBuild = true;
#else
inline constexpr bool kSanitizerBuild = false;
#endif

/// Every `stride`-th element of `all` in a sanitizer build, all of them otherwise.
template <class T>
std::vector<T> sanitizer_sample(const std::vector<T>& all, size_t stride = 16) {
  if (!kSanitizerBuild) return all;
  std::vector<T> sample;
  for (size_t i = 0; i < all.size(); i += stride) sample.push_back(all[i]);
  return sample;
}

}  // namespace rtk::test
