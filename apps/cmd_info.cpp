// `rtk info`: which instruction sets the CPU has and which kernel variant runs.
#include <cstdio>
#include <string>

#include "01_base/cpu_features.h"
#include "10_kernel_api/accel.h"
#include "commands.h"
#include "options.h"
#include "render_kernels/choose_kernels.h"

namespace rtk::cli {

int run_info(std::span<const std::string_view> args) {
  const Options options("info", args, {.with_value = {"isa"}, .flags = {}});
  const std::string requested = options.get("isa", "");
  const Isa chosen = choose_isa(requested);  // refuses a bad -isa before printing
  const CpuFeatures& f = cpu_features();
  std::printf("cpu: %s (%s)\n", f.brand.c_str(), f.vendor.c_str());
  std::printf("isas:");
  for (Isa isa : kAllIsas)
    std::printf(" %s%s", std::string(isa_name(isa)).c_str(), isa_supported(isa) ? "" : "(no)");
  std::printf("\nvariant: %s%s\n", std::string(isa_name(chosen)).c_str(),
              requested.empty() ? " (best the CPU runs)" : " (forced by -isa)");
  return 0;
}

int run_version() {
  std::printf("rtk %s\n", RTK_VERSION);
  // Every kernel is compiled once per ISA (chapter 1); the CPU decides at run time which runs.
  std::printf("kernel variants compiled in:");
  for (Isa isa : kAllIsas) std::printf(" %s", std::string(isa_name(isa)).c_str());
  std::printf("\nthis CPU runs:");
  for (Isa isa : kAllIsas)
    if (isa_supported(isa)) std::printf(" %s", std::string(isa_name(isa)).c_str());
  std::printf(" (default %s)\n", std::string(isa_name(choose_isa(""))).c_str());
  std::printf("structures (-accel): bvh2 bvh4 bvh8 [.objectsplit|.spatialsplit], bvh4mb (motion blur)\n");
  std::printf("layouts: triangle1 triangle4 triangle8 triangle1i triangle4i triangle1v triangle4v\n");
  std::printf("intersectors: moeller pluecker watertight\n");
  std::printf("renderer kernels: rtk%s\n", embree_kernels_available() ? " embree (Embree 3)" : "");
  return 0;
}

}  // namespace rtk::cli
