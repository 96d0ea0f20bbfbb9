#include "09_inflight/ray_order.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <utility>

#include <tbb/parallel_for.h>

namespace rtk {

RayOrderKey::RayOrderKey(const Box3f& scene) {
  constexpr float cells = float(1 << kCellBitsPerAxis);
  for (int axis = 0; axis < 3; ++axis) {
    const float extent = scene.upper[axis] - scene.lower[axis];
    const float s = cells / extent;
    const bool usable = extent > 0.0f && std::isfinite(s);
    lower_[axis] = usable ? scene.lower[axis] : 0.0f;
    scale_[axis] = usable ? s : 0.0f;
  }
}

namespace {

/// The fewest rays a thread of the sort takes: fewer would cost more in counts to add up than
/// they save.
constexpr size_t kRaysPerPart = size_t(1) << 14;

/// How many copies ahead the sort asks the cache for the ray it will copy: enough to overlap
/// the scattered reads, which 8, 16 and 32 did alike.
constexpr size_t kCopyAhead = 16;

}  // namespace

// [ch09-sort-rays]
bool sort_rays(std::span<const Ray> rays, const RayOrderKey& key, const RayOrderPolicy& policy,
               SortedRays& sorted, int threads) {
  sorted.rays.clear();
  sorted.from.clear();
  using Mode = RayOrderPolicy::Mode;
  const size_t n = rays.size();
  if (policy.mode == Mode::never || n < 2) return false;
  if (n > size_t(UINT32_MAX)) throw std::invalid_argument("sort_rays: more than 2^32 - 1 rays");
  if (policy.mode == Mode::automatic) {
    if (n < policy.min_rays) return false;
    // A sample of neighbouring pairs says whether the batch is coherent already, before any
    // work is spent on the rest.
    const size_t samples = std::clamp<size_t>(policy.samples, 1, n - 1);
    size_t coherent = 0;
    for (size_t s = 0; s < samples; ++s) {
      const size_t i = s * (n - 1) / samples;
      coherent += key(rays[i]) == key(rays[i + 1]);
    }
    if (double(coherent) >= policy.coherent_fraction * double(samples)) return false;
  }
  // A counting sort: count each key, turn the counts into each key's first place, then put
  // every ray's index at its key's next place. Equal keys keep the order they were given in.
  // Only the indices are scattered, four bytes each where a ray has thirty-six; the rays are
  // then copied in sorted order, written one after the other and read from scattered places,
  // each asked of the cache a few copies ahead. (Scattering the rays themselves left most of
  // the sort's time to stores waiting on lines from memory, which some processors commit one
  // by one.) With several threads, each counts and places one contiguous part of the batch,
  // and a key's places go to the parts in turn, so the order is the same; each then copies
  // one part of the sorted batch.
  const size_t parts = std::clamp<size_t>(size_t(threads), 1, n / kRaysPerPart + 1);
  auto part_range = [&](size_t p) { return std::pair{p * n / parts, (p + 1) * n / parts}; };
  auto for_each_part = [&](auto&& body) {
    if (parts == 1) return body(size_t(0));
    tbb::parallel_for(size_t(0), parts, [&](size_t p) { body(p); });
  };
  std::vector<uint16_t> keys(n);
  std::vector<uint32_t> place(parts * kOrderKeys, 0);  // place[p * kOrderKeys + key]
  for_each_part([&](size_t p) {
    uint32_t* count = place.data() + p * kOrderKeys;
    const auto [begin, end] = part_range(p);
    for (size_t i = begin; i < end; ++i) ++count[keys[i] = uint16_t(key(rays[i]))];
  });
  uint32_t first = 0;
  for (uint32_t k = 0; k < kOrderKeys; ++k)
    for (size_t p = 0; p < parts; ++p) first += std::exchange(place[p * kOrderKeys + k], first);
  sorted.rays.resize(n);
  sorted.from.resize(n);
  for_each_part([&](size_t p) {
    uint32_t* next = place.data() + p * kOrderKeys;
    const auto [begin, end] = part_range(p);
    for (size_t i = begin; i < end; ++i) sorted.from[next[keys[i]]++] = uint32_t(i);
  });
  for_each_part([&](size_t p) {
    const auto [begin, end] = part_range(p);
    for (size_t i = begin; i < end; ++i) {
      if (i + kCopyAhead < end) prefetch_l1(&rays[sorted.from[i + kCopyAhead]]);
      sorted.rays[i] = rays[sorted.from[i]];
    }
  });
  return true;
}
// [ch09-sort-rays]

namespace {

/// Rays per call of a kernel: enough that the call's cost is spread thin, few enough that
/// their answers (4 KiB of closest hits) stay in the first-level cache until they are written.
constexpr size_t kRaysPerCall = 256;

template <class Answer, class Kernel>
void trace_sorted(Kernel kernel, const void* structure, const SortedRays& sorted, size_t first,
                  size_t count, std::span<Answer> answers) {
  if (first > sorted.size() || count > sorted.size() - first)
    throw std::invalid_argument("trace_sorted: the range is not inside the sorted batch");
  if (answers.size() != sorted.size())
    throw std::invalid_argument("trace_sorted: the answers are not one per ray of the batch");
  std::array<Answer, kRaysPerCall> found;
  for (size_t begin = first; begin < first + count; begin += kRaysPerCall) {
    const size_t n = std::min(kRaysPerCall, first + count - begin);
    kernel(structure, std::span<const Ray>(sorted.rays.data() + begin, n),
           std::span<Answer>(found.data(), n));
    for (size_t i = 0; i < n; ++i) answers[sorted.from[begin + i]] = found[i];
  }
}

}  // namespace

void intersect_sorted(const TraceKernels& kernels, const void* structure, const SortedRays& sorted,
                      size_t first, size_t count, std::span<Hit> hits) {
  trace_sorted(kernels.intersect, structure, sorted, first, count, hits);
}

void occluded_sorted(const TraceKernels& kernels, const void* structure, const SortedRays& sorted,
                     size_t first, size_t count, std::span<uint8_t> occluded) {
  trace_sorted(kernels.occluded, structure, sorted, first, count, occluded);
}

}  // namespace rtk
