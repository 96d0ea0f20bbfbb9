/// \file
/// The `-tri` configuration strings of the guide (sections 4.4 to 4.6): a leaf layout of
/// chapter 6 with one of this chapter's intersectors, `.fast` and `.accurate`, and which pairs
/// exist.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "06_layouts/triangle_layout.h"
#include "07_intersectors/intersector_kind.h"

namespace rtk {

/// Whether a layout can run an intersector. The precomputed layouts (triangle1/4/8) keep v0
/// and two edges, from which the other vertices cannot be recovered bit for bit, and the
/// Plücker and watertight tests need the vertices as every neighbour sees them: so they are
/// Möller-Trumbore only, as in the guide.
bool layout_supports(TriangleLayout layout, IntersectorKind intersector);

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

// [ch07-parse]
/// Parses a `-tri` string: a layout name, optionally followed by `.moeller`, `.pluecker`,
/// `.watertight`, `.fast` (the fastest intersector the layout supports: Möller-Trumbore) or
/// `.accurate` (the most accurate it supports: watertight where the layout keeps vertices,
/// Möller-Trumbore for triangle1/4/8). A bare layout means `.fast`, the guide's default.
/// Throws std::invalid_argument with a message that lists the supported combinations for an
/// unknown layout or intersector or an unsupported pair (e.g. "triangle4.pluecker").
TriangleConfig parse_triangle_config(std::string_view text);
// [ch07-parse]

}  // namespace rtk
