#include "render_kernels/choose_kernels.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include "render_kernels/accel_kernels.h"
#ifdef RTK_HAVE_EMBREE
#include "embree/embree_kernels.h"
#endif

namespace rtk {

namespace {

std::string build_figures(double seconds, size_t bytes) {
  char text[64];
  std::snprintf(text, sizeof text, "build %.3f s, %.1f MB", seconds, bytes / 1e6);
  return text;
}

RenderKernels make_rtk(const RenderScene& scene, const AccelConfig& config) {
  auto kernels = std::make_unique<AccelKernels>(scene, config);
  const AccelInfo& info = kernels->info();
  std::string summary = "accel " + info.accel + ", tri " + info.tri + ", isa " +
                        std::string(isa_name(info.isa)) + " (" + info.choice + "); " +
                        build_figures(info.build_seconds, info.bytes);
  return {std::move(kernels), std::move(summary)};
}

#ifdef RTK_HAVE_EMBREE
RenderKernels make_embree(const RenderScene& scene, const AccelConfig& config) {
  if (!config.accel.empty() || !config.tri.empty() || config.isa)
    throw std::invalid_argument("-kernels embree: -accel, -tri and -isa choose RTK's structures and "
                                "do not apply to Embree's; leave them out");
  auto kernels = std::make_unique<EmbreeKernels>(scene, std::max(1, config.threads));
  std::string summary = kernels->name() + "; " + build_figures(kernels->build_seconds(), kernels->total_bytes());
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

RenderKernels make_render_kernels(const RenderScene& scene, const AccelConfig& config, std::string_view which) {
  if (which == "rtk") return make_rtk(scene, config);
  if (which == "embree") {
#ifdef RTK_HAVE_EMBREE
    return make_embree(scene, config);
#else
    throw std::invalid_argument("-kernels embree: this build of RTK has no Embree (install Debian's "
                                "libembree-dev and configure the build again)");
#endif
  }
  throw std::invalid_argument("-kernels: unknown kernels '" + std::string(which) + "' (rtk or embree)");
}

}  // namespace rtk
