/// \file
/// The oracle every acceleration structure is tested against: each ray against every triangle,
/// in double precision.
#pragma once

#include <cstring>
#include <span>
#include <string>

#include "01_base/ray.h"
#include "01_base/triangle_mesh.h"

namespace rtk::test {

/// The closest hit of `ray` among all triangles (Möller-Trumbore in double precision, two-sided,
/// zero-area triangles never hit, only tnear <= t <= tfar). Ties in t go to the lower primID.
/// Invalid rays (rtk::is_valid) miss.
Hit brute_force_intersect(const TriangleMesh& mesh, const Ray& ray);

/// Whether any triangle blocks `ray` in [tnear, tfar].
bool brute_force_occluded(const TriangleMesh& mesh, const Ray& ray);

/// Whether two hits are the same bits: t, u, v and primID (a Hit is 16 bytes with no padding).
inline bool same_bits(const Hit& a, const Hit& b) { return std::memcmp(&a, &b, sizeof(Hit)) == 0; }

/// How far a kernel's answer may be from the oracle's and still agree with it.
struct Tolerance {
  float t_relative = 1e-4f;  ///< of the hit distance, measured in units of |dir|
  float uv = 1e-3f;          ///< absolute, on the barycentric weights
};

/// Why a kernel's hit disagrees with the oracle's, or an empty string if it agrees. A different
/// primID is accepted when both triangles are hit at the same t (coplanar or shared edges), and
/// a hit or miss within the tolerance of tnear, tfar or a triangle's edge is accepted either way.
std::string compare_hits(const TriangleMesh& mesh, const Ray& ray, const Hit& kernel,
                         const Hit& oracle, Tolerance tolerance = {});

}  // namespace rtk::test
