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
/// FILE, -trisphere p r numTheta numPhi, -righthanded, -lefthanded, -o FILE (rendered with the
/// state set up before it; ScriptOutput), -conventions, -backplate, and the viewer's -fullscreen
/// and -refine; -vignetting 0|1 (the cos^4 falloff of chapter 11's camera). RTK's own -time SECONDS and
/// -reference IMAGE are for `rtk render` (equal-time rendering and its error).
/// script_option_help() lists them all. `#` starts a comment; files are named relative to the
/// script that names them.
///
/// Every value is checked where it is read, so that its error names the file and line (or
/// the command line's argument): numbers are finite and in their option's range (-fov
/// between 0 and 180, -radius and -focaldistance not negative, -vu and -vd not zero, ...), an
/// output file's folder exists and may be written (check_output_path). What can only be
/// judged once everything is read (whether -vp, -vi and -vu make a camera; whether -accel and
/// -tri suit the scene) is checked by the device, and SceneScript::given_at keeps where those
/// options were given for its messages. Limits: scene/scene_limits.h.
#pragma once

#include <filesystem>
#include <initializer_list>
#include <map>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "10_kernel_api/accel.h"
#include "12_materials/material.h"
#include "14_pathtracer/render.h"
#include "14_pathtracer/scene.h"
#include "image/tonemap.h"
#include "scene/parse_number.h"

namespace rtk {

/// What an `-o` renders: the state the scripts and the command line had set up when they
/// named it, as in Embree 1.1, where each -o renders at its position (two -o with different
/// -size between them give two different images).
struct ScriptOutput {
  std::filesystem::path path;  ///< the image file
  /// Counts the options read before this -o: two outputs with the same count (nothing between
  /// them) are the same image, rendered once.
  uint64_t state = 0;
  RenderOptions options;
  ToneMap tone;
  CameraParams camera;
  AccelConfig accel;
  std::string kernels;
  /// The scene as it was at this -o, kept only once a later option changed it (geometry or a
  /// light added); null: the scene is SceneScript::scene.
  std::shared_ptr<const RenderScene> scene;
};

/// Everything the scripts and the command line said, in the order they said it.
struct SceneScript {
  RenderScene scene;                         ///< geometry, materials, lights, camera
  RenderOptions options;                     ///< size, spp, depth, seed, threads, renderer
  ToneMap tone;                              ///< -gamma
  AccelConfig accel;                         ///< -accel, -tri, -isa (threads: options.threads)
  std::string kernels = "rtk";               ///< -kernels rtk|embree: who traces the rays
  bool fullscreen = false;                   ///< -fullscreen: the viewer fills the screen
  bool refine = true;                        ///< -refine 0|1: the viewer refines progressively
  /// -conventions embree1.1|rtk: how the images read after it map onto surfaces and the sky.
  /// Scripts are the guide's unless they say otherwise, so Embree 1.1's are the default.
  TextureConventions conventions = TextureConventions::embree11();
  std::vector<ScriptOutput> output_states;     ///< every -o, in order, and what it renders
  uint64_t options_read = 0;                   ///< how many options were read (ScriptOutput::state)
  /// The first option read after the last -o (empty when none was, or no -o was given): it
  /// changes no image, which `rtk render` says.
  std::string after_last_output;
  /// -time SECONDS: render progressively until this much time is spent (0: -spp samples).
  double time_limit = 0;
  /// -reference IMAGE: a converged image (.pfm, .hdr or .exr, linear) to report the error against.
  std::filesystem::path reference;
  std::vector<std::filesystem::path> files;    ///< every file read (scripts and geometry)
  /// Where each option checked only after reading was last given, by name ("-vp", "-vi" (also
  /// for -vd), "-vu", "-fov", "-radius", "-focaldistance", "-accel", "-tri", "-isa", "-kernels").
  std::map<std::string, scene_io::Where, std::less<>> given_at;
};

/// One option of the scripts (and of `rtk render`'s command line), as -help lists it.
struct ScriptOptionHelp {
  std::string_view name;       ///< "-vp"
  std::string_view arguments;  ///< "x y z"
  std::string_view meaning;    ///< one line
};
/// Every option read_script_file and read_script_args accept, in the order -help lists them
/// (a test checks that every option the reader knows is here).
std::span<const ScriptOptionHelp> script_option_help();

/// Runs `make` (a device commit of the script's camera or scene) and turns its
/// std::invalid_argument into a FileError at the place where an option of `options` was
/// given: the first that the message names (the message is then told from that name on), or
/// else the first given, with the option's name in front: "view.ecs:3: -vi: camera: look-at
/// point equals the camera position". When none of them was given (the defaults were refused) the
/// error passes unchanged.
template <class Make>
auto at_given_place(const SceneScript& script, std::initializer_list<std::string_view> options,
                    Make&& make) {
  try {
    return make();
  } catch (const std::invalid_argument& e) {
    const std::string_view message = e.what();
    auto given = [&](bool named) -> const std::pair<const std::string, scene_io::Where>* {
      for (std::string_view o : options)
        if (auto it = script.given_at.find(o);
            it != script.given_at.end() && (!named || message.find(o) != message.npos))
          return &*it;
      return nullptr;
    };
    const auto* place = given(true);
    if (!place) place = given(false);
    if (!place) throw;
    // A message that names the option ("rtk device: scene #1: -accel: ...") is told from
    // there on; another gets the option's name in front.
    const size_t named = message.find(place->first + ":");
    scene_io::fail(place->second, named != std::string_view::npos
                                      ? std::string(message.substr(named))
                                      : place->first + ": " + std::string(message));
  }
}

/// Reads a command script into `script`. Throws FileError "FILE:LINE: message" for any
/// error: an unknown option, a missing or malformed argument, an unbalanced { }, a file that
/// cannot be read or parsed (then the message is that file's own), a script that includes
/// itself. Warnings (ignored options, approximated materials) go to `warn`.
void read_script_file(const std::filesystem::path& path, SceneScript& script,
                      const WarningHandler& warn = {});

/// Reads the text of a command script named `path` (files it names are relative to its
/// folder): read_script_file without reading the script itself, for the fuzzer.
void read_script_text(std::string_view text, const std::filesystem::path& path, SceneScript& script,
                      const WarningHandler& warn = {});

/// Reads command-line arguments with the same rules; files are relative to the current
/// folder, and errors name "command line" and the argument's position instead of a line.
void read_script_args(std::span<const std::string_view> args, SceneScript& script,
                      const WarningHandler& warn = {});

}  // namespace rtk
