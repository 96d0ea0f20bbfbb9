/// \file
/// What a scene script says, as objects of chapter 15's device: `rtk render` and the viewer
/// read the script with lib/scene, hand its scene to the device with import_scene, and make
/// the camera, the renderer and the framebuffer from its settings through handles. Frames are
/// then rendered by the device, from committed versions only.
#pragma once

#include "15_device/device.h"
#include "scene/scene_script.h"

namespace rtk::cli {

/// The script's scene, imported and committed with its -accel, -tri, -isa and `threads` build
/// threads. Throws std::invalid_argument (from the commit) for a configuration RTK lacks.
Handle commit_scene(Device& device, const SceneScript& script, int threads);
/// The same for `scene` (the script's as it was at one -o) with the script's configuration.
Handle commit_scene(Device& device, const RenderScene& scene, const SceneScript& config, int threads);

/// A committed camera of `params` ("pinhole", or "thinlens" with a lens radius).
Handle commit_camera(Device& device, const CameraParams& params);

/// Sets `params` on an existing camera and commits its new version (a "pinhole" camera takes
/// no lens; a "thinlens" camera with radius 0 is a pinhole).
void commit_camera(Device& device, const Handle& camera, const CameraParams& params);

/// A committed renderer with `options` ("pathtracer", or "debug" for the guide's eye light).
Handle commit_renderer(Device& device, const RenderOptions& options);

/// A committed framebuffer of width x height pixels.
Handle commit_framebuffer(Device& device, int width, int height);

/// Commits a new, empty version of width x height pixels of an existing framebuffer.
void commit_framebuffer(Device& device, const Handle& framebuffer, int width, int height);

}  // namespace rtk::cli
