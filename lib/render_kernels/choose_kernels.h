/// \file
/// Which kernels trace the renderer's rays: `-kernels rtk` (the default, RTK's own structures
/// through lib/render_kernels' AccelKernels) or `-kernels embree` (Embree 3 through
/// lib/embree's EmbreeKernels, in builds made where Debian's libembree-dev is installed). The
/// path tracer sees only chapter 14's RayKernels, so the choice changes nothing but who
/// answers the ray queries: the guide's second way to compare, other kernels inside RTK's
/// renderer.
#pragma once

#include <memory>
#include <string>
#include <string_view>

#include "14_pathtracer/accel_kernels.h"

namespace rtk {

/// Whether this build can run the renderer on Embree's kernels.
bool embree_kernels_available();

/// Builds `which` ("rtk" or "embree") for `scene`. RTK's kernels take `config` (-accel, -tri,
/// -isa; threads for the build). Embree takes only config.threads: -accel, -tri and -isa
/// describe RTK's structures, and asking for them with Embree is refused rather than ignored.
/// Throws std::invalid_argument naming -kernels for an unknown name, for Embree in a build
/// without it, and for a moving scene on Embree.
RenderKernels make_render_kernels(const RenderScene& scene, const AccelConfig& config,
                                  std::string_view which);

/// make_render_kernels(scene, config, which) as a factory for the device API (chapter 15).
/// Checks `which` at once, so that an unknown name fails before any scene is read.
KernelFactory kernel_factory(std::string which);

}  // namespace rtk
