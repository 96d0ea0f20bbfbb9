/// \file
/// What the traversal benchmarks of chapters 2 and 3 share: scenes (procedural, and real meshes
/// from the folder the RTK_SCENES environment variable names), and the rays they trace.
/// Benchmark code only.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "01_base/ray.h"
#include "01_base/triangle_mesh.h"

namespace rtk::bench {

/// A scene for the benchmarks: its name, and its file when it is a real mesh.
struct SceneSource {
  std::string name;
  std::string path;  ///< empty for a procedural scene
};

/// The procedural scenes, then the real meshes found under $RTK_SCENES (skipped when the
/// variable is unset or a file is missing).
std::vector<SceneSource> bench_scenes();

/// Makes or loads a scene's mesh (once per name; later calls return the cached mesh).
const TriangleMesh& scene_mesh(const SceneSource& source);

/// Reads the `v` and `f` lines of a Wavefront OBJ file (the ray-replay subset: fan
/// triangulation, `i`, `i/t`, `i//n`, `i/t/n` and negative indices). Throws std::runtime_error
/// naming the file and line of anything malformed. A stopgap until the project's loader (lib/)
/// can be used from a chapter.
TriangleMesh read_obj_vf(const std::string& path);

/// Primary rays: a pinhole camera outside the scene's box, looking at its centre, one ray per
/// pixel of a width x height image. Coherent: neighbours take nearly the same path.
std::vector<Ray> primary_rays(const TriangleMesh& mesh, int width, int height);

/// Diffuse rays: from random points on random triangles (slightly off the surface, on a random
/// side) in cosine-distributed directions about the normal. Incoherent, like the secondary
/// rays of a path tracer. Deterministic for a seed.
std::vector<Ray> diffuse_rays(const TriangleMesh& mesh, int count, uint64_t seed);

}  // namespace rtk::bench
