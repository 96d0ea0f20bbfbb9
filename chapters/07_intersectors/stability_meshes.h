/// \file
/// Closed meshes and aimed rays for the stability tests: where intersectors fail is at the
/// shared edges and vertices of meshes, so the rays here are aimed at exactly those.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "01_base/ray.h"
#include "01_base/triangle_mesh.h"

namespace rtk {

/// A closed box tiled with n x n quads per face (two triangles each), every vertex shared,
/// faces wound counter-clockwise seen from outside. With a box whose corners and n are powers
/// of two the grid coordinates are exact, so rays can be aimed exactly at its edges and vertices.
TriangleMesh make_tiled_box(int n, const Box3f& box);

/// A spindle: two fans of `segments` long, thin triangles that meet at a ring of radius
/// `radius` around `center` and end at two poles `half_length` away along `axis` (normalized
/// here). A closed, convex mesh of 2 segments triangles, wound counter-clockwise from outside;
/// each pole is a vertex where `segments` slivers meet.
TriangleMesh make_spindle(int segments, float half_length, float radius, Vec3f center, Vec3f axis);

/// An open, flat fan of `segments` triangles around `center` in the plane normal to `normal`,
/// with angles that vary from wide to very thin slivers (the thinnest spans about a thousandth
/// of a turn). A ray through the center vertex must hit it.
TriangleMesh make_sliver_fan(int segments, Vec3f center, float radius, Vec3f normal);

/// The mesh moved by `offset` (each vertex rounded once).
TriangleMesh translated(const TriangleMesh& mesh, Vec3f offset);

/// The mesh's edges, each once, as pairs of vertex indices (lower index first).
std::vector<std::array<uint32_t, 2>> unique_edges(const TriangleMesh& mesh);

/// Rays from `origin` aimed at every vertex of the mesh (direction = vertex - origin in float).
std::vector<Ray> rays_at_vertices(const TriangleMesh& mesh, Vec3f origin);

/// Rays from `origin` aimed at points of every edge (a, b): for each fraction s, the point
/// (1 - s) a + s b evaluated in float, which lies exactly on the edge when it is representable
/// (s = 1/2 on a dyadic grid) and within rounding of it otherwise.
std::vector<Ray> rays_at_edges(const TriangleMesh& mesh, Vec3f origin, std::span<const float> fractions);

/// The number of rays that found no hit: on rays that must hit (from inside a closed mesh, or
/// through the interior of a fan), the number of leaks.
size_t count_misses(std::span<const Hit> hits);

/// The interval [t_in, t_out] in which a ray is inside a convex closed mesh, computed in double
/// precision from the planes of its triangles (Cyrus and Beck, "Generalized two- and
/// three-dimensional clipping", 1978): no edge or vertex decisions, hence no leaks. The planes
/// are oriented away from the mean of the vertices, which must be inside. t_in > t_out when the
/// ray's line misses the mesh.
std::array<double, 2> convex_interval(const TriangleMesh& mesh, const Ray& ray);

}  // namespace rtk
