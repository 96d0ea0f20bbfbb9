/// \file
/// How an application with vector types of its own uses RTK: a thin wrapper that converts at
/// the boundary and leaves the kernels as they are. The Embree 1.1 guide gives the same advice
/// for extracted kernels: adapt the interface around the core, never the core to the host.
#pragma once

#include <rtk/10_kernel_api/accel.h>

#include <cstddef>
#include <span>
#include <stdexcept>
#include <vector>

/// The host application of the example: its own types, which RTK never sees.
namespace app {

/// The application's vector: four floats, the last one padding, as SIMD-minded code often
/// keeps them. It is not layout-compatible with rtk::Vec3f (12 bytes), so it is converted.
struct float4 {
  float x = 0, y = 0, z = 0, w = 0;
};

/// The application's ray: a start point, a direction and the longest distance of interest.
struct Ray {
  float4 origin;
  float4 direction;
  float max_distance = 1e30f;
};

/// The application's answer: the triangle hit (-1 for none) and where, in its own terms.
struct Hit {
  int triangle = -1;
  float distance = 0;
  float4 position;
};

// [api-wrapper]
/// The application's tracer: it owns an rtk::Accel and speaks only the application's types.
/// Conversions happen once per call on whole batches, so the kernels still see the long runs
/// of rays they are fast on.
class Tracer {
 public:
  /// Builds over the application's vertex positions and index triples (three ints a triangle).
  Tracer(std::span<const float4> positions, std::span<const int> indices)
      : accel_(to_mesh(positions, indices)) {}

  /// The closest hit of every ray, in the application's types.
  std::vector<Hit> trace(std::span<const Ray> rays) const {
    std::vector<rtk::Ray> rtk_rays(rays.size());
    for (size_t i = 0; i < rays.size(); ++i) {
      rtk_rays[i].org = to_rtk(rays[i].origin);
      rtk_rays[i].dir = to_rtk(rays[i].direction);
      rtk_rays[i].tfar = rays[i].max_distance;
    }
    std::vector<rtk::Hit> rtk_hits(rays.size());
    accel_.intersect(rtk_rays, rtk_hits);
    std::vector<Hit> hits(rays.size());
    for (size_t i = 0; i < rays.size(); ++i) {
      if (!rtk_hits[i].found()) continue;
      const rtk::Vec3f p = rtk_rays[i].org + rtk_hits[i].t * rtk_rays[i].dir;
      hits[i] = {static_cast<int>(rtk_hits[i].prim), rtk_hits[i].t, {p.x, p.y, p.z, 1.0f}};
    }
    return hits;
  }

 private:
  static rtk::Vec3f to_rtk(const float4& v) { return {v.x, v.y, v.z}; }

  // RTK checks that indices are in range; the wrapper checks what only its own types can get
  // wrong (a count that is not a multiple of three, a negative index).
  static rtk::TriangleMesh to_mesh(std::span<const float4> positions,
                                   std::span<const int> indices) {
    if (indices.size() % 3 != 0)
      throw std::invalid_argument("Tracer: indices do not come in triples");
    rtk::TriangleMesh mesh;
    for (const float4& p : positions) mesh.vertices.push_back(to_rtk(p));
    for (size_t i = 0; i < indices.size(); i += 3) {
      if (indices[i] < 0 || indices[i + 1] < 0 || indices[i + 2] < 0)
        throw std::invalid_argument("Tracer: a negative vertex index");
      mesh.triangles.push_back({static_cast<uint32_t>(indices[i]),
                                static_cast<uint32_t>(indices[i + 1]),
                                static_cast<uint32_t>(indices[i + 2])});
    }
    return mesh;
  }

  rtk::Accel accel_;
};
// [api-wrapper]

}  // namespace app
