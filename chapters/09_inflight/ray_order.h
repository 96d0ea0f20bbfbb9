/// \file
/// Rays in order: a batch traced in an order of its own choosing. Rays that start near each
/// other and head the same way visit the same nodes and leaves; traced one after the other,
/// the second finds in the caches what the first brought in. A batch of incoherent rays (the
/// bounces of a path tracer, in the order their paths happened to be in) is sorted by a key
/// that puts such rays next to each other, traced in that order, and its answers are written
/// back where the caller expects them. A batch that is coherent already is traced as given.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "01_base/box3.h"
#include "01_base/platform.h"
#include "01_base/ray.h"
#include "02_bvh2/trace_kernels.h"

namespace rtk {

// [ch09-order-key]
/// A ray's sort key: the three sign bits of its direction (its octant) above the Morton code of
/// the cell of a 16 x 16 x 16 grid over the scene's box that holds its origin. Rays of one
/// octant visit a node's children in the same order; rays whose origins share a cell start in
/// the same part of the scene, and cells next to each other in Morton order are next to each
/// other in space. Origins outside the box count as in the nearest cell.
inline constexpr int kCellBitsPerAxis = 4;
inline constexpr int kOrderKeyBits = 3 + 3 * kCellBitsPerAxis;
inline constexpr uint32_t kOrderKeys = uint32_t(1) << kOrderKeyBits;

/// Maps rays to sort keys over one scene's box.
class RayOrderKey {
 public:
  /// Keys over `scene`; an empty box gives every ray the same origin cell.
  explicit RayOrderKey(const Box3f& scene);
  /// The key of a ray, below kOrderKeys: octant in the top three bits, the origin's cell below.
  /// Any ray has a key, NaNs included (they are traced as misses wherever they land).
  RTK_INLINE uint32_t operator()(const Ray& ray) const {
    const uint32_t morton = spread(cell(ray.org.x, 0)) | spread(cell(ray.org.y, 1)) << 1 |
                            spread(cell(ray.org.z, 2)) << 2;
    const uint32_t octant = uint32_t(std::signbit(ray.dir.x)) | uint32_t(std::signbit(ray.dir.y)) << 1 |
                            uint32_t(std::signbit(ray.dir.z)) << 2;
    return octant << (3 * kCellBitsPerAxis) | morton;
  }

 private:
  /// The cell of a coordinate along `axis`: (c - lower) * scale clamped to [0, 15]; NaN gives 0.
  RTK_INLINE uint32_t cell(float c, int axis) const {
    constexpr float last = float((1 << kCellBitsPerAxis) - 1);
    const float f = (c - lower_[axis]) * scale_[axis];
    const float above = f > 0.0f ? f : 0.0f;  // also NaN to 0
    return uint32_t(above < last ? above : last);
  }
  /// A cell index with bit b moved to bit 3b: three of them, shifted by 0, 1 and 2 and or-ed,
  /// interleave into a Morton code.
  RTK_INLINE static uint32_t spread(uint32_t x) {
    x = (x | x << 4) & 0x0c3u;  // bits 2-3 up by 4: 3210 -> 32....10
    return (x | x << 2) & 0x249u;  // then every other pair apart: 3..2..1..0
  }

  Vec3f lower_;
  Vec3f scale_;  // cells per unit length on each axis (0 for a flat or empty axis)
};
// [ch09-order-key]

/// When a batch is worth sorting. A batch of fewer than `min_rays` rays is traced as given
/// (too few rays to share much whatever their order), and so is one in which at least
/// `coherent_fraction` of `samples` neighbouring pairs, spread over the batch, already share
/// octant and cell: primary rays from a pinhole, shadow rays toward one light in the order of
/// the pixels they came from.
struct RayOrderPolicy {
  size_t min_rays = 4096;
  size_t samples = 1024;
  double coherent_fraction = 0.5;
  /// Sorting changes nothing but the order of the work, never an answer; `always` sorts
  /// whatever the batch looks like, `never` traces every batch as given.
  enum class Mode { automatic, always, never } mode = Mode::automatic;
};

/// A batch in the order it is traced in: copies of its rays sorted by key, equal keys in their
/// given order, and for each copy the index of the ray it came from.
struct SortedRays {
  std::vector<Ray> rays;
  std::vector<uint32_t> from;
  size_t size() const { return rays.size(); }
};

/// Sorts `rays` into `sorted` (storage reused from batch to batch) with one counting sort: a
/// pass that counts each key, one that copies every ray to its key's next place. Returns false
/// (and leaves `sorted` empty) when the policy says to trace the batch as given.
bool sort_rays(std::span<const Ray> rays, const RayOrderKey& key, const RayOrderPolicy& policy,
               SortedRays& sorted);

// [ch09-in-order]
/// Traces sorted.rays[first, first + count) with `kernels`, a few hundred at a time, and writes
/// each answer where the caller expects it: hits[sorted.from[i]] answers sorted.rays[i], as if
/// the batch had been traced as given, bit for bit. Threads may trace disjoint ranges at once.
void intersect_sorted(const TraceKernels& kernels, const void* structure, const SortedRays& sorted,
                      size_t first, size_t count, std::span<Hit> hits);
/// The same for occlusion: occluded[sorted.from[i]] answers sorted.rays[i].
void occluded_sorted(const TraceKernels& kernels, const void* structure, const SortedRays& sorted,
                     size_t first, size_t count, std::span<uint8_t> occluded);
// [ch09-in-order]

}  // namespace rtk
