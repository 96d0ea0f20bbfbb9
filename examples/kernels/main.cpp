/// \file
/// An application that uses RTK's installed kernels: it builds an acceleration structure over
/// triangles of its own, traces a few rays and prints what they hit. The scene and the rays
/// are chosen so that every answer can be worked out by hand (tests/install checks them).
/// Usage: rtk_kernels_example [ISA]   (scalar, sse4, avx2 or avx512; the best one by default)

#include <rtk/10_kernel_api/accel.h>
#include <rtk/10_kernel_api/motion_accel.h>

#include <cstdint>
#include <cstdio>
#include <exception>
#include <stdexcept>
#include <string>
#include <vector>

#include "app_tracer.h"

namespace {

void print_hits(const char* what, const std::vector<rtk::Hit>& hits) {
  for (size_t i = 0; i < hits.size(); ++i) {
    if (hits[i].found())
      std::printf("%s %zu: triangle %u at t=%.3f u=%.3f v=%.3f\n", what, i, hits[i].prim, hits[i].t,
                  hits[i].u, hits[i].v);
    else
      std::printf("%s %zu: miss\n", what, i);
  }
}

int run(int argc, char** argv) {
  // [api-build]
  // A 4x4 floor at z = 0 and a 1x1 tile at z = 1 above it, two triangles each. Triangle i is
  // triangles[i]; a hit's u and v weigh its second and third vertex.
  rtk::TriangleMesh mesh;
  mesh.vertices = {{0, 0, 0}, {4, 0, 0}, {4, 4, 0}, {0, 4, 0},   // floor
                   {1, 1, 1}, {2, 1, 1}, {2, 2, 1}, {1, 2, 1}};  // tile
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}, {4, 5, 6}, {4, 6, 7}};

  rtk::AccelConfig config;  // empty strings: the defaults for the ISA
  if (argc > 1) config.isa = rtk::choose_isa(argv[1]);
  const rtk::Accel accel(mesh, config);  // the mesh may go away now
  // [api-build]
  std::printf("built %s with %s leaves for %s\n", accel.info().accel.c_str(),
              accel.info().tri.c_str(), std::string(rtk::isa_name(accel.info().isa)).c_str());

  // [api-intersect]
  // Rays straight down from z = 3; the last one has no direction, which makes it a miss.
  const rtk::Vec3f down(0, 0, -1);
  std::vector<rtk::Ray> rays(5);
  rays[0].org = {3, 1, 3};         // the floor, triangle 0, at t = 3
  rays[1].org = {1.5f, 1.25f, 3};  // the tile, triangle 2, at t = 2
  rays[2].org = {1, 3, 3};         // the floor, triangle 1
  rays[3].org = {5, 5, 3};         // beside everything
  for (int i = 0; i < 4; ++i) rays[i].dir = down;
  rays[4].org = {1.5f, 1.5f, 3};  // dir stays (0, 0, 0): not a ray
  std::vector<rtk::Hit> hits(rays.size());
  accel.intersect(rays, hits);
  // [api-intersect]
  print_hits("ray", hits);

  // [api-occluded]
  // Shadow rays up from just above the floor to z = 3: one under the tile, one in the open.
  std::vector<rtk::Ray> shadow(2);
  shadow[0].org = {1.5f, 1.75f, 0.5f};
  shadow[1].org = {3, 1, 0.5f};
  for (rtk::Ray& r : shadow) {
    r.dir = {0, 0, 1};
    r.tfar = 2.5f;
  }
  std::vector<uint8_t> blocked(shadow.size());
  accel.occluded(shadow, blocked);
  // [api-occluded]
  for (size_t i = 0; i < blocked.size(); ++i)
    std::printf("shadow %zu: %s\n", i, blocked[i] ? "blocked" : "free");

  // [api-motion]
  // Motion blur: the same triangles at time 1, the tile slid by 2 along x. Each ray says when
  // it looks, with `time` in [0, 1].
  rtk::TriangleMesh moved = mesh;
  for (uint32_t i = 4; i < 8; ++i) moved.vertices[i].x += 2;
  const rtk::Accel motion(mesh, moved);
  std::vector<rtk::Ray> timed(3);
  timed[0].org = {1.75f, 1.5f, 3};  // at time 0 the tile is there: triangle 2 at t = 2
  timed[1].org = {1.75f, 1.5f, 3};  // at time 1 it has gone: the floor, triangle 0, at t = 3
  timed[1].time = 1;
  timed[2].org = {3.75f, 1.5f, 3};  // at time 1 the tile has arrived here: triangle 2
  timed[2].time = 1;
  for (rtk::Ray& r : timed) r.dir = down;
  std::vector<rtk::Hit> timed_hits(timed.size());
  motion.intersect(timed, timed_hits);
  // [api-motion]
  const bool moving = motion.info().accel.starts_with(rtk::kMotionAccel);
  std::printf("motion structure: %s\n", moving ? "yes" : "no");
  for (size_t i = 0; i < timed_hits.size(); ++i)
    std::printf("motion %zu: triangle %u at t=%.3f\n", i, timed_hits[i].prim, timed_hits[i].t);

  // [api-refused]
  // A configuration RTK does not have is refused with the list of those it has.
  try {
    rtk::AccelConfig bad;
    bad.accel = "octree";
    const rtk::Accel refused(mesh, bad);
  } catch (const std::invalid_argument& e) {
    std::printf("refused: %s\n", e.what());
  }
  // [api-refused]

  // [api-wrapped]
  // The same scene through the application's own types (app_tracer.h).
  const app::float4 positions[] = {{0, 0, 0, 1}, {4, 0, 0, 1}, {4, 4, 0, 1}, {0, 4, 0, 1},
                                   {1, 1, 1, 1}, {2, 1, 1, 1}, {2, 2, 1, 1}, {1, 2, 1, 1}};
  const int indices[] = {0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7};
  const app::Tracer tracer(positions, indices);
  const app::Ray app_rays[] = {{{1.5f, 1.75f, 3, 1}, {0, 0, -1, 0}, 10.0f},
                               {{0.5f, 0.5f, 3, 1}, {0, 0, -1, 0}, 2.0f}};
  const std::vector<app::Hit> app_hits = tracer.trace(app_rays);
  // [api-wrapped]
  for (size_t i = 0; i < app_hits.size(); ++i) {
    const app::Hit& h = app_hits[i];
    if (h.triangle >= 0)
      std::printf("wrapped %zu: triangle %d at (%.3f, %.3f, %.3f)\n", i, h.triangle, h.position.x,
                  h.position.y, h.position.z);
    else
      std::printf("wrapped %zu: nothing within %.3f\n", i, app_rays[i].max_distance);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "rtk_kernels_example: %s\n", e.what());
    return 2;
  }
}
