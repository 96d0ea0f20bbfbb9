#include "06_layouts/triangle_layout.h"

#include "06_layouts/triangle_i.h"
#include "06_layouts/triangle_m.h"
#include "06_layouts/triangle_v.h"
#include "02_bvh2/triangle1.h"

namespace rtk {

std::string_view layout_name(TriangleLayout layout) {
  switch (layout) {
    case TriangleLayout::triangle1: return "triangle1";
    case TriangleLayout::triangle4: return "triangle4";
    case TriangleLayout::triangle8: return "triangle8";
    case TriangleLayout::triangle1i: return "triangle1i";
    case TriangleLayout::triangle4i: return "triangle4i";
    case TriangleLayout::triangle1v: return "triangle1v";
    case TriangleLayout::triangle4v: return "triangle4v";
  }
  return "?";
}

std::optional<TriangleLayout> parse_layout(std::string_view name) {
  for (const TriangleLayout layout : kAllLayouts)
    if (layout_name(layout) == name) return layout;
  return std::nullopt;
}

bool is_precomputed(TriangleLayout layout) {
  return layout == TriangleLayout::triangle1 || layout == TriangleLayout::triangle4 ||
         layout == TriangleLayout::triangle8;
}

size_t leaf_bytes_per_triangle(TriangleLayout layout) {
  switch (layout) {
    case TriangleLayout::triangle1: return sizeof(Triangle1);
    case TriangleLayout::triangle4: return sizeof(TriangleM<4>) / 4;
    case TriangleLayout::triangle8: return sizeof(TriangleM<8>) / 8;
    case TriangleLayout::triangle1i: return sizeof(Triangle1i);
    case TriangleLayout::triangle4i: return sizeof(TriangleMi<4>) / 4;
    case TriangleLayout::triangle1v: return sizeof(Triangle1v);
    case TriangleLayout::triangle4v: return sizeof(TriangleMv<4>) / 4;
  }
  return 0;
}

// [ch06-estimate]
double estimated_bytes_per_triangle(TriangleLayout layout, int width) {
  // Measured with sah_options_for(layout) on the closed procedural meshes (spheres of 16,128
  // and 130,560 triangles, a terrain of 131,072; the largest value, rounded up): leaf blocks
  // with their padding, the nodes, and for the indexed layouts the shared vertices (12 bytes
  // each, about half a vertex per triangle). With one triangle per leaf test, eight children
  // cost more nodes' padding above small leaves than four; the blocks, priced as blocks, fill
  // BVH8 nodes as well as BVH4 nodes. A triangle soup costs more: the indexed layouts, with
  // three vertices of its own per triangle, some 35 bytes, and triangle8 in a BVH8, whose
  // scattered triangles gain from smaller leaves, some 35. Two children leave no slot empty:
  // BVH2 measured at or below BVH4 with every layout, so it shares BVH4's figures.
  const bool wide = width > 4;
  switch (layout) {
    case TriangleLayout::triangle1: return wide ? 107 : 85;
    case TriangleLayout::triangle4: return wide ? 70 : 70;
    case TriangleLayout::triangle8: return wide ? 70 : 66;
    case TriangleLayout::triangle1i: return wide ? 97 : 75;
    case TriangleLayout::triangle4i: return wide ? 42 : 42;
    case TriangleLayout::triangle1v: return wide ? 107 : 85;
    case TriangleLayout::triangle4v: return wide ? 57 : 57;
  }
  return 0;
}

TriangleLayout choose_default_layout(size_t triangle_count, Isa isa, int width, size_t memory_budget_bytes) {
  // The guide's recommendation: blocks of four for SSE, of eight for AVX. The scalar variant
  // measured fastest with blocks of eight too: its eight-lane loops are vectorized by the
  // compiler with the SSE2 that every x86-64 has.
  const TriangleLayout fastest = isa == Isa::sse4 ? TriangleLayout::triangle4 : TriangleLayout::triangle8;
  // Model no more than the scene needs: a scene that would not fit gets the leanest layout.
  const double needed = estimated_bytes_per_triangle(fastest, width) * double(triangle_count);
  return needed <= double(memory_budget_bytes) ? fastest : TriangleLayout::triangle4i;
}
// [ch06-estimate]

}  // namespace rtk
