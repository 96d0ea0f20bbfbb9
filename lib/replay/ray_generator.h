/// \file
/// The rays that `rtk rays` writes and the benchmarks trace: four kinds, each a stand-in for a
/// workload of a Monte Carlo renderer, all deterministic for a seed on every platform.
///
/// Determinism: the only source of randomness is std::mt19937_64, whose output the C++
/// standard fixes bit for bit. Its 64-bit words are turned into floats here (the top 24 bits,
/// scaled by 2^-24, give a float in [0, 1) exactly) instead of by
/// std::uniform_real_distribution, whose algorithm each standard library chooses for itself.
/// The arithmetic after that is plain float math compiled without contraction, so the same
/// seed gives the same file with GCC and Clang, in any ISA variant.
///
/// The scene's frame: B is the box of the vertices that triangles use (unused vertices do not
/// count), c its centre, d the length of its diagonal, r = d / 2 the radius of the sphere
/// around it (1 when the scene is a single point), and eps = 1e-4 d the surface epsilon.
///
/// - primary: a pinhole camera outside the scene looking at c, y up, with a vertical field of
///   view of 45 degrees. It stands on the line from c along (0.4, 0.3, 1) (in front, slightly
///   right and above) at the distance where the sphere around the scene fills 90% of the
///   image height. The image is w = ceil(sqrt(n)) pixels wide and h = ceil(n / w) high; ray i
///   goes through pixel (i mod w, i / w), rows from the top, at a random point inside the
///   pixel (the seed moves these points). Directions are normalized; tnear = 0, tfar = +inf.
/// - diffuse: a point on a triangle chosen with probability proportional to its area
///   (zero-area triangles are never chosen), uniform on that triangle; the direction is
///   cosine-distributed about the triangle's geometric normal, on a random side (the scene
///   has no notion of outside). Normalized direction; tnear = eps, so the ray does not find
///   the surface it leaves; tfar = +inf. These rays are incoherent, like path-tracing bounces.
/// - shadow: a surface point chosen as for diffuse, toward a point light L above the scene,
///   L = (c.x, B.upper.y + r, c.z). The direction is L - p, not normalized, so that t = 1 is
///   the light; tnear and tfar stop eps (in scene units) short of the surface and of the light.
///   For occlusion queries.
/// - random: origins uniform in B grown by half its size on every side (plus 5% of d, so that
///   flat scenes get a thickness), directions uniform on the sphere (normalized), tnear = 0,
///   tfar = +inf. Many start inside the scene, many miss.
///
/// Every ray also gets a uniform random time in [0, 1), which only motion blur reads.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "01_base/box3.h"
#include "01_base/ray.h"
#include "01_base/triangle_mesh.h"

namespace rtk {

/// The kinds of ray `rtk rays -kind` makes.
enum class RayKind { primary, diffuse, shadow, random };

/// "primary", "diffuse", "shadow" or "random".
std::string_view ray_kind_name(RayKind kind);

/// Parses a ray kind's name; nothing for an unknown one.
std::optional<RayKind> parse_ray_kind(std::string_view name);

/// The box of the vertices that the triangles use (empty when there are no triangles).
Box3f used_bounds(const TriangleMesh& mesh);

/// Where the primary camera stands for a scene box (see the file comment).
Vec3f primary_camera_position(const Box3f& bounds);

/// Where the shadow rays' point light is for a scene box (see the file comment).
Vec3f shadow_light_position(const Box3f& bounds);

/// The distance that diffuse and shadow rays keep from the surface they leave: 1e-4 times the
/// box's diagonal.
float surface_epsilon(const Box3f& bounds);

/// `count` rays of a kind for a scene, the same for the same seed. Throws std::invalid_argument
/// when the scene has no triangles, or (diffuse, shadow) no triangle with an area.
std::vector<Ray> generate_rays(const TriangleMesh& mesh, RayKind kind, size_t count, uint64_t seed);

}  // namespace rtk
