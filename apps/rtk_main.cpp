// The rtk command line: `rtk info` for now; later chapters add their commands here.
#include <cstdio>
#include <exception>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "01_base/cpu_features.h"

namespace {

// Options may be written with one dash or two.
std::string_view option_name(std::string_view arg) {
  if (arg.starts_with("--")) return arg.substr(2);
  if (arg.starts_with("-")) return arg.substr(1);
  return {};
}

int run_info(const std::vector<std::string_view>& args) {
  std::string_view requested;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string_view name = option_name(args[i]);
    if (name == "isa" && i + 1 < args.size()) {
      requested = args[++i];
    } else {
      throw std::invalid_argument("info: unknown option '" + std::string(args[i]) + "'");
    }
  }
  const rtk::Isa chosen = rtk::choose_isa(requested);  // refuses a bad -isa before printing
  const rtk::CpuFeatures& f = rtk::cpu_features();
  std::printf("cpu: %s (%s)\n", f.brand.c_str(), f.vendor.c_str());
  std::printf("isas:");
  for (rtk::Isa isa : rtk::kAllIsas)
    std::printf(" %s%s", std::string(rtk::isa_name(isa)).c_str(),
                rtk::isa_supported(isa) ? "" : "(no)");
  std::printf("\nvariant: %s%s\n", std::string(rtk::isa_name(chosen)).c_str(),
              requested.empty() ? " (best the CPU runs)" : " (forced by -isa)");
  return 0;
}

void usage() {
  std::fprintf(stderr,
               "usage: rtk info [-isa scalar|sse4|avx2|avx512]\n"
               "  info   print the CPU's instruction sets and the kernel variant chosen\n");
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string_view> args(argv + 1, argv + argc);
  if (args.empty()) {
    usage();
    return 2;
  }
  try {
    const std::string_view command = args.front();
    args.erase(args.begin());
    if (command == "info") return run_info(args);
    std::fprintf(stderr, "rtk: unknown command '%s'\n", std::string(command).c_str());
    usage();
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "rtk: %s\n", e.what());
    return 1;
  }
}
