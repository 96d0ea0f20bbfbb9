/// \file
/// The renderer on someone else's kernels: chapter 14's RayKernels implemented by Embree 3, so
/// that `rtk render -kernels embree` runs the same path tracer, scene and camera on Embree's
/// BVH and intersectors instead of RTK's. The renderer cannot tell the two apart; only the
/// time and the statistics differ (and the images, within noise: see tests/render).
#pragma once

#include <span>
#include <string>

#include "14_pathtracer/ray_kernels.h"
#include "14_pathtracer/scene.h"
#include "embree/embree_scene.h"

namespace rtk {

/// RayKernels over an EmbreeScene built from a RenderScene's mesh.
class EmbreeKernels final : public RayKernels {
 public:
  /// Builds Embree's structure with `threads` build threads. Embree 3's motion blur needs a
  /// different geometry set-up, so a scene whose vertices move is refused here with a message
  /// that names the option (-kernels) rather than rendered without its blur.
  EmbreeKernels(const RenderScene& scene, int threads);

  /// Embree's scene, and two kernels that call rtcIntersect1 / rtcOccluded1 for each ray.
  Tracer tracer() const override;
  /// "embree 3.13.5 (rtcIntersect1, medium-quality build)".
  std::string name() const override;

  /// Embree's build time in seconds.
  double build_seconds() const { return scene_.build_seconds(); }
  /// What Embree's scene holds: its BVH and the vertex and index buffers, in bytes.
  size_t total_bytes() const { return scene_.total_bytes(); }

 private:
  EmbreeScene scene_;
};

}  // namespace rtk
