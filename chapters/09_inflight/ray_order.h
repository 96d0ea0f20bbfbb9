/// \file
/// Rays in order: a batch traced in an order of its own choosing. Rays that start near each
/// other and head the same way visit the same nodes and leaves; traced one after the other,
/// the second finds in the caches what the first brought in. A batch of incoherent rays (the
/// bounces of a path tracer, in the order their paths happened to be in) is sorted by a key
/// that puts such rays next to each other, traced in that order, and its answers are written
/// back where the caller expects them. A batch that is coherent already is traced as given.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
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
  /// Computed without a branch, the three axes side by side in the lanes of a vector: a sort
  /// of incoherent rays would mispredict a branch on where each origin lies.
  RTK_INLINE uint32_t operator()(const Ray& ray) const {
    Lanes org, dir;
    const char* bytes = reinterpret_cast<const char*>(&ray);
    std::memcpy(&org, bytes + offsetof(Ray, org), sizeof org);  // org.x, org.y, org.z, tnear
    std::memcpy(&dir, bytes + offsetof(Ray, dir), sizeof dir);  // dir.x, dir.y, dir.z, time
    // (c - lower) * scale clamped to [0, 15] as `f > 0 ? f : 0`, then `f < 15 ? f : 15`: one
    // maximum and one minimum, and a NaN becomes 0.
    const Lanes zero{0, 0, 0, 0}, last = zero + float((1 << kCellBitsPerAxis) - 1);
    Lanes f = (org - lower_) * scale_;
    f = f > zero ? f : zero;
    f = f < last ? f : last;
    Ints x = __builtin_convertvector(f, Ints);
    x = (x | x << 4) & 0x0c3;  // bits 3210 to 32....10
    x = (x | x << 2) & 0x249;  // and on to 3..2..1..0: bit b at bit 3b
    const uint32_t morton = uint32_t(x[0] | x[1] << 1 | x[2] << 2);
    // -1 in the lanes whose sign bit is set, 0 in the others.
    const Ints sign = reinterpret_cast<Ints>(dir) < Ints{0, 0, 0, 0};
    const uint32_t octant = uint32_t((sign[0] & 1) | (sign[1] & 2) | (sign[2] & 4));
    return octant << (3 * kCellBitsPerAxis) | morton;
  }

 private:
  /// Four floats or four integers in one SSE register (GCC/Clang vector types, compiled for
  /// the baseline ISA); lane 3 is unused.
  typedef float Lanes __attribute__((vector_size(16)));
  typedef int32_t Ints __attribute__((vector_size(16)));
  Lanes lower_{0, 0, 0, 0};
  Lanes scale_{0, 0, 0, 0};  // cells per unit length on each axis (0 for a flat or empty axis)
};
// [ch09-order-key]

// [ch09-order-policy]
/// When a batch is worth sorting. A batch of fewer than `min_rays` rays is traced as given
/// (too few rays to share much whatever their order), as is one in which at least
/// `coherent_fraction` of `samples` neighbouring pairs, spread over the batch, already share
/// octant and cell: primary rays from a pinhole, shadow rays toward one light in the order of
/// the pixels they came from. The size of the structure does not enter: a tree that fits the
/// second-level cache gains too (chapter 9 measures the teapot and the Cornell box).
struct RayOrderPolicy {
  size_t min_rays = 4096;
  size_t samples = 1024;
  double coherent_fraction = 0.5;
  /// Sorting changes nothing but the order of the work, never an answer; `always` sorts
  /// whatever the batch looks like, `never` traces every batch as given.
  enum class Mode { automatic, always, never } mode = Mode::automatic;
};
// [ch09-order-policy]

/// A batch in the order it is traced in: copies of its rays sorted by key, equal keys in their
/// given order, and for each copy the index of the ray it came from.
struct SortedRays {
  std::vector<Ray> rays;
  std::vector<uint32_t> from;
  size_t size() const { return rays.size(); }
};

/// Sorts `rays` into `sorted` (storage reused from batch to batch) with one counting sort: a
/// pass that counts each key, one that puts every ray's index at its key's next place, and one
/// that copies the rays in that order, each cut into up to `threads` parts that the threads of
/// the caller's TBB task arena share (the result does not depend on how many). Returns false
/// (and leaves `sorted` empty) when the policy says to trace the batch as given.
bool sort_rays(std::span<const Ray> rays, const RayOrderKey& key, const RayOrderPolicy& policy,
               SortedRays& sorted, int threads = 1);

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
