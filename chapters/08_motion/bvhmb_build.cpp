#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "02_bvh2/build_tree.h"
#include "04_sah/build_sah.h"
#include "06_layouts/layout_build.h"
#include "06_layouts/triangle_i.h"
#include "08_motion/bvh4mb.h"

namespace rtk {

namespace {

/// A child's boxes at the two ends of the shutter.
struct TimeBoxes {
  Box3f b0, b1;
  TimeBoxes& extend(const TimeBoxes& o) {
    b0.extend(o.b0), b1.extend(o.b1);
    return *this;
  }
};

bool finite_box(const Box3f& b) { return is_finite(b.lower) && is_finite(b.upper); }

// [ch08-swept-refs]
// Each triangle enters the SAH builder as the box it sweeps over the shutter: the union of its
// boxes at times 0 and 1. The triangle at any time t in between lies in that union, since each
// vertex moves along a segment whose ends are in the two boxes. A triangle with a non-finite
// vertex or motion gets a NaN box, which the builder leaves out.
std::vector<PrimRef> make_swept_refs(const MotionMesh& mesh) {
  constexpr float nan = std::numeric_limits<float>::quiet_NaN();
  std::vector<PrimRef> refs;
  refs.reserve(mesh.size());
  for (uint32_t prim = 0; prim < mesh.size(); ++prim) {
    const Box3f b0 = mesh.bounds(prim, 0.0f), b1 = mesh.bounds(prim, 1.0f);
    bool finite = finite_box(b0) && finite_box(b1);
    for (int k = 0; k < 3; ++k) finite = finite && is_finite(mesh.motion_of(mesh.base.triangles[prim][size_t(k)]));
    refs.emplace_back(finite ? merge(b0, b1) : Box3f(Vec3f(nan), Vec3f(nan)), prim);
  }
  return refs;
}
// [ch08-swept-refs]

// [ch08-pad]
// The rounding bound of a plane's interpolation. The kernels compute a vertex as
// p0 + t * d and a plane as l0 + t * dl, each with a few roundings of at most half an ulp of
// the largest magnitude m involved (the difference dl, the product, the sum), so a vertex can
// stray past the interpolated plane by some 12 m 2^-24. Growing both boxes by m 2^-19 (32 m
// 2^-24) absorbs it; the scene's 2^-16 added on top absorbs the slab test's own rounding, as in
// chapter 6.
float plane_pad(float lo0, float hi0, float lo1, float hi1, float scene_pad) {
  const float m = std::max(std::max(std::fabs(lo0), std::fabs(hi0)), std::max(std::fabs(lo1), std::fabs(hi1)));
  return scene_pad + m * 0x1p-19f;
}
// [ch08-pad]

}  // namespace

SahBuildOptions motion_sah_options() { return sah_options_for(TriangleLayout::triangle4i); }

template <int N>
BVHMB<N> build_bvhmb(MotionMesh mesh, IntersectorKind intersector, const SahBuildOptions* options) {
  BVHMB<N> bvh;
  bvh.mesh = std::move(mesh);
  bvh.intersector = intersector;
  bvh.leaves.layout = std::string(Triangle4iLayout::kName);
  const MotionMesh& m = bvh.mesh;
  if (m.base.vertices.size() > kMaxIndexedVertices)
    throw std::invalid_argument("a moving mesh of " + std::to_string(m.base.vertices.size()) +
                                " vertices is more than triangle4i can index");

  // Step 1: the tree, built over the swept boxes.
  const SahBuildOptions sah = options ? *options : motion_sah_options();
  const BuildTree<N> tree = build_binned_sah<N>(make_swept_refs(m), sah);
  if (tree.empty()) return bvh;
  bvh.depth = tree_depth(tree);
  if (bvh.depth > kBvhMbMaxDepth)
    throw std::invalid_argument("a tree of depth " + std::to_string(bvh.depth) +
                                " is deeper than the motion traversal's stack allows");

  // [ch08-time-boxes]
  // Step 2: every child's boxes at times 0 and 1, from its triangles' vertices at those
  // times (computed as the kernels compute them), bottom up: children follow their parents in
  // the node array, so a backward pass sees every child before its parent.
  auto leaf_boxes = [&](const typename BuildTree<N>::Child& c) {
    TimeBoxes boxes;
    for (uint32_t k = c.index; k < c.index + c.leaf_count; ++k)
      boxes.extend({m.bounds(tree.prim_ids[k], 0.0f), m.bounds(tree.prim_ids[k], 1.0f)});
    return boxes;
  };
  std::vector<TimeBoxes> node_boxes(tree.nodes.size());
  for (size_t i = tree.nodes.size(); i-- > 0;)
    for (int c = 0; c < tree.nodes[i].num_children; ++c) {
      const auto& child = tree.nodes[i].children[size_t(c)];
      node_boxes[i].extend(child.is_leaf() ? leaf_boxes(child) : node_boxes[child.index]);
    }
  const TimeBoxes scene = tree.root.is_leaf() ? leaf_boxes(tree.root) : node_boxes[tree.root.index];
  // [ch08-time-boxes]
  bvh.bounds0 = scene.b0, bvh.bounds1 = scene.b1;
  const float scene_pad = reduce_max(merge(scene.b0, scene.b1).size()) * 0x1p-16f;

  // Step 3: the nodes in depth-first order, each child's planes at time 0 and their motion.
  auto leaf_ref = [&](const typename BuildTree<N>::Child& c) {
    const std::span<const uint32_t> prims(tree.prim_ids.data() + c.index, c.leaf_count);
    return append_leaf<Triangle4iLayout>(bvh.leaves, m.base, prims);
  };
  constexpr float inf = std::numeric_limits<float>::infinity();
  const std::vector<uint32_t> order = depth_first_order(tree);
  std::vector<uint32_t> position(tree.nodes.size());
  for (size_t k = 0; k < order.size(); ++k) position[order[k]] = uint32_t(k);
  bvh.nodes.resize(tree.nodes.size());
  for (size_t k = 0; k < order.size(); ++k) {
    const auto& in = tree.nodes[order[k]];
    NodeMB<N>& out = bvh.nodes[k];
    float* lower0[3] = {out.lower_x, out.lower_y, out.lower_z};
    float* upper0[3] = {out.upper_x, out.upper_y, out.upper_z};
    float* dlower[3] = {out.dlower_x, out.dlower_y, out.dlower_z};
    float* dupper[3] = {out.dupper_x, out.dupper_y, out.dupper_z};
    for (int c = 0; c < N; ++c) {
      if (c >= in.num_children) {
        // An unused slot: planes at +inf that never move, which no clamped ray interval enters.
        for (int a = 0; a < 3; ++a) lower0[a][c] = upper0[a][c] = inf, dlower[a][c] = dupper[a][c] = 0.0f;
        out.children[c] = kEmptyLeaf;
        continue;
      }
      const auto& child = in.children[size_t(c)];
      const TimeBoxes boxes = child.is_leaf() ? leaf_boxes(child) : node_boxes[child.index];
      for (int a = 0; a < 3; ++a) {
        const float pad = plane_pad(boxes.b0.lower[a], boxes.b0.upper[a], boxes.b1.lower[a], boxes.b1.upper[a], scene_pad);
        const float l0 = boxes.b0.lower[a] - pad, l1 = boxes.b1.lower[a] - pad;
        const float u0 = boxes.b0.upper[a] + pad, u1 = boxes.b1.upper[a] + pad;
        lower0[a][c] = l0, dlower[a][c] = l1 - l0;
        upper0[a][c] = u0, dupper[a][c] = u1 - u0;
      }
      out.children[c] = child.is_leaf() ? leaf_ref(child)
                                        : make_inner_ref(size_t(position[child.index]) * sizeof(NodeMB<N>));
    }
  }
  bvh.root = tree.root.is_leaf() ? leaf_ref(tree.root) : make_inner_ref(0);
  return bvh;
}

template BVHMB<4> build_bvhmb<4>(MotionMesh, IntersectorKind, const SahBuildOptions*);
template BVHMB<8> build_bvhmb<8>(MotionMesh, IntersectorKind, const SahBuildOptions*);

}  // namespace rtk
