/// \file
/// Writes a triangle mesh as OBJ text that load_obj() reads back bit for bit: the benchmarks
/// and tests turn procedural scenes into files with it, so that `rtk` sees the same triangles.
#pragma once

#include <filesystem>
#include <string>

#include "01_base/triangle_mesh.h"

namespace rtk {

/// The mesh as OBJ text: one `v` line per vertex, with the shortest decimal form that reads
/// back as the same float (std::to_chars), then one `f` line per triangle (1-based indices).
std::string format_obj(const TriangleMesh& mesh);

/// Writes format_obj(mesh) to a file; throws FileError naming the file on failure.
void save_obj(const std::filesystem::path& path, const TriangleMesh& mesh);

}  // namespace rtk
