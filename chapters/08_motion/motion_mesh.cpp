#include "08_motion/motion_mesh.h"

#include <stdexcept>
#include <string>

namespace rtk {

namespace {

std::string mismatch(std::string_view name0, std::string_view name1, const std::string& what) {
  return "the motion mesh " + std::string(name1) + " does not match " + std::string(name0) + ": " + what +
         " (the mesh at time 1 must have the same vertices and faces, moved)";
}

std::string triangle_text(const std::array<uint32_t, 3>& t) {
  return "(" + std::to_string(t[0]) + ", " + std::to_string(t[1]) + ", " + std::to_string(t[2]) + ")";
}

}  // namespace

Box3f MotionMesh::bounds(uint32_t prim, float time) const {
  Box3f box;
  for (int k = 0; k < 3; ++k) box.extend(position(base.triangles[prim][size_t(k)], time));
  return box;
}

TriangleMesh MotionMesh::at(float time) const {
  TriangleMesh mesh;
  mesh.triangles = base.triangles;
  mesh.vertices.resize(base.vertices.size());
  for (uint32_t v = 0; v < base.vertices.size(); ++v) mesh.vertices[v] = position(v, time);
  return mesh;
}

void check_motion_pair(const TriangleMesh& t0, const TriangleMesh& t1, std::string_view name0,
                       std::string_view name1) {
  if (t0.vertices.size() != t1.vertices.size())
    throw std::invalid_argument(mismatch(name0, name1,
                                         std::to_string(t1.vertices.size()) + " vertices against " +
                                             std::to_string(t0.vertices.size())));
  if (t0.triangles.size() != t1.triangles.size())
    throw std::invalid_argument(mismatch(name0, name1,
                                         std::to_string(t1.triangles.size()) + " triangles against " +
                                             std::to_string(t0.triangles.size())));
  for (size_t i = 0; i < t0.triangles.size(); ++i)
    if (t0.triangles[i] != t1.triangles[i])
      throw std::invalid_argument(mismatch(name0, name1,
                                           "triangle " + std::to_string(i) + " is " + triangle_text(t1.triangles[i]) +
                                               " but " + triangle_text(t0.triangles[i]) + " in " +
                                               std::string(name0)));
}

// [ch08-make-sparse]
MotionMesh make_motion_mesh(const TriangleMesh& t0, const TriangleMesh& t1, MotionStorage storage) {
  check_motion_pair(t0, t1);
  for (size_t i = 0; i < t0.triangles.size(); ++i)
    for (uint32_t index : t0.triangles[i])
      if (index >= t0.vertices.size())
        throw std::invalid_argument("triangle " + std::to_string(i) + " names vertex " + std::to_string(index) +
                                    " of a mesh with " + std::to_string(t0.vertices.size()));
  MotionMesh mesh;
  mesh.base = t0;
  mesh.storage = storage;
  const size_t n = t0.vertices.size();
  if (storage == MotionStorage::dense) mesh.motion.resize(n);
  else mesh.slot.assign(n, 0), mesh.motion.push_back(Vec3f(0.0f));  // slot 0: the shared zero motion
  for (size_t v = 0; v < n; ++v) {
    const Vec3f d = t1.vertices[v] - t0.vertices[v];
    // `!(d == 0)` rather than `d != 0`: a NaN motion is kept, so that the builder sees it.
    const bool moves = !(d.x == 0.0f && d.y == 0.0f && d.z == 0.0f);
    mesh.moving += moves ? 1 : 0;
    if (storage == MotionStorage::dense) {
      mesh.motion[v] = moves ? d : Vec3f(0.0f);
    } else if (moves) {
      mesh.slot[v] = uint32_t(mesh.motion.size());
      mesh.motion.push_back(d);
    }
  }
  return mesh;
}
// [ch08-make-sparse]

MotionMesh convert_storage(const MotionMesh& mesh, MotionStorage storage) {
  MotionMesh out;
  out.base = mesh.base;
  out.storage = storage;
  out.moving = mesh.moving;
  const size_t n = mesh.base.vertices.size();
  if (storage == MotionStorage::dense) {
    out.motion.resize(n);
    for (uint32_t v = 0; v < n; ++v) out.motion[v] = mesh.motion_of(v);
  } else {
    out.slot.assign(n, 0);
    out.motion.push_back(Vec3f(0.0f));
    for (uint32_t v = 0; v < n; ++v) {
      const Vec3f d = mesh.motion_of(v);
      if (d.x == 0.0f && d.y == 0.0f && d.z == 0.0f) continue;
      out.slot[v] = uint32_t(out.motion.size());
      out.motion.push_back(d);
    }
  }
  return out;
}

}  // namespace rtk
