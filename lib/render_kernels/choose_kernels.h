/// \file
/// Which kernels trace the renderer's rays: `-kernels rtk` (the default, RTK's own structures
/// through lib/render_kernels' AccelKernels) or `-kernels embree` (Embree 3 through
/// lib/embree's EmbreeKernels, in builds made where Debian's libembree-dev is installed). The
/// path tracer sees only chapter 12's RayKernels, so the choice changes nothing but who
/// answers the ray queries: the guide's second way to compare, other kernels inside RTK's
/// renderer.
#pragma once

#include <memory>
#include <string>
#include <string_view>

#include "12_pathtracer/ray_kernels.h"
#include "12_pathtracer/scene.h"
#include "api/accel.h"

namespace rtk {

/// Whether this build can run the renderer on Embree's kernels.
bool embree_kernels_available();

/// The kernels a render runs on, and one line that says what was built.
struct RenderKernels {
  std::unique_ptr<RayKernels> kernels;
  /// e.g. "accel bvh8.objectsplit, tri triangle8.moeller, isa avx512 (default for the CPU);
  /// build 0.012 s, 0.1 MB" or "embree 3.13.5 (rtcIntersect1, medium-quality build); build ...".
  std::string summary;
};

/// Builds `which` ("rtk" or "embree") for `scene`. RTK's kernels take `config` (-accel, -tri,
/// -isa; threads for the build). Embree takes only config.threads: -accel, -tri and -isa
/// describe RTK's structures, and asking for them with Embree is refused rather than ignored.
/// Throws std::invalid_argument naming -kernels for an unknown name, for Embree in a build
/// without it, and for a moving scene on Embree.
RenderKernels make_render_kernels(const RenderScene& scene, const AccelConfig& config, std::string_view which);

}  // namespace rtk
