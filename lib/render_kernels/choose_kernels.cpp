#include "render_kernels/choose_kernels.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include "14_pathtracer/accel_kernels.h"
#ifdef RTK_HAVE_EMBREE
#include "embree/embree_kernels.h"
#endif

namespace rtk {

namespace {

#ifdef RTK_HAVE_EMBREE
RenderKernels make_embree(const RenderScene& scene, const AccelConfig& config) {
  if (!config.accel.empty() || !config.tri.empty() || config.isa)
    throw std::invalid_argument(
        "-kernels embree: -accel, -tri and -isa choose RTK's structures and "
        "do not apply to Embree's; leave them out");
  auto kernels = std::make_unique<EmbreeKernels>(scene, std::max(1, config.threads));
  char figures[64];
  std::snprintf(figures, sizeof figures, "; build %.3f s, %.1f MB", kernels->build_seconds(),
                kernels->total_bytes() / 1e6);
  std::string summary = kernels->name() + figures;
  return {std::move(kernels), std::move(summary)};
}
#endif

}  // namespace

bool embree_kernels_available() {
#ifdef RTK_HAVE_EMBREE
  return true;
#else
  return false;
#endif
}

RenderKernels make_render_kernels(const RenderScene& scene, const AccelConfig& config,
                                  std::string_view which) {
  if (which == "rtk") return make_rtk_kernels(scene, config);
  if (which == "embree") {
#ifdef RTK_HAVE_EMBREE
    return make_embree(scene, config);
#else
    throw std::invalid_argument(
        "-kernels embree: this build of RTK has no Embree (install Debian's "
        "libembree-dev and configure the build again)");
#endif
  }
  throw std::invalid_argument("-kernels: unknown kernels '" + std::string(which) +
                              "' (rtk or embree)");
}

KernelFactory kernel_factory(std::string which) {
  if (which != "rtk" && which != "embree")
    throw std::invalid_argument("-kernels: unknown kernels '" + which + "' (rtk or embree)");
  return [which](const RenderScene& scene, const AccelConfig& config) {
    return make_render_kernels(scene, config, which);
  };
}

}  // namespace rtk
