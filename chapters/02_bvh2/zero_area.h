/// \file
/// The exact zero-area test that every leaf layout applies once, when it is built.
#pragma once

#include "01_base/vec3.h"

namespace rtk {

/// Whether the triangle's vertices are collinear (or repeated) in exact arithmetic.
///
/// A zero-area triangle must never be hit, but an intersector cannot tell one reliably: once
/// the vertices are made relative to the ray origin or sheared, their rounding makes a flat
/// triangle a sliver of tiny, nonzero area. So the layouts decide once, exactly, and store such
/// a triangle as three copies of its first vertex, which every ray/triangle test (Möller-Trumbore here,
/// Plücker and watertight in chapter 7) rejects with exact zeros (its edges and normal are zero vectors). The edge vectors are differences of
/// floats, exact in double; the components of their cross product are compared as exact
/// products (the rounded product plus its error, by FMA), so nothing is rounded away.
bool is_zero_area(Vec3f p0, Vec3f p1, Vec3f p2);

}  // namespace rtk
