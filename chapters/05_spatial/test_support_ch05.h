/// \file
/// Test-only support for chapter 5: the scenes the tests share and an independent check of a
/// spatial-split tree and its clipped references.
#pragma once

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "02_bvh2/build_tree.h"
#include "05_spatial/architecture_scene.h"
#include "05_spatial/spatial_options.h"
#include "testing/scenes.h"

namespace rtk::test {

/// A scene with a name, for CAPTURE.
struct NamedMesh {
  std::string name;
  TriangleMesh mesh;
};

/// Triangles lying in the planes x = 0.5, y = 0.5 and z = 0.5 of the unit cube, where centre
/// splits put their planes, plus diagonal slivers through them.
inline TriangleMesh make_axis_planes(int per_plane, uint64_t seed) {
  TriangleMesh m = make_slivers(per_plane, seed);
  for (int axis = 0; axis < 3; ++axis)
    for (int i = 0; i < per_plane; ++i) {
      const float a = float(i) / float(per_plane), b = float(i + 1) / float(per_plane);
      const uint32_t base = uint32_t(m.vertices.size());
      Vec3f p[3] = {Vec3f(0.5f), Vec3f(0.5f), Vec3f(0.5f)};
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      p[0][u] = a, p[0][v] = 0.0f;
      p[1][u] = b, p[1][v] = 0.0f;
      p[2][u] = a, p[2][v] = 1.0f;
      for (const Vec3f& q : p) m.vertices.push_back(q);
      m.triangles.push_back({base, base + 1, base + 2});
    }
  return m;
}

/// The scenes the tree and ray tests share: small enough for sanitizer builds.
inline std::vector<NamedMesh> spatial_scenes() {
  std::vector<NamedMesh> s;
  s.push_back({"slivers", make_slivers(1200, 502)});
  s.push_back({"architecture", make_architecture(4, 60, 24, 503)});
  s.push_back({"sphere", make_sphere(16, 32)});
  TriangleMesh soup = make_random_soup(1500, 504);
  add_degenerate_triangles(soup, 60, 505);
  s.push_back({"soup+degenerate", std::move(soup)});
  s.push_back({"axis-planes", make_axis_planes(150, 506)});
  return s;
}

/// Why a spatial-split tree over `mesh` is wrong, or an empty string. `refs` are the leaf
/// references (build_spatial_sah's `leaf_refs`). Checked: refs[i].prim == prim_ids[i]; every
/// reference box lies in its triangle's box and in its leaf's box, and each leaf's box is the
/// union of its references; every box lies in its parent's; 2 to N children per node; leaves
/// of at most `max_leaf`; every buildable triangle referenced at least once, and every sampled
/// point of it inside one of its references' boxes; at most `budget` extra references.
template <int N>
std::string check_spatial_tree(const BuildTree<N>& tree, const std::vector<PrimRef>& refs,
                               const TriangleMesh& mesh, int max_leaf, size_t budget) {
  std::ostringstream err;
  if (refs.size() != tree.prim_ids.size()) return "leaf_refs and prim_ids differ in length";
  const std::vector<PrimRef> tris = make_prim_refs(mesh);
  std::vector<std::vector<Box3f>> parts(mesh.size());
  size_t buildable = 0;
  for (const PrimRef& t : tris) buildable += is_buildable(t) ? 1 : 0;
  if (refs.size() > buildable + budget) err << refs.size() << " references exceed the budget; ";
  for (size_t i = 0; i < refs.size(); ++i) {
    if (refs[i].prim != tree.prim_ids[i]) return "leaf_refs and prim_ids disagree";
    if (refs[i].prim >= mesh.size()) return "bad primitive ID";
    if (!is_buildable(tris[refs[i].prim])) err << "unbuildable triangle referenced; ";
    if (refs[i].box().empty() || !tris[refs[i].prim].box().contains(refs[i].box()))
      err << "reference " << i << " leaves its triangle's box; ";
    parts[refs[i].prim].push_back(refs[i].box());
  }
  // Every triangle is covered: sampled points (in double, then checked with a tolerance of a
  // millionth of the scene) lie in some reference box of that triangle.
  const Box3f scene = mesh.bounds();
  const float tol = 1e-6f * std::max({scene.size().x, scene.size().y, scene.size().z, 1e-30f});
  for (uint32_t p = 0; p < mesh.size(); ++p) {
    if (!is_buildable(tris[p])) continue;
    if (parts[p].empty()) {
      err << "triangle " << p << " is not referenced; ";
      continue;
    }
    const Vec3f a = mesh.vertex(p, 0), b = mesh.vertex(p, 1), c = mesh.vertex(p, 2);
    const int n = 8;
    for (int i = 0; i <= n; ++i)
      for (int j = 0; i + j <= n; ++j) {
        const double s = double(i) / n, t = double(j) / n;
        const Vec3f q{float(a.x + s * (double(b.x) - a.x) + t * (double(c.x) - a.x)),
                      float(a.y + s * (double(b.y) - a.y) + t * (double(c.y) - a.y)),
                      float(a.z + s * (double(b.z) - a.z) + t * (double(c.z) - a.z))};
        bool inside = false;
        for (const Box3f& box : parts[p]) {
          Box3f grown = box;
          grown.lower = grown.lower - Vec3f(tol), grown.upper = grown.upper + Vec3f(tol);
          inside = inside || grown.contains(q);
        }
        if (!inside) {
          err << "a point of triangle " << p << " is in none of its references; ";
          return err.str();
        }
      }
  }
  // The structure, top down.
  if (tree.empty()) return refs.empty() ? err.str() : "an empty tree with references";
  struct Item {
    typename BuildTree<N>::Child child;
    Box3f parent;
  };
  std::vector<Item> todo = {{tree.root, tree.root.box}};
  std::vector<int> covered(refs.size(), 0);
  size_t visited = 0;
  while (!todo.empty()) {
    const Item it = todo.back();
    todo.pop_back();
    if (!it.parent.contains(it.child.box)) err << "a box leaves its parent's; ";
    if (it.child.is_leaf()) {
      if (it.child.leaf_count > uint32_t(max_leaf)) err << "leaf of " << it.child.leaf_count << "; ";
      if (size_t(it.child.index) + it.child.leaf_count > refs.size()) return "leaf out of range";
      Box3f u;
      for (uint32_t i = it.child.index; i < it.child.index + it.child.leaf_count; ++i)
        u.extend(refs[i].box()), ++covered[i];
      if (!(u == it.child.box)) err << "a leaf box is not the union of its references; ";
      continue;
    }
    if (it.child.index >= tree.nodes.size() || ++visited > tree.nodes.size()) return "bad node index";
    const auto& node = tree.nodes[it.child.index];
    if (node.num_children < 2 || node.num_children > N) err << "node with " << node.num_children << " children; ";
    for (int c = 0; c < node.num_children; ++c) todo.push_back({node.children[size_t(c)], it.child.box});
  }
  for (int c : covered)
    if (c != 1) return err.str() + "a leaf entry is covered " + std::to_string(c) + " times";
  if (visited != tree.nodes.size()) err << "unreachable nodes; ";
  return err.str();
}

}  // namespace rtk::test
