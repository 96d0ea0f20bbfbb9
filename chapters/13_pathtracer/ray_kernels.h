/// \file
/// The narrow interface between the renderer and whatever traces its rays: closest hits and
/// occlusion on spans of rays, and a name. lib/render_kernels implements it on rtk::Accel
/// (chapters 2 to 8); another implementation (Embree, for comparisons) needs only these three
/// functions.
#pragma once

#include <cstdint>
#include <span>
#include <string>

#include "01_base/ray.h"

namespace rtk {

// [ch13-ray-kernels]
/// Ray queries as the path tracer uses them. The renderer calls them from several threads
/// at once, each call with one tile's batch of rays, so implementations must be thread-safe
/// and should trace a call's rays on the calling thread (the tiles are the parallelism).
class RayKernels {
 public:
  virtual ~RayKernels() = default;
  /// The closest hit of every ray: hits[i] for rays[i]; a miss for invalid rays (rtk::is_valid).
  virtual void intersect(std::span<const Ray> rays, std::span<Hit> hits) const = 0;
  /// Whether each ray is blocked in [tnear, tfar]: occluded[i] = 1 or 0.
  virtual void occluded(std::span<const Ray> rays, std::span<uint8_t> occluded) const = 0;
  /// What traces the rays, for messages and statistics (e.g. "rtk bvh8.objectsplit
  /// triangle4v.pluecker avx2").
  virtual std::string name() const = 0;
};
// [ch13-ray-kernels]

}  // namespace rtk
