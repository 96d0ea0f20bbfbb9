#include "testing/brute_force.h"

#include <cmath>
#include <sstream>
#include <string>

namespace rtk::test {

namespace {

struct Vec3d {
  double x, y, z;
  Vec3d(Vec3f v) : x(v.x), y(v.y), z(v.z) {}
  Vec3d(double x_, double y_, double z_) : x(x_), y(y_), z(z_) {}
};
Vec3d operator-(Vec3d a, Vec3d b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
double dot(Vec3d a, Vec3d b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Vec3d cross(Vec3d a, Vec3d b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }

struct Candidate {
  bool hit = false;
  double t = 0, u = 0, v = 0;
};

// Möller and Trumbore, "Fast, minimum storage ray/triangle intersection", JGT 1997, in doubles:
// the oracle trades speed for a margin of 29 bits over the kernels it judges.
Candidate intersect_triangle(const TriangleMesh& mesh, uint32_t prim, const Ray& ray) {
  const Vec3d p0 = mesh.vertex(prim, 0), p1 = mesh.vertex(prim, 1), p2 = mesh.vertex(prim, 2);
  const Vec3d e1 = p1 - p0, e2 = p2 - p0;
  const Vec3d dir = ray.dir;
  const Vec3d pvec = cross(dir, e2);
  const double det = dot(e1, pvec);
  if (det == 0.0 || dot(cross(e1, e2), cross(e1, e2)) == 0.0) return {};
  const Vec3d tvec = Vec3d(ray.org) - p0;
  const double u = dot(tvec, pvec) / det;
  if (u < 0.0 || u > 1.0) return {};
  const Vec3d qvec = cross(tvec, e1);
  const double v = dot(dir, qvec) / det;
  if (v < 0.0 || u + v > 1.0) return {};
  const double t = dot(e2, qvec) / det;
  if (t < double(ray.tnear) || t > double(ray.tfar)) return {};
  return {true, t, u, v};
}

}  // namespace

Hit brute_force_intersect(const TriangleMesh& mesh, const Ray& ray) {
  Hit best;
  if (!is_valid(ray)) return best;
  double best_t = INFINITY;
  for (uint32_t prim = 0; prim < mesh.size(); ++prim) {
    const Candidate c = intersect_triangle(mesh, prim, ray);
    if (c.hit && c.t < best_t) {
      best_t = c.t;
      best = {float(c.t), float(c.u), float(c.v), prim};
    }
  }
  return best;
}

bool brute_force_occluded(const TriangleMesh& mesh, const Ray& ray) {
  if (!is_valid(ray)) return false;
  for (uint32_t prim = 0; prim < mesh.size(); ++prim)
    if (intersect_triangle(mesh, prim, ray).hit) return true;
  return false;
}

std::string compare_hits(const TriangleMesh& mesh, const Ray& ray, const Hit& kernel,
                         const Hit& oracle, Tolerance tol) {
  std::ostringstream why;
  auto describe = [&](const char* who, const Hit& h) {
    why << who << " prim=" << (h.found() ? std::to_string(h.prim) : "miss") << " t=" << h.t
        << " u=" << h.u << " v=" << h.v << "; ";
  };
  // Near-misses are legitimate both ways: a hit within the tolerance of the triangle's edge or
  // of the ray's interval may be found by one side and not the other. Re-test with a loosened
  // triangle to decide whether a disagreement is such a borderline case.
  auto borderline = [&](const Hit& h) {
    if (!h.found()) return false;
    const float eps = tol.uv;
    const float t_eps = tol.t_relative * std::max(1.0f, std::fabs(h.t));
    return h.u < eps || h.v < eps || h.u + h.v > 1 - eps || std::fabs(h.t - ray.tnear) < t_eps ||
           std::fabs(h.t - ray.tfar) < t_eps;
  };
  const float t_eps = tol.t_relative * std::max(1.0f, std::fabs(oracle.t));
  if (kernel.found() != oracle.found()) {
    if (borderline(kernel) || borderline(oracle)) return {};
    why << "hit/miss differ: ";
  } else if (!kernel.found()) {
    return {};
  } else if (std::fabs(kernel.t - oracle.t) > t_eps) {
    // Two hits at different t: only acceptable if the oracle's nearer hit is borderline.
    if (borderline(oracle) && kernel.t > oracle.t) return {};
    why << "t differs: ";
  } else if (kernel.prim != oracle.prim) {
    // Same t, different triangle: a shared edge or coplanar triangles. Acceptable if the kernel's
    // triangle really is hit there.
    Ray probe = ray;
    probe.tnear = kernel.t - t_eps;
    probe.tfar = kernel.t + t_eps;
    TriangleMesh single;
    single.vertices = {mesh.vertex(kernel.prim, 0), mesh.vertex(kernel.prim, 1), mesh.vertex(kernel.prim, 2)};
    single.triangles = {{0, 1, 2}};
    if (brute_force_occluded(single, probe) || borderline(kernel)) return {};
    why << "prim differs at equal t: ";
  } else if (std::fabs(kernel.u - oracle.u) > tol.uv || std::fabs(kernel.v - oracle.v) > tol.uv) {
    why << "u/v differ: ";
  } else {
    return {};
  }
  describe("kernel", kernel);
  describe("oracle", oracle);
  why << "ray org=(" << ray.org.x << "," << ray.org.y << "," << ray.org.z << ") dir=(" << ray.dir.x
      << "," << ray.dir.y << "," << ray.dir.z << ") tnear=" << ray.tnear << " tfar=" << ray.tfar;
  return why.str();
}

}  // namespace rtk::test
