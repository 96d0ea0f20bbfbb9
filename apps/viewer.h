/// \file
/// The interactive viewer (chapter 16): `rtk -c scene.ecs` without -o opens a window that
/// shows the scene refined progressively, with the guide's orbit-camera controls. GLFW and
/// OpenGL draw chapter 14's framebuffer, tone-mapped, as a texture.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "scene/scene_script.h"

namespace rtk::cli {

/// The viewer's own options, which the scene scripts do not know: test hooks that make a
/// window session reproducible.
struct ViewerOptions {
  int frames = 0;          ///< -frames N: close the window after N frames (0: when the user does)
  /// -screenshot FILE: save the window's pixels after the last of the -frames (which it needs).
  std::string screenshot;
};

/// Takes -frames N and -screenshot FILE (one dash or two) out of `args` into `options` and
/// returns the other arguments, in order, for the scene-script parser. Throws UsageError for
/// a missing or bad value, or a -screenshot without -frames.
std::vector<std::string_view> take_viewer_options(std::span<const std::string_view> args,
                                                  ViewerOptions& options);

/// Opens the window and runs it until it is closed (or -frames is reached); returns the exit
/// status. Builds the kernels for `script`'s scene first. Throws std::runtime_error with a
/// message that says how to render to a file instead when no window can be opened (no
/// display, no OpenGL).
int run_viewer(SceneScript& script, const ViewerOptions& options);

}  // namespace rtk::cli
