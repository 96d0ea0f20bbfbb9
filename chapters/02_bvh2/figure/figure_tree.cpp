// The picture of chapter 2: a median-built BVH2 over a small flat scene, level by level.
// Writes, into the folder given, triangles.tsv (one triangle per block: three corners and the
// first again) and boxes.tsv (x0 y0 x1 y1 depth leaf, one line per node's child box), which
// figure/levels.gp draws. Run by `bash scripts/measure.sh ch02`:
//   build/chapters/02_bvh2/ch02_figure OUTPUT_FOLDER
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "02_bvh2/build_tree.h"
#include "02_bvh2/median_builder.h"

using namespace rtk;

namespace {

/// 96 small triangles in the plane z = 0: a spiral of growing ones and a dense cluster, so that
/// the median split has both sparse and crowded regions to cut.
TriangleMesh flat_scene() {
  TriangleMesh mesh;
  auto add = [&](float x, float y, float r, float a) {
    const auto n = static_cast<uint32_t>(mesh.vertices.size());
    for (int k = 0; k < 3; ++k) {
      const float t = a + 2.0943951f * static_cast<float>(k);
      mesh.vertices.push_back({x + r * std::cos(t), y + r * std::sin(t), 0.0f});
    }
    mesh.triangles.push_back({n, n + 1, n + 2});
  };
  for (int i = 0; i < 64; ++i) {  // the spiral
    const float s = static_cast<float>(i) / 64.0f, angle = 9.0f * s;
    add(50.0f + 42.0f * s * std::cos(angle), 50.0f + 42.0f * s * std::sin(angle), 1.0f + 2.5f * s,
        1.3f * static_cast<float>(i));
  }
  for (int i = 0; i < 32; ++i) {  // the cluster
    add(78.0f + 3.0f * static_cast<float>(i % 6), 20.0f + 3.0f * static_cast<float>(i / 6), 1.2f,
        0.7f * static_cast<float>(i));
  }
  return mesh;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s OUTPUT_FOLDER\n", argv[0]);
    return 2;
  }
  const std::filesystem::path dir = argv[1];
  std::filesystem::create_directories(dir);
  const TriangleMesh mesh = flat_scene();
  const BuildTree<2> tree = build_median<2>(make_prim_refs(mesh), 2);

  FILE* tris = std::fopen((dir / "triangles.tsv").c_str(), "w");
  FILE* boxes = std::fopen((dir / "boxes.tsv").c_str(), "w");
  if (!tris || !boxes) {
    std::fprintf(stderr, "%s: cannot write into %s\n", argv[0], dir.c_str());
    return 1;
  }
  for (uint32_t t = 0; t < mesh.size(); ++t) {
    for (int k = 0; k <= 3; ++k) {
      const Vec3f v = mesh.vertex(t, k % 3);
      std::fprintf(tris, "%g\t%g\n", v.x, v.y);
    }
    std::fprintf(tris, "\n");
  }
  // Children come after their parents, so one forward pass gives every node its depth.
  std::vector<int> depth(tree.nodes.size(), 0);
  auto child = [&](const BuildTree<2>::Child& c, int d) {
    std::fprintf(boxes, "%g\t%g\t%g\t%g\t%d\t%d\n", c.box.lower.x, c.box.lower.y, c.box.upper.x,
                 c.box.upper.y, d, c.is_leaf() ? 1 : 0);
    if (!c.is_leaf()) depth[c.index] = d + 1;
  };
  child(tree.root, 0);
  for (size_t i = 0; i < tree.nodes.size(); ++i) {
    for (int c = 0; c < tree.nodes[i].num_children; ++c) child(tree.nodes[i].children[c], depth[i]);
  }
  std::fclose(tris);
  std::fclose(boxes);
  std::printf("%zu triangles, %zu inner nodes, depth %d\n", mesh.size(), tree.nodes.size(),
              tree_depth(tree));
  return 0;
}
