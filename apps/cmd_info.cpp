// `rtk info`: which instruction sets the CPU has and which kernel variant runs.
#include <cstdio>
#include <string>

#include "01_base/cpu_features.h"
#include "commands.h"
#include "options.h"

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

}  // namespace rtk::cli
