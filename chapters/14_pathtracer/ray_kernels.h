/// \file
/// The narrow interface between the renderer and whatever traces its rays: chapter 10's Tracer
/// (a structure bound to its two batch kernels) and a name. AccelKernels (accel_kernels.h)
/// implements it on RTK's own structures; lib/embree implements it on Embree 3, for the
/// comparisons.
#pragma once

#include <string>

#include "10_kernel_api/accel.h"

namespace rtk {

// [ch14-ray-kernels]
/// What traces the path tracer's rays. It owns the structure; the path tracer asks once for its
/// Tracer and then calls it from several threads at once, each call with one tile's batch of
/// rays, traced on the calling thread (the tiles are the parallelism): one indirect call per
/// batch, from the renderer to the traversal loop.
class RayKernels {
 public:
  virtual ~RayKernels() = default;
  /// The structure and its kernels; valid while this object lives. Invalid rays
  /// (rtk::is_valid) miss.
  virtual Tracer tracer() const = 0;
  /// What traces the rays, for messages and statistics (e.g. "rtk bvh8.objectsplit
  /// triangle4v.pluecker avx2").
  virtual std::string name() const = 0;
};
// [ch14-ray-kernels]

}  // namespace rtk
