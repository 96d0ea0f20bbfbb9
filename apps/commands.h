/// \file
/// The commands of `rtk`, one file each (cmd_*.cpp). A command takes its arguments (without
/// the command's name) and returns the exit status; errors are thrown (cli::UsageError for the
/// command line, rtk::FileError for files) and reported by main().
///
/// Exit status, for every command: 0 success; 1 `compare` found disagreements beyond what
/// its options allow; 2 an error, with a message on stderr that names the option, or the file
/// and line.
#pragma once

#include <cstdio>
#include <span>
#include <string_view>

namespace rtk::cli {

/// The exit status of a command that found its inputs to differ (`rtk compare`).
inline constexpr int kExitDiffer = 1;
/// The exit status of a command that could not do its work.
inline constexpr int kExitError = 2;

/// `rtk info [-isa NAME]`: the CPU, its instruction sets and the variant that runs.
int run_info(std::span<const std::string_view> args);
/// `rtk rays -i SCENE.obj -kind K -n COUNT [-seed S] -o R.rays`.
int run_rays(std::span<const std::string_view> args);
/// `rtk trace -i SCENE.obj -rays R.rays (-hits H.hits | -occl O.occl) [...]`.
int run_trace(std::span<const std::string_view> args);
/// `rtk compare A B [-rays R.rays] [-tolerance T] [-allow P] [-show N]`.
int run_compare(std::span<const std::string_view> args);
/// `rtk render [-c SCENE.ecs] [guide options...] -o IMAGE`: the path tracer (chapter 14).
/// With `viewer_without_output` (`rtk view`, and the guide's short form `rtk -c SCENE.ecs`),
/// no -o opens the interactive viewer (chapter 16) instead of being an error.
int run_render(std::span<const std::string_view> args, bool viewer_without_output = false);
/// `rtk render -help` (also `rtk view -help`, `rtk -c SCENE.ecs -help`): every option of the
/// scripts and of the command line, one line each, and the viewer's own.
void print_render_options(std::FILE* out);
/// `rtk version` (-version): the version, the kernel variants compiled in and the kernels the
/// renderer can run on.
int run_version();

}  // namespace rtk::cli
