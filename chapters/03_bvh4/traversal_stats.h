/// \file
/// What a traversal did, counted: the statistics mode of the BVH4/BVH8 kernels.
#pragma once

#include <array>
#include <cstdint>

namespace rtk {

// [ch03-stats]
/// Counters of a statistics-mode traversal, summed over rays. The counting code is compiled
/// only into the statistics variants of the kernels; the fast path has none of it.
struct TraversalStats {
  uint64_t rays = 0;        ///< valid rays traced (invalid rays are not traversed)
  uint64_t nodes = 0;       ///< inner nodes whose children's boxes were tested
  uint64_t leaves = 0;      ///< leaves whose primitives were tested
  uint64_t primitives = 0;  ///< primitive blocks tested
  uint64_t culled = 0;      ///< stack entries skipped at pop because of a closer hit
  /// children_hit[k]: how many node visits found exactly k children hit (k = 0..16).
  std::array<uint64_t, 17> children_hit{};

  double nodes_per_ray() const { return rays ? double(nodes) / double(rays) : 0.0; }
  double leaves_per_ray() const { return rays ? double(leaves) / double(rays) : 0.0; }
  /// The share of node visits with k children hit.
  double hit_fraction(int k) const { return nodes ? double(children_hit[size_t(k)]) / double(nodes) : 0.0; }

  TraversalStats& operator+=(const TraversalStats& o) {
    rays += o.rays, nodes += o.nodes, leaves += o.leaves, primitives += o.primitives, culled += o.culled;
    for (size_t k = 0; k < children_hit.size(); ++k) children_hit[k] += o.children_hit[k];
    return *this;
  }
  bool operator==(const TraversalStats&) const = default;
};
// [ch03-stats]

}  // namespace rtk
