/// \file
/// The renderer's ray kernels on RTK's own acceleration structures: chapter 12's RayKernels
/// implemented by rtk::Accel (lib/api), built for exactly what the scene needs: a static
/// structure for a static scene, the motion structure (chapter 8) only when vertices move.
#pragma once

#include <span>
#include <string>

#include "12_pathtracer/ray_kernels.h"
#include "12_pathtracer/scene.h"
#include "api/accel.h"

namespace rtk {

/// RayKernels over an rtk::Accel built from a RenderScene's mesh.
class AccelKernels final : public RayKernels {
 public:
  /// Builds the structure for `scene` with `config` (-accel, -tri, -isa, -threads for the
  /// build). A scene with vertices_t1 gets the two-time-step constructor of rtk::Accel.
  /// Throws std::invalid_argument like rtk::Accel for a configuration RTK does not have.
  AccelKernels(const RenderScene& scene, const AccelConfig& config);

  void intersect(std::span<const Ray> rays, std::span<Hit> hits) const override;
  void occluded(std::span<const Ray> rays, std::span<uint8_t> occluded) const override;
  /// "rtk ACCEL TRI ISA", e.g. "rtk bvh8.objectsplit triangle4v.pluecker avx2".
  std::string name() const override;

  /// What was built: the resolved configuration, its size and build time.
  const AccelInfo& info() const { return accel_.info(); }

 private:
  Accel accel_;
};

}  // namespace rtk
