/// \file
/// The `-tri` configuration strings of the guide (section 4.4-4.6): which leaf layout, with
/// which intersector, and the default chosen from the scene and the ISA.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "01_base/cpu_features.h"
#include "07_intersectors/intersector_kind.h"

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

/// Whether a layout can run an intersector. The precomputed layouts (triangle1/4/8) keep v0
/// and two edges, from which the other vertices cannot be recovered bit for bit, and the
/// Plücker and watertight tests need the vertices as every neighbour sees them: so they are
/// Möller-Trumbore only, as in the guide.
bool layout_supports(TriangleLayout layout, IntersectorKind intersector);

/// Leaf bytes per triangle of a full block (padding and the tree not counted; the indexed
/// layouts' shared vertices not counted either).
size_t leaf_bytes_per_triangle(TriangleLayout layout);

/// A layout and its intersector.
struct TriangleConfig {
  TriangleLayout layout = TriangleLayout::triangle4;
  IntersectorKind intersector = IntersectorKind::moeller;

  /// The full name, e.g. "triangle4v.pluecker".
  std::string name() const;
  constexpr bool operator==(const TriangleConfig&) const = default;
};

/// Every supported combination, layouts in the guide's order, fastest intersector first.
std::vector<TriangleConfig> supported_triangle_configs();

// [ch06-parse]
/// Parses a `-tri` string: a layout name, optionally followed by `.moeller`, `.pluecker`,
/// `.watertight`, `.fast` (the fastest intersector the layout supports: Möller-Trumbore) or
/// `.accurate` (the most accurate it supports: watertight where the layout keeps vertices,
/// Möller-Trumbore for triangle1/4/8). A bare layout means `.fast`, the guide's default.
/// Throws std::invalid_argument with a message that lists the supported combinations for an
/// unknown layout or intersector or an unsupported pair (e.g. "triangle4.pluecker").
TriangleConfig parse_triangle_config(std::string_view text);
// [ch06-parse]

/// What choose_default_layout() assumes a layout costs per triangle, tree and padding
/// included: measured on closed procedural meshes with BVH4 (see chapter.md, "Bytes per
/// triangle"). The indexed layouts include half a shared vertex per triangle.
double estimated_bytes_per_triangle(TriangleLayout layout);

/// The layout a scene gets when it asks for none: the guide's recommendation for the ISA
/// (triangle4 for SSE, triangle8 for AVX; triangle8 for the scalar variant, which measured
/// fastest with it), unless its estimated size exceeds the memory budget, in which case the
/// leanest layout, triangle4i. Model no more than the scene needs.
TriangleLayout choose_default_layout(size_t triangle_count, Isa isa,
                                     size_t memory_budget_bytes = std::numeric_limits<size_t>::max());

}  // namespace rtk
