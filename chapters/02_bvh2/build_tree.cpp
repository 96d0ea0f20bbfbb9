#include "02_bvh2/build_tree.h"

namespace rtk {

std::vector<PrimRef> make_prim_refs(const TriangleMesh& mesh) {
  std::vector<PrimRef> refs(mesh.size());
  for (uint32_t i = 0; i < mesh.size(); ++i) refs[i] = PrimRef(mesh.bounds(i), i);
  return refs;
}

template <int N>
double sah_cost(const BuildTree<N>& tree, double traversal_cost, double intersection_cost) {
  const double root_area = tree.root.box.half_area();
  if (tree.empty() || root_area <= 0.0) return 0.0;
  if (tree.root.is_leaf()) return intersection_cost * tree.root.leaf_count;
  // The root node is traversed by every ray; every other box is entered with probability
  // area(box) / area(root).
  double cost = traversal_cost;
  for (const auto& node : tree.nodes) {
    for (int i = 0; i < node.num_children; ++i) {
      const auto& child = node.children[i];
      const double p = child.box.half_area() / root_area;
      cost += child.is_leaf() ? p * intersection_cost * child.leaf_count : p * traversal_cost;
    }
  }
  return cost;
}

template double sah_cost<2>(const BuildTree<2>&, double, double);
template double sah_cost<4>(const BuildTree<4>&, double, double);
template double sah_cost<8>(const BuildTree<8>&, double, double);

}  // namespace rtk
