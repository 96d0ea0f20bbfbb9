// leaks_by_distance: chapter 7's chart of leak rate against distance from the origin. A closed
// sphere and a tiled box of size 16, moved to 10^k on every axis (k = 0 to 7), rays from inside
// aimed exactly at every vertex and edge midpoint (rays that must all hit), traced through a
// BVH4 by Möller-Trumbore (triangle4), the stable Plücker test and the watertight test
// (triangle4v), each with chapter 2's widened box exits and without them, and by Embree 3 in
// its default and its robust mode where Embree is installed. Prints a TSV:
//   offset  series  rays  leaks  rate
// chapters/07_intersectors/chart/leaks_by_distance.sh draws it.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "01_base/cpu_features.h"
#include "01_base/isa_dispatch.h"
#include "04_sah/build_sah.h"
#include "06_layouts/layout_build.h"
#include "07_intersectors/layout_intersectors.h"
#include "07_intersectors/stability_meshes.h"
#include "testing/scenes.h"
#ifdef RTK_HAVE_EMBREE
#include "embree/embree_scene.h"
#endif

namespace {

using namespace rtk;

struct Case {
  TriangleMesh mesh;
  std::vector<Ray> rays;
};

/// The two meshes at `offset`, each with rays from inside at its vertices and edge midpoints.
std::vector<Case> cases_at(float offset) {
  constexpr float kSize = 16.0f;
  constexpr float kEdgeMidpoint[] = {0.5f};
  const Vec3f o(offset);
  const Vec3f inside = o + Vec3f{0.1f, -0.07f, 0.23f} * kSize;
  std::vector<Case> cases;
  for (const TriangleMesh& m : {make_tiled_box(8, Box3f(Vec3f(-kSize), Vec3f(kSize))),
                                test::make_sphere(16, 32, {0, 0, 0}, kSize)}) {
    Case c{translated(m, o), {}};
    c.rays = rays_at_vertices(c.mesh, inside);
    const std::vector<Ray> edges = rays_at_edges(c.mesh, inside, kEdgeMidpoint);
    c.rays.insert(c.rays.end(), edges.begin(), edges.end());
    cases.push_back(std::move(c));
  }
  return cases;
}

void print(float offset, const std::string& series, size_t rays, size_t leaks) {
  std::printf("%g\t%s\t%zu\t%zu\t%.6g\n", double(offset), series.c_str(), rays, leaks,
              double(leaks) / double(rays));
}

}  // namespace

int main() {
  const Isa isa = best_isa();
  std::printf("offset\tseries\trays\tleaks\trate\n");
  for (int k = 0; k <= 7; ++k) {
    const float offset = float(std::pow(10.0, k));
    const std::vector<Case> cases = cases_at(offset);
    size_t rays = 0;
    for (const Case& c : cases) rays += c.rays.size();
    // RTK: the three tests through BVH4, with and without the widened exits.
    for (const IntersectorKind kind : kAllIntersectors) {
      const TriangleLayout layout = kind == IntersectorKind::moeller ? TriangleLayout::triangle4 : TriangleLayout::triangle4v;
      for (const bool widened : {true, false}) {
        size_t leaks = 0;
        for (const Case& c : cases) {
          const LayoutBVH<4> bvh = build_layout_bvh<4>(c.mesh, layout, 1);
          const TraceKernels kernels = widened ? RTK_PICK_ISA(isa, intersector_kernels<4>)({layout, kind})
                                               : RTK_PICK_ISA(isa, unwidened_bvh4_kernels)(kind);
          std::vector<Hit> hits(c.rays.size());
          kernels.intersect(&bvh.bvh, c.rays, hits);
          leaks += count_misses(hits);
        }
        print(offset, std::string(intersector_name(kind)) + (widened ? "" : " unwidened"), rays, leaks);
      }
    }
#ifdef RTK_HAVE_EMBREE
    // Embree 3 on the same rays, in its default mode and in its robust mode.
    for (const bool robust : {false, true}) {
      size_t leaks = 0;
      for (const Case& c : cases) {
        const EmbreeScene embree(c.mesh, 1, "", robust);
        std::vector<Hit> hits(c.rays.size());
        embree.intersect(c.rays, hits);
        leaks += count_misses(hits);
      }
      print(offset, robust ? "embree robust" : "embree", rays, leaks);
    }
#endif
  }
  return 0;
}
