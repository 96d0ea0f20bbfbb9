/// \file
/// A triangle mesh in linear motion over the shutter [0, 1]: the vertices at time 0, and the
/// motion of those vertices that move, stored sparsely (only the moving ones) or densely (all).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

#include "01_base/ray.h"
#include "01_base/triangle_mesh.h"

namespace rtk {

/// How a MotionMesh stores the motion of its vertices.
enum class MotionStorage : uint8_t {
  /// A motion vector for every vertex: 24 bytes per vertex, static ones included.
  dense,
  /// Motion vectors for the moving vertices only, found through a per-vertex slot: 16 bytes per
  /// vertex plus 12 per moving vertex. Slot 0 holds the zero vector that every static vertex
  /// shares, so the kernels read all vertices the same way, with no branch.
  sparse,
};

/// The name used in tables and benchmarks: "dense" or "sparse".
constexpr std::string_view motion_storage_name(MotionStorage storage) {
  return storage == MotionStorage::dense ? "dense" : "sparse";
}

// [ch08-vertex-at]
/// Where a vertex is at `time`: p0 + time * d, with d = p1 - p0 its motion over the shutter.
/// Every variant (scalar and SIMD kernels, the builder, the tests' oracle) computes a vertex
/// with exactly these two roundings, so they all see the same triangles. At time 0, and for a
/// vertex that does not move (d = 0), the result is p0 exactly; at time 1 it is p0 + d, which
/// is p1 up to the rounding of the difference.
constexpr Vec3f vertex_at(Vec3f p0, Vec3f d, float time) {
  return {p0.x + time * d.x, p0.y + time * d.y, p0.z + time * d.z};
}
// [ch08-vertex-at]

// [ch08-motion-ray]
/// Whether a ray is a ray for a motion-blur structure: a valid ray (rtk::is_valid) whose time
/// lies in the shutter [0, 1]. A NaN time or one outside the shutter is a miss: the scene
/// says nothing about where its triangles are then (extrapolating the motion would invent
/// geometry, clamping would hide a caller's bug), and the node boxes bound the triangles only
/// within the shutter. Static structures ignore the time.
inline bool is_valid_motion_ray(const Ray& ray) {
  return is_valid(ray) && ray.time >= 0.0f && ray.time <= 1.0f;
}
// [ch08-motion-ray]

// [ch08-motion-mesh]
/// A triangle mesh whose vertices move linearly from `base.vertices` (time 0) by their motion
/// vectors (time 1). The triangles never change; only positions move.
struct MotionMesh {
  TriangleMesh base;  ///< the triangles, and the vertices at time 0
  MotionStorage storage = MotionStorage::sparse;
  /// Dense: the motion of vertex v is motion[v]. Sparse: motion[0] is the zero vector, and the
  /// motion of vertex v is motion[slot[v]].
  std::vector<Vec3f> motion;
  std::vector<uint32_t> slot;  ///< sparse only: one entry per vertex, 0 for a static vertex
  size_t moving = 0;           ///< vertices whose motion is not zero

  size_t size() const { return base.size(); }
  /// The motion vector of vertex v.
  Vec3f motion_of(uint32_t v) const { return storage == MotionStorage::dense ? motion[v] : motion[slot[v]]; }
  /// Vertex v at `time`.
  Vec3f position(uint32_t v, float time) const { return vertex_at(base.vertices[v], motion_of(v), time); }
  /// The box of triangle `prim` at `time`.
  Box3f bounds(uint32_t prim, float time) const;
  /// The whole mesh at `time`: what a ray with that time sees (the tests' oracle uses it).
  TriangleMesh at(float time) const;
  /// Whether anything moves.
  bool moves() const { return moving != 0; }
  /// Bytes of vertex data: positions, motion vectors and slots.
  size_t vertex_bytes() const {
    return base.vertices.size() * sizeof(Vec3f) + motion.size() * sizeof(Vec3f) + slot.size() * sizeof(uint32_t);
  }
};
// [ch08-motion-mesh]

/// Throws std::invalid_argument unless `t1` can be the mesh `t0` at time 1: the same number of
/// vertices, the same number of triangles, and the same vertex indices in every triangle. The
/// message names both (`name0`, `name1`: file names, or "t0" and "t1") and the first mismatch.
void check_motion_pair(const TriangleMesh& t0, const TriangleMesh& t1, std::string_view name0 = "t0",
                       std::string_view name1 = "t1");

/// Makes the moving mesh whose vertices are at `t0` at time 0 and `t1` at time 1 (checked with
/// check_motion_pair(), which throws). A vertex index out of range throws
/// std::invalid_argument. A vertex moves when any component of p1 - p0 is not zero (a NaN
/// motion counts as moving; the builder then leaves its triangles out, and they are never hit).
MotionMesh make_motion_mesh(const TriangleMesh& t0, const TriangleMesh& t1,
                            MotionStorage storage = MotionStorage::sparse);

/// The same moving mesh with its motion stored the other way.
MotionMesh convert_storage(const MotionMesh& mesh, MotionStorage storage);

}  // namespace rtk
