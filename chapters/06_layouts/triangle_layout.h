/// \file
/// The leaf layouts of the guide (section 4.4) by name, what each costs per triangle, and the
/// layout a scene gets when it asks for none. (The `-tri` string adds the intersector to the
/// layout: chapter 7's triangle_config.h.)
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <string_view>

#include "01_base/cpu_features.h"

namespace rtk {

/// The leaf layouts of the guide.
enum class TriangleLayout {
  triangle1,   ///< one precomputed triangle (v0, e1, e2): Möller-Trumbore only
  triangle4,   ///< four precomputed triangles (v0, e1, e2, Ng) in SoA: Möller-Trumbore only
  triangle8,   ///< eight precomputed triangles in SoA: Möller-Trumbore only
  triangle1i,  ///< one triangle as indices into the shared vertex array
  triangle4i,  ///< four triangles as indices: the least memory
  triangle1v,  ///< one triangle as three vertices
  triangle4v,  ///< four triangles as vertices in SoA
};

/// All layouts, in the guide's order.
inline constexpr TriangleLayout kAllLayouts[] = {
    TriangleLayout::triangle1,  TriangleLayout::triangle4,  TriangleLayout::triangle8,
    TriangleLayout::triangle1i, TriangleLayout::triangle4i, TriangleLayout::triangle1v,
    TriangleLayout::triangle4v};

/// The layout's name in `-tri` strings: "triangle1", "triangle4", ...
std::string_view layout_name(TriangleLayout layout);

/// Parses a layout name ("triangle4v"); std::nullopt for anything else.
std::optional<TriangleLayout> parse_layout(std::string_view name);

/// Whether the layout stores Möller-Trumbore's precomputed triangle (v0, e1, e2, and for
/// blocks Ng) rather than vertices: triangle1, triangle4 and triangle8. From those the other
/// vertices cannot be recovered bit for bit, so they serve Möller-Trumbore only.
bool is_precomputed(TriangleLayout layout);

/// Leaf bytes per triangle of a full block (padding and the tree not counted; the indexed
/// layouts' shared vertices not counted either).
size_t leaf_bytes_per_triangle(TriangleLayout layout);

/// What choose_default_layout() assumes a layout costs per triangle in a BVH of `width` (2, 4 or
/// 8) children, tree and padding included: measured on closed procedural meshes (see chapter.md,
/// "Bytes per triangle"). The indexed layouts include half a shared vertex per triangle.
double estimated_bytes_per_triangle(TriangleLayout layout, int width);

/// The layout a scene gets when it asks for none, in a BVH of `width` children: the guide's
/// recommendation for the ISA (triangle4 for SSE, triangle8 for AVX; triangle8 for the scalar
/// variant, which measured fastest with it), unless its estimated size exceeds the memory
/// budget, in which case the leanest layout, triangle4i. Model no more than the scene needs.
TriangleLayout choose_default_layout(size_t triangle_count, Isa isa, int width,
                                     size_t memory_budget_bytes = std::numeric_limits<size_t>::max());

}  // namespace rtk
