/// \file
/// How each layout's blocks become K triangles in registers: the loaders that chapter 2's
/// LeafIntersector calls (02_bvh2/leaf_intersector.h), so that every layout plugs into every
/// traversal and every ray/triangle test. Per-ISA template: include from kernel sources only.
#pragma once

#ifndef RTK_ISA
#error "layout_loads.h belongs to kernel sources compiled once per ISA"
#endif

#include <cstdint>
#include <type_traits>

#include "01_base/platform.h"
#include "01_base/ray.h"
#include "01_base/simd.h"
#include "02_bvh2/leaf_intersector.h"
#include "06_layouts/triangle_i.h"
#include "06_layouts/triangle_layout.h"
#include "06_layouts/triangle_m.h"
#include "06_layouts/triangle_v.h"

namespace rtk::RTK_ISA {

// [ch06-load-blocks]
// The precomputed blocks give Möller-Trumbore's (v0, e1, e2, Ng) with no arithmetic (chapter
// 2's Triangle1 keeps no normal and computes it); the vertex blocks load, the indexed blocks
// gather through their indices.
/// triangle4 and triangle8: four aligned rows of M floats per vector.
template <int M>
RTK_INLINE void load_moeller(const TriangleM<M>& b, Vec3v<M>& v0, Vec3v<M>& e1, Vec3v<M>& e2, Vec3v<M>& ng) {
  v0 = Vec3v<M>::load(b.v0[0], b.v0[1], b.v0[2], 0);
  e1 = Vec3v<M>::load(b.e1[0], b.e1[1], b.e1[2], 0);
  e2 = Vec3v<M>::load(b.e2[0], b.e2[1], b.e2[2], 0);
  ng = Vec3v<M>::load(b.Ng[0], b.Ng[1], b.Ng[2], 0);
}

RTK_INLINE void load_vertices(const Triangle1v& b, Vec3v<1>& p0, Vec3v<1>& p1, Vec3v<1>& p2) {
  p0 = Vec3v<1>(b.p0), p1 = Vec3v<1>(b.p1), p2 = Vec3v<1>(b.p2);
}
template <int M>
RTK_INLINE void load_vertices(const TriangleMv<M>& b, Vec3v<M>& p0, Vec3v<M>& p1, Vec3v<M>& p2) {
  p0 = Vec3v<M>::load(b.p[0][0], b.p[0][1], b.p[0][2], 0);
  p1 = Vec3v<M>::load(b.p[1][0], b.p[1][1], b.p[1][2], 0);
  p2 = Vec3v<M>::load(b.p[2][0], b.p[2][1], b.p[2][2], 0);
}
RTK_INLINE void load_vertices(const Triangle1i& b, Vec3v<1>& p0, Vec3v<1>& p1, Vec3v<1>& p2) {
  p0 = Vec3v<1>(b.vertices[b.v[0]]), p1 = Vec3v<1>(b.vertices[b.v[1]]), p2 = Vec3v<1>(b.vertices[b.v[2]]);
}
/// triangle4i: each component of each vertex is one gather at float offset 3 v + axis.
template <int M>
RTK_INLINE void load_vertices(const TriangleMi<M>& b, Vec3v<M>& p0, Vec3v<M>& p1, Vec3v<M>& p2) {
  const float* base = &b.vertices[0].x;
  Vec3v<M>* out[3] = {&p0, &p1, &p2};
  for (int k = 0; k < 3; ++k) {
    const vint<M> offset = vint<M>::load(b.v[k]) * vint<M>(3);
    *out[k] = {vfloat<M>::gather(base, offset), vfloat<M>::gather(base, offset + vint<M>(1)),
               vfloat<M>::gather(base, offset + vint<M>(2))};
  }
}
// [ch06-load-blocks]

// [ch06-moeller-leaf]
/// Calls make(std::type_identity<Leaf>{}) with the leaf policy that reads the vertex or indexed
/// `layout` with the test `Test`, and returns what it returns; {} for the precomputed layouts,
/// which only Möller-Trumbore reads. Chapter 7 gives these layouts its own tests through it.
template <class Test, class Make>
auto with_vertex_leaf(TriangleLayout layout, Make&& make)
    -> decltype(make(std::type_identity<LeafIntersector<Triangle1iLayout, Test>>{})) {
  switch (layout) {
    case TriangleLayout::triangle1i: return make(std::type_identity<LeafIntersector<Triangle1iLayout, Test>>{});
    case TriangleLayout::triangle4i: return make(std::type_identity<LeafIntersector<Triangle4iLayout, Test>>{});
    case TriangleLayout::triangle1v: return make(std::type_identity<LeafIntersector<Triangle1vLayout, Test>>{});
    case TriangleLayout::triangle4v: return make(std::type_identity<LeafIntersector<Triangle4vLayout, Test>>{});
    default: return {};
  }
}

/// Calls make(std::type_identity<Leaf>{}) with the leaf policy that reads `layout` with
/// Möller-Trumbore, and returns what it returns: the precomputed blocks give the test its edges
/// and normal, the others their vertices. The one list of layouts that every per-layout
/// instantiation (a traversal, a kernel of a later chapter) is made from.
template <class Make>
auto with_moeller_leaf(TriangleLayout layout, Make&& make)
    -> decltype(make(std::type_identity<LeafIntersector<Triangle1Layout, MoellerTrumbore, true>>{})) {
  using M = MoellerTrumbore;
  switch (layout) {
    case TriangleLayout::triangle1: return make(std::type_identity<LeafIntersector<Triangle1Layout, M, true>>{});
    case TriangleLayout::triangle4: return make(std::type_identity<LeafIntersector<Triangle4Layout, M, true>>{});
    case TriangleLayout::triangle8: return make(std::type_identity<LeafIntersector<Triangle8Layout, M, true>>{});
    default: return with_vertex_leaf<M>(layout, make);
  }
}
// [ch06-moeller-leaf]

}  // namespace rtk::RTK_ISA
