// The rtk command line: one command per file (cmd_*.cpp), dispatched here; errors are reported
// here, one line on stderr that names the command and the option or file, and exit status 2.
#include <cstdio>
#include <exception>
#include <new>
#include <string>
#include <string_view>
#include <vector>

#include "commands.h"
#include "options.h"
#include "output_checks.h"

namespace {

constexpr const char* kUsage =
    "usage: rtk COMMAND [options]   (options take one dash or two)\n"
    "  info    [-isa scalar|sse4|avx2|avx512]\n"
    "          the CPU's instruction sets and the kernel variant chosen\n"
    "  rays    -i SCENE.obj -kind primary|diffuse|shadow|random -n COUNT [-seed K] -o R.rays\n"
    "          generate rays for a scene (deterministic for a seed; default seed 1)\n"
    "  trace   -i SCENE.obj -rays R.rays (-hits H.hits | -occl O.occl) [-motion S1.obj]\n"
    "          [-accel SPEC] [-tri SPEC] [-isa NAME] [-threads N] [-repeat N]\n"
    "          [-order auto|sorted|given] [-packets on|off]\n"
    "          trace rays with RTK; one JSON line per step on stdout (median of -repeat runs);\n"
    "          -order: sort an incoherent batch before tracing it (auto), always, or never\n"
    "          -packets: trace rays of one octant side by side where the batch allows (on)\n"
    "          -motion gives the scene at shutter time 1 (motion blur, -accel bvh4mb)\n"
    "  compare A.hits B.hits | A.occl B.occl [-rays R.rays] [-tolerance T] [-allow P] [-show N]\n"
    "          agreement of two tracers: exit 0 when at most P percent of the rays differ\n"
    "          (default 0), 1 when more do. Hits agree with the same primID and\n"
    "          |t1 - t2| <= T max(|t|, 1), or T max(|t|, |org|/|dir|) given the rays\n"
    "          (default T 1e-4); -show lists the first N differing rays (default 10)\n"
    "  render  [-c SCENE.ecs] [-size W H] [-spp N] [-depth N] [-seed N] [-threads N] [-accel "
    "SPEC]\n"
    "          [-tri SPEC] [-isa NAME] [-kernels rtk|embree] [any option of the guide's scripts]\n"
    "          [-time SECONDS] [-reference IMAGE.pfm] -o IMAGE.png|tga|ppm|hdr|pfm\n"
    "          render with the path tracer, on RTK's kernels or (-kernels embree) on Embree's;\n"
    "          -time renders progressively until the time is spent (instead of -spp),\n"
    "          -reference prints the relative RMS error against a converged image;\n"
    "          `rtk -c SCENE.ecs ... -o IMAGE` is the same\n"
    "  view    [-c SCENE.ecs] [options of render] [-frames N [-screenshot FILE.png]]\n"
    "          the interactive viewer (also `rtk -c SCENE.ecs` without -o): mouse orbits, pans,\n"
    "          dollies; c prints the camera; -frames N closes it after N frames,\n"
    "          -screenshot then saves the window\n"
    "  help    this text, with every option of render, view and the scripts (also -help;\n"
    "          `rtk render -help` and `rtk -c SCENE.ecs -help` list those options alone)\n"
    "  version the version and the kernels compiled in (also -version)\n"
    "exit status: 0 success, 1 compare found differences, 2 error (message on stderr),\n"
    "  130 or 143 a render stopped by SIGINT or SIGTERM (the image so far is written)\n";

bool is_help(std::string_view a) { return a == "help" || a == "-h" || a == "-help" || a == "--help"; }
bool is_version(std::string_view a) { return a == "version" || a == "-version" || a == "--version"; }

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string_view> args(argv + 1, argv + argc);
  if (args.empty()) {
    std::fputs(kUsage, stderr);
    return rtk::cli::kExitError;
  }
  const std::string command(args.front());
  const std::span<const std::string_view> rest(args.data() + 1, args.size() - 1);
  try {
    // Standard output carries results: a closed one is found before any work is done, and a
    // write that fails at the end (a full disk) is an error too.
    rtk::cli::check_stdout();
    const int status = [&] {
      // -help anywhere: the commands, or the options of the command it follows (render, view
      // and the guide's short form, whose options are the scripts').
      const bool renders = command == "render" || command == "view" ||
                           (command.size() > 1 && command[0] == '-' && !is_help(command) && !is_version(command));
      if (is_help(command)) {
        std::fputs(kUsage, stdout);
        std::fputs("\n", stdout);
        rtk::cli::print_render_options(stdout);
        return 0;
      }
      for (std::string_view a : rest)
        if (is_help(a) && a != "help") {
          if (renders)
            rtk::cli::print_render_options(stdout);
          else
            std::fputs(kUsage, stdout);
          return 0;
        }
      if (is_version(command)) return rtk::cli::run_version();
      if (command == "info") return rtk::cli::run_info(rest);
      if (command == "rays") return rtk::cli::run_rays(rest);
      if (command == "trace") return rtk::cli::run_trace(rest);
      if (command == "compare") return rtk::cli::run_compare(rest);
      if (command == "render") return rtk::cli::run_render(rest);
      if (command == "view") return rtk::cli::run_render(rest, true);
      // The guide's short form: options without a command render (rtk -c scene.ecs -o out.png).
      if (renders) return rtk::cli::run_render(command == "render" || command == "view" ? rest : args,
                                               command != "render");
      std::fprintf(stderr, "rtk: unknown command '%s'\n%s", command.c_str(), kUsage);
      return rtk::cli::kExitError;
    }();
    rtk::cli::flush_stdout();
    return status;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr,
                 "rtk %s: out of memory: the inputs or options ask for more memory than there is\n",
                 command.c_str());
  } catch (const rtk::cli::UsageError& e) {
    std::fprintf(stderr, "rtk %s: %s (see 'rtk help')\n", command.c_str(), e.what());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "rtk %s: %s\n", command.c_str(), e.what());
  }
  return rtk::cli::kExitError;
}
