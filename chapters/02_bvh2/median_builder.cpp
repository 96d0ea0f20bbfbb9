#include "02_bvh2/median_builder.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace rtk {

namespace {

/// A range [begin, end) of the builder's reference array with the boxes of its references and
/// of their centroids.
struct Range {
  size_t begin = 0, end = 0;
  Box3f bounds;
  Box3f centroids;
  size_t size() const { return end - begin; }
};

Range make_range(std::span<const PrimRef> refs, size_t begin, size_t end) {
  Range r{begin, end, {}, {}};
  for (size_t i = begin; i < end; ++i) {
    r.bounds.extend(refs[i].box());
    r.centroids.extend(refs[i].center2());
  }
  return r;
}

template <int N>
class MedianBuilder {
 public:
  MedianBuilder(std::vector<PrimRef> refs, int max_leaf_size)
      : refs_(std::move(refs)), max_leaf_(size_t(max_leaf_size)) {}

  BuildTree<N> build() {
    if (refs_.empty()) return std::move(tree_);
    tree_.root = make_child(make_range(refs_, 0, refs_.size()));
    // prim_ids follow the final order of the references, which only the recursion settles.
    tree_.prim_ids.resize(refs_.size());
    for (size_t i = 0; i < refs_.size(); ++i) tree_.prim_ids[i] = refs_[i].prim;
    return std::move(tree_);
  }

 private:
  // [ch02-median-split]
  // Split at the object median: the lower half (by centroid on the longest centroid axis) goes
  // left. nth_element is enough: the halves need not be sorted inside.
  std::pair<Range, Range> split(const Range& r) {
    const int axis = max_axis(r.centroids.size());
    const size_t mid = r.begin + r.size() / 2;
    std::nth_element(refs_.begin() + long(r.begin), refs_.begin() + long(mid),
                     refs_.begin() + long(r.end), [axis](const PrimRef& a, const PrimRef& b) {
                       const float ca = a.center2()[axis], cb = b.center2()[axis];
                       return ca < cb || (ca == cb && a.prim < b.prim);  // a total order
                     });
    return {make_range(refs_, r.begin, mid), make_range(refs_, mid, r.end)};
  }
  // [ch02-median-split]

  // A leaf for a small range, otherwise a new inner node filled by splitting its largest child.
  typename BuildTree<N>::Child make_child(const Range& r) {
    typename BuildTree<N>::Child child;
    child.box = r.bounds;
    if (r.size() <= max_leaf_) {
      child.index = uint32_t(r.begin);
      child.leaf_count = uint32_t(r.size());
      return child;
    }
    // The parent's index is taken before its children are made: children point forward.
    const size_t index = tree_.nodes.size();
    tree_.nodes.emplace_back();
    child.index = uint32_t(index);

    // [ch02-median-fill]
    Range parts[N];
    int count = 1;
    parts[0] = r;
    while (count < N) {
      int largest = 0;
      for (int i = 1; i < count; ++i)
        if (parts[i].size() > parts[largest].size()) largest = i;
      if (parts[largest].size() <= max_leaf_) break;
      auto [left, right] = split(parts[largest]);
      parts[largest] = left;
      parts[count++] = right;
    }
    // [ch02-median-fill]
    for (int i = 0; i < count; ++i) {
      const auto made = make_child(parts[i]);
      tree_.nodes[index].children[i] = made;  // re-index: make_child may grow `nodes`
    }
    tree_.nodes[index].num_children = count;
    return child;
  }

  std::vector<PrimRef> refs_;
  size_t max_leaf_;
  BuildTree<N> tree_;
};

}  // namespace

template <int N>
BuildTree<N> build_median(std::span<const PrimRef> refs, int max_leaf_size) {
  static_assert(N >= 2, "a node needs at least two children");
  if (max_leaf_size < 1)
    throw std::invalid_argument("build_median: max_leaf_size must be at least 1, not " +
                                std::to_string(max_leaf_size));
  std::vector<PrimRef> kept;
  kept.reserve(refs.size());
  for (const PrimRef& ref : refs)
    if (is_buildable(ref)) kept.push_back(ref);
  return MedianBuilder<N>(std::move(kept), max_leaf_size).build();
}

template BuildTree<2> build_median<2>(std::span<const PrimRef>, int);
template BuildTree<4> build_median<4>(std::span<const PrimRef>, int);
template BuildTree<8> build_median<8>(std::span<const PrimRef>, int);
template BuildTree<16> build_median<16>(std::span<const PrimRef>, int);

}  // namespace rtk
