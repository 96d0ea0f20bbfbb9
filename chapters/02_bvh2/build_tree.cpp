#include "02_bvh2/build_tree.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace rtk {

void check_vertex_indices(const TriangleMesh& mesh, size_t first, size_t last) {
  // An index past the vertex array would make us read memory that is not ours: refuse the mesh
  // and say which triangle is wrong.
  const size_t vertex_count = mesh.vertices.size();
  for (size_t i = first; i < std::min(last, mesh.size()); ++i)
    for (uint32_t index : mesh.triangles[i])
      if (index >= vertex_count)
        throw std::invalid_argument("triangle " + std::to_string(i) + " names vertex " +
                                    std::to_string(index) + " of a mesh with " +
                                    std::to_string(vertex_count) + " vertices");
}

std::vector<PrimRef> make_prim_refs(const TriangleMesh& mesh) {
  check_vertex_indices(mesh);
  std::vector<PrimRef> refs(mesh.size());
  for (uint32_t i = 0; i < mesh.size(); ++i) refs[i] = make_prim_ref(mesh, i);
  return refs;
}

template <int N>
double sah_cost(const BuildTree<N>& tree, double traversal_cost, double intersection_cost,
                int leaf_block) {
  auto tests = [leaf_block](uint32_t count) { return double(leaf_tests(count, leaf_block)); };
  const double root_area = tree.root.box.half_area();
  if (tree.empty() || root_area <= 0.0) return 0.0;
  if (tree.root.is_leaf()) return intersection_cost * tests(tree.root.leaf_count);
  // The root node is traversed by every ray; every other box is entered with probability
  // area(box) / area(root).
  double cost = traversal_cost;
  for (const auto& node : tree.nodes) {
    for (int i = 0; i < node.num_children; ++i) {
      const auto& child = node.children[i];
      const double p = child.box.half_area() / root_area;
      cost +=
          child.is_leaf() ? p * intersection_cost * tests(child.leaf_count) : p * traversal_cost;
    }
  }
  return cost;
}

template double sah_cost<2>(const BuildTree<2>&, double, double, int);
template double sah_cost<4>(const BuildTree<4>&, double, double, int);
template double sah_cost<8>(const BuildTree<8>&, double, double, int);
template double sah_cost<16>(const BuildTree<16>&, double, double, int);

}  // namespace rtk
