/// \file
/// The guide's command scripts (.ecs): a file of command-line options, read left to right,
/// that loads geometry, places the camera and lights and sets the renderer's options. The
/// command line of `rtk render` is read by the same parser, so that anything a script says,
/// the command line can say after it (and override).
///
/// Options (as in Embree 1.1's viewer, plus RTK's -motion, -isa, -kernels, -seed, -sampler,
/// -filter, -focaldistance): -c FILE, -i FILE (.obj with its .mtl, or .xml: scene/xml_scene.h),
/// -motion FILE (the previous -i at shutter time 1), -vp/-vi/-vu/-vd x y z, -fov/-angle deg,
/// -radius r, -focaldistance d, -size w h, -spp n, -depth n, -gamma g, -renderer NAME
/// [{ key = value ... }] (pathtracer/pt with depth, spp; debug), -accel, -tri, -isa,
/// -kernels rtk|embree, -threads n,
/// -seed n, -ambientlight r g b, -pointlight p I, -directionallight/-dirlight d E,
/// -distantlight d L halfAngle, -trianglelight P U V L, -quadlight P U V L, -hdrilight r g b
/// FILE, -trisphere p r numTheta numPhi, -o FILE. -vignetting, -backplate, -display,
/// -fullscreen and -refine are read and ignored with a warning. `#` starts a comment; files
/// are named relative to the script that names them.
#pragma once

#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "11_materials/material.h"
#include "13_pathtracer/render.h"
#include "13_pathtracer/scene.h"
#include "09_kernel_api/accel.h"
#include "image/tonemap.h"

namespace rtk {

/// Everything the scripts and the command line said, in the order they said it.
struct SceneScript {
  RenderScene scene;                         ///< geometry, materials, lights, camera
  RenderOptions options;                     ///< size, spp, depth, seed, threads, renderer
  ToneMap tone;                              ///< -gamma
  AccelConfig accel;                         ///< -accel, -tri, -isa (threads: options.threads)
  std::string kernels = "rtk";               ///< -kernels rtk|embree: who traces the rays
  std::vector<std::filesystem::path> outputs;  ///< every -o, in order
  std::vector<std::filesystem::path> files;    ///< every file read (scripts and geometry)
};

/// Reads a command script into `script`. Throws FileError "FILE:LINE: message" for any
/// error: an unknown option, a missing or malformed argument, an unbalanced { }, a file that
/// cannot be read or parsed (then the message is that file's own), a script that includes
/// itself. Warnings (ignored options, approximated materials) go to `warn`.
void read_script_file(const std::filesystem::path& path, SceneScript& script,
                      const WarningHandler& warn = {});

/// Reads command-line arguments with the same rules; files are relative to the current
/// folder, and errors name "command line" and the argument's position instead of a line.
void read_script_args(std::span<const std::string_view> args, SceneScript& script,
                      const WarningHandler& warn = {});

}  // namespace rtk
