/// \file
/// MTL material libraries (the `mtllib` of OBJ files), read into chapter 12's "OBJ" materials.
///
/// Keys: `newmtl NAME`; `Kd Ks Tf` (three numbers or one grey, each from 0 to 1), `Ka Ke`
/// (0 to 1e10: the guide's files give Ka 20, lamps need large Ke); `Ns` (0 to 1e6), `Ni` (0 to
/// 10), `d` and `Tr` (0 to 1), `illum` (a whole number from 0 to 10); `map_Kd [options] FILE`
/// (a texture, relative to the MTL file, read by the scene's TextureConventions: RTK's decode
/// 8-bit files from sRGB, Embree 1.1's read them as linear); `map_d [options] FILE` (opacity)
/// and `map_Bump` or `bump [-bm SCALE] [options] FILE` (heights), data maps read as linear
/// values and interpolated; other texture options are ignored with a warning. Every value is
/// checked where it is read, so that an error names the MTL file and line; a material that
/// chapter 12 refuses as a whole is reported at its `newmtl` line. Other keys (map_Ks, ...)
/// are warned about once per file and ignored.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <string_view>

#include "12_materials/material.h"
#include "14_pathtracer/scene.h"

namespace rtk {

/// Reads the MTL file at `path` (at most kMaxTextFileBytes) into materials added to `scene`;
/// returns each material's index by name. Throws FileError "FILE:LINE: message".
std::map<std::string, uint32_t> load_mtl(const std::filesystem::path& path, RenderScene& scene,
                                         const WarningHandler& warn = {},
                                         const TextureConventions& conventions = {});

/// load_mtl on the text of the file named `path` (textures are relative to its folder), for
/// the fuzzer.
std::map<std::string, uint32_t> read_mtl_text(std::string_view text,
                                              const std::filesystem::path& path, RenderScene& scene,
                                              const WarningHandler& warn = {},
                                              const TextureConventions& conventions = {});

}  // namespace rtk
