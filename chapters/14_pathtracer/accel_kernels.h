/// \file
/// The renderer's ray kernels on RTK's own acceleration structures: RayKernels implemented by
/// chapter 10's rtk::Accel, built for exactly what the scene needs: a static structure for a
/// static scene, the motion structure (chapter 8) only when vertices move.
#pragma once

#include <functional>
#include <memory>
#include <string>

#include "10_kernel_api/accel.h"
#include "14_pathtracer/ray_kernels.h"
#include "14_pathtracer/scene.h"

namespace rtk {

/// RayKernels over an rtk::Accel built from a RenderScene's mesh.
class AccelKernels final : public RayKernels {
 public:
  /// Builds the structure for `scene` with `config` (-accel, -tri, -isa, -threads for the
  /// build). A scene with vertices_t1 gets the two-time-step constructor of rtk::Accel.
  /// Throws std::invalid_argument like rtk::Accel for a configuration RTK does not have.
  AccelKernels(const RenderScene& scene, const AccelConfig& config);

  Tracer tracer() const override { return accel_.tracer(); }
  /// "rtk ACCEL TRI ISA", e.g. "rtk bvh8.objectsplit triangle4v.pluecker avx2".
  std::string name() const override;

  /// What was built: the resolved configuration, its size and build time.
  const AccelInfo& info() const { return accel_.info(); }

 private:
  Accel accel_;
};

/// Ray kernels built for a scene, and one line that says what was built.
struct RenderKernels {
  std::unique_ptr<const RayKernels> kernels;
  /// e.g. "accel bvh8.objectsplit, tri triangle8.moeller, isa avx512 (default for the CPU);
  /// build 0.012 s, 0.1 MB".
  std::string summary;
};

/// Builds whatever kernels a renderer's scene is to be traced with, from the scene and the
/// -accel, -tri, -isa and build-thread settings. The device API (chapter 15) builds every
/// committed scene's kernels through one of these.
using KernelFactory = std::function<RenderKernels(const RenderScene& scene, const AccelConfig& config)>;

/// RTK's own kernels (an AccelKernels) for `scene` with `config`, and their summary.
RenderKernels make_rtk_kernels(const RenderScene& scene, const AccelConfig& config);

}  // namespace rtk
