#include "04_sah/build_sah.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#include <tbb/task_group.h>

#include <array>
#include <atomic>
#include <cmath>
#include <limits>
#include <memory>
#include <new>
#include <stdexcept>
#include <string>
#include <vector>

#include "01_base/aligned.h"
#include "04_sah/binning.h"
#include "04_sah/node_filling.h"
#include "04_sah/occluder_order.h"
#include "04_sah/prim_set.h"
#include "04_sah/rotations.h"

namespace rtk {

namespace sah {
namespace {

/// A piece of the tree made by one job. A small job's fragment is its whole subtree, in local
/// indices; a medium or large job's is one node whose inner children are other jobs' fragments
/// (`sub`, indexed by the child's `index` until the fragments are put together).
template <int N>
struct Fragment {
  std::vector<typename BuildTree<N>::Node> nodes;
  std::array<std::unique_ptr<Fragment>, N> sub;
  bool upper = false;       ///< one node whose inner children are in `sub`
  size_t total = 0;         ///< nodes here and in all sub-fragments
  OccluderSummary summary;  ///< of the fragment's root, for ordering its parent's children
};

/// Counts every job adds to; the sums do not depend on the schedule.
struct Counters {
  std::atomic<size_t> inner{0}, leaves{0}, large{0}, medium{0}, small{0}, fallback{0}, rotations{0};
};

/// What one job counts as it goes, added to the shared Counters once when it is done: an atomic
/// add at every leaf and split would make the threads take the counters' cache line from each
/// other thousands of times per build.
struct JobCounts {
  size_t leaves = 0, fallback = 0;
  void add_to(Counters& c) const {
    c.leaves += leaves;
    c.fallback += fallback;
  }
};

template <int N>
class Builder {
 public:
  using Tree = BuildTree<N>;
  using Node = typename Tree::Node;
  using Child = typename Tree::Child;

  /// Past this node depth nodes are filled by median splits (chapter 4's bound).
  static constexpr int kMedianDepth = kMedianFillDepth<N>;

  Builder(PrimRef* refs, const SahBuildOptions& options, Counters& counters)
      : refs_(refs), options_(options), counters_(counters) {}

  /// Builds the subtree of a set that wants to be split, whose node lies at `depth` (the root
  /// node at 1): a small job below kSmallJobPrims, otherwise one node whose children become
  /// tasks.
  std::unique_ptr<Fragment<N>> build_job(const PrimSet& set, int depth) {
    return set.size() < kSmallJobPrims ? build_small(set, depth) : build_upper(set, depth);
  }

 private:
  /// Fills one node with the skeleton of node_filling.h; a split is split_set() below.
  int fill_node(const PrimSet& set, std::array<PrimSet, N>& kids, int depth, JobCounts& counts) {
    return sah::fill_node<N>(set, kids, depth, options_.max_leaf_size, [&](PrimSet chosen, bool median) {
      if (median) chosen.split = Split{};  // split_set() then cuts the range in the middle
      bool fallback = false;
      auto halves = split_set(chosen, refs_, options_, fallback);
      counts.fallback += fallback ? 1 : 0;
      return halves;
    });
  }

  Child leaf(const PrimSet& s, JobCounts& counts) {
    ++counts.leaves;
    Child c;
    c.box = s.bounds;
    c.index = s.begin;
    c.leaf_count = s.size();
    return c;
  }

  // [ch04-small-job]
  /// A small job: one thread builds the whole subtree, depth first (node_filling.h), then
  /// rotates and orders it.
  std::unique_ptr<Fragment<N>> build_small(const PrimSet& root, int depth) {
    auto fragment = std::make_unique<Fragment<N>>();
    auto& nodes = fragment->nodes;
    JobCounts counts;
    build_depth_first<N>(
        nodes, root, depth,
        [&](const PrimSet& set, auto& kids, int d) { return fill_node(set, kids, d, counts); },
        [&](const PrimSet& set) { return leaf(set, counts); });
    counts.add_to(counters_);
    // Tree rotations
    if (options_.rotations) {
      const size_t applied = rotate_tree<N>(nodes, kRotationRounds);
      counters_.rotations += applied;
      if (applied) nodes = preorder<N>(nodes);
    }
    // Occluder ordering
    if (options_.occluder_order != OccluderOrder::off)
      fragment->summary = order_subtree<N>(nodes, root.bounds, refs_, options_);
    fragment->total = nodes.size();
    counters_.inner += nodes.size();
    ++counters_.small;
    return fragment;
  }
  // [ch04-small-job]

  // [ch04-upper-job]
  /// A medium or large job: fill one node (with parallel passes if the set is large), then
  /// build every inner child as a task of its own and wait for them.
  std::unique_ptr<Fragment<N>> build_upper(const PrimSet& set, int depth) {
    auto fragment = std::make_unique<Fragment<N>>();
    fragment->upper = true;
    std::array<PrimSet, N> kids;
    JobCounts counts;
    const int k = fill_node(set, kids, depth, counts);
    ++(set.size() >= kLargeJobPrims ? counters_.large : counters_.medium);
    Node& node = fragment->nodes.emplace_back();
    node.num_children = k;
    tbb::task_group tasks;
    for (int i = 0; i < k; ++i) {
      if (!kids[i].wants_split) {
        node.children[i] = leaf(kids[i], counts);
        continue;
      }
      node.children[i].box = kids[i].bounds;
      node.children[i].index = uint32_t(i);  // which sub-fragment, until assembly
      tasks.run(
          [this, &fragment, &kids, i, depth] { fragment->sub[i] = build_job(kids[i], depth + 1); });
    }
    tasks.wait();
    counts.add_to(counters_);
    fragment->total = 1;
    for (const auto& sub : fragment->sub) fragment->total += sub ? sub->total : 0;
    ++counters_.inner;
    // Occluder ordering: the children's summaries are known once their tasks are done.
    if (options_.occluder_order != OccluderOrder::off) {
      std::array<OccluderSummary, N> summaries;
      for (int i = 0; i < k; ++i) {
        const Child& c = node.children[i];
        summaries[i] = c.is_leaf() ? leaf_summary(refs_ + c.index, c.leaf_count, c.box, options_)
                                   : fragment->sub[c.index]->summary;
      }
      fragment->summary = order_children<N>(node, summaries, set.bounds, options_);
    }
    return fragment;
  }
  // [ch04-upper-job]

  PrimRef* refs_;
  const SahBuildOptions& options_;
  Counters& counters_;
};

// [ch04-assemble]
/// Copies a fragment and its sub-fragments into `out` from `offset` on, in depth-first
/// preorder of the fragments, turning local indices into global ones. Where each fragment goes
/// follows from the fragments' sizes alone, so the node order is the same for any schedule.
template <int N>
void place(const Fragment<N>& fragment, uint32_t offset, typename BuildTree<N>::Node* out) {
  if (!fragment.upper) {
    for (size_t j = 0; j < fragment.nodes.size(); ++j) {
      auto node = fragment.nodes[j];
      for (int i = 0; i < node.num_children; ++i)
        if (!node.children[i].is_leaf()) node.children[i].index += offset;
      out[offset + j] = node;
    }
    return;
  }
  auto node = fragment.nodes[0];
  std::array<const Fragment<N>*, N> subs{};
  std::array<uint32_t, N> at{};
  uint32_t next = offset + 1;
  for (int i = 0; i < node.num_children; ++i) {
    auto& child = node.children[i];
    if (child.is_leaf()) continue;
    subs[i] = fragment.sub[child.index].get();
    at[i] = next;
    child.index = next;
    next += uint32_t(subs[i]->total);
  }
  out[offset] = node;
  tbb::task_group tasks;
  for (int i = 0; i < node.num_children; ++i)
    if (subs[i]) tasks.run([&subs, &at, out, i] { place<N>(*subs[i], at[i], out); });
  tasks.wait();
}
// [ch04-assemble]


/// Frees the references, a block of `bytes` from aligned_malloc().
struct ReleaseRefs {
  std::size_t bytes = 0;
  void operator()(PrimRef* p) const { aligned_free(p, bytes, 64); }
};

/// The builder's own copy of the references: valid ones only, in input order, with -0 turned
/// into +0 (x + 0 does that) so that minimum and maximum never have to choose between two
/// zeros, which would make the bounds depend on the order of a parallel reduction.
struct Prepared {
  std::unique_ptr<PrimRef[], ReleaseRefs> refs;
  uint32_t count = 0;
  Box3f bounds, centroids;
};

// [ch04-prepare]
/// Makes the builder's references in one parallel pass over blocks of the input, each block's
/// bounds found as its references are written: `make_ref(block, i)` gives reference i. Where
/// some cannot be placed (rare: a NaN or infinite vertex), a serial pass squeezes them out,
/// keeping the order.
template <class MakeRef>
Prepared prepare(size_t n, MakeRef&& make_ref) {
  const size_t blocks = (n + kPartitionBlockPrims - 1) / kPartitionBlockPrims;
  std::vector<uint32_t> valid(blocks);
  std::vector<Box3f> bounds(blocks), centroids(blocks);
  Prepared p;
  // Raw storage, not a vector: every element is written below, so zeroing it first would be
  // a wasted pass over the largest array of the build. Being large, it goes on huge pages
  // (aligned_malloc()).
  const size_t bytes = std::max<size_t>(n, 1) * sizeof(PrimRef);
  p.refs = {static_cast<PrimRef*>(aligned_malloc(bytes, 64)), ReleaseRefs{bytes}};
  PrimRef* out = p.refs.get();
  tbb::parallel_for(size_t(0), blocks, [&](size_t b) {
    const size_t first = b * kPartitionBlockPrims, last = std::min(n, first + kPartitionBlockPrims);
    uint32_t v = 0;
    for (size_t i = first; i < last; ++i) {
      PrimRef r = make_ref(b, i);
      r.lower = r.lower + Vec3f(0.0f);
      r.upper = r.upper + Vec3f(0.0f);
      out[i] = r;
      if (!is_buildable(r)) continue;
      ++v;
      bounds[b].extend(r.box());
      centroids[b].extend(centroid(r));
    }
    valid[b] = v;
  });
  size_t total = 0;
  for (size_t b = 0; b < blocks; ++b) {
    total += valid[b];
    p.bounds.extend(bounds[b]);
    p.centroids.extend(centroids[b]);
  }
  if (total < n) {
    size_t o = 0;
    for (size_t i = 0; i < n; ++i)
      if (is_buildable(out[i])) out[o++] = out[i];
  }
  p.count = uint32_t(total);
  return p;
}
// [ch04-prepare]

/// The references of a span, as given.
Prepared prepare(std::span<const PrimRef> input) {
  return prepare(input.size(), [&](size_t, size_t i) { return input[i]; });
}

/// The references of a mesh's triangles, made here rather than copied from make_prim_refs(): one
/// parallel pass instead of a serial one and a copy. A triangle with a vertex index out of range
/// is refused as make_prim_refs() refuses it, naming the first such triangle whatever the
/// schedule (each block notes its first, and the first block with one decides).
Prepared prepare(const TriangleMesh& mesh) {
  const size_t n = mesh.size();
  const size_t blocks = (n + kPartitionBlockPrims - 1) / kPartitionBlockPrims;
  std::vector<size_t> first_bad(blocks, n);
  Prepared p = prepare(n, [&](size_t b, size_t i) {
    if (vertex_indices_valid(mesh, i)) return make_prim_ref(mesh, uint32_t(i));
    first_bad[b] = std::min(first_bad[b], i);
    return PrimRef(Box3f(Vec3f(std::numeric_limits<float>::quiet_NaN())), uint32_t(i));
  });
  for (size_t bad : first_bad)
    if (bad < n) check_vertex_indices(mesh, bad, bad + 1);
  return p;
}

// [ch04-size-fresh]
/// Sizes one of the tree's arrays, mapping its pages on the arena's threads first. resize()
/// writes every element on one thread, and in fresh memory a write must wait for the kernel to
/// map and zero the page, which on a large scene made these two resizes a serial stretch that
/// a second thread could not shorten. Mapped in pieces on every thread, the resize that follows
/// writes into memory that is already there. One thread alone gains nothing by asking first.
template <class Vector>
void resize_fresh(Vector& v, size_t n) {
  const size_t bytes = n * sizeof(typename Vector::value_type);
  if (bytes >= kHugePageBytes && v.capacity() < n && tbb::this_task_arena::max_concurrency() > 1) {
    v.reserve(n);  // the block, untouched
    char* const base = reinterpret_cast<char*>(v.data());
    tbb::parallel_for(tbb::blocked_range<size_t>(0, bytes, kHugePageBytes),
                      [&](const tbb::blocked_range<size_t>& r) { map_pages_now(base + r.begin(), r.size()); });
  }
  v.resize(n);
}
// [ch04-size-fresh]

template <int N>
BuildTree<N> build(const Prepared& p, size_t input_size, const SahBuildOptions& options,
                   SahBuildStats* stats) {
  BuildTree<N> tree;
  Counters counters;
  if (p.count > 0) {
    const PrimSet root = make_root_set(p.refs.get(), p.count, p.bounds, p.centroids, options);
    if (!root.wants_split) {
      tree.root.box = root.bounds;
      tree.root.index = 0;
      tree.root.leaf_count = root.size();
      counters.leaves = 1;
    } else {
      Builder<N> builder(p.refs.get(), options, counters);
      const auto fragment = builder.build_job(root, 1);
      resize_fresh(tree.nodes, fragment->total);
      place<N>(*fragment, 0, tree.nodes.data());
      tree.root.box = root.bounds;
      tree.root.index = 0;
      tree.root.leaf_count = 0;
    }
    resize_fresh(tree.prim_ids, p.count);
    const PrimRef* refs = p.refs.get();
    tbb::parallel_for(tbb::blocked_range<size_t>(0, p.count, kPartitionBlockPrims),
                      [&](const tbb::blocked_range<size_t>& r) {
                        for (size_t i = r.begin(); i != r.end(); ++i)
                          tree.prim_ids[i] = refs[i].prim;
                      });
  }
  if (stats) {
    *stats = SahBuildStats{};
    stats->primitives = p.count;
    stats->skipped = input_size - p.count;
    stats->inner_nodes = counters.inner;
    stats->leaves = counters.leaves;
    stats->large_jobs = counters.large;
    stats->medium_jobs = counters.medium;
    stats->small_jobs = counters.small;
    stats->fallback_splits = counters.fallback;
    stats->rotations = counters.rotations;
  }
  return tree;
}

}  // namespace
}  // namespace sah

namespace {

/// What both entry points do: refuse invalid options and more than 2^32 - 2 inputs (`what`),
/// then prepare the references and build, in an arena of options.threads threads (0: the
/// caller's).
template <int N, class Prepare>
BuildTree<N> checked_build(size_t count, const char* what, const SahBuildOptions& options,
                           SahBuildStats* stats, Prepare&& prepare) {
  static_assert(N == 2 || N == 4 || N == 8 || N == 16, "nodes of 2, 4, 8 or 16 children");
  check_sah_options(options, "build_binned_sah");
  if (count > size_t(std::numeric_limits<uint32_t>::max()) - 1)
    throw std::length_error(std::string("build_binned_sah: more than 2^32 - 2 ") + what);
  const SahBuildOptions resolved = with_binning_isa(options);
  auto build = [&] { return sah::build<N>(prepare(), count, resolved, stats); };
  if (options.threads == 0) return build();
  tbb::task_arena arena(options.threads);
  return arena.execute(build);
}

}  // namespace

template <int N>
BuildTree<N> build_binned_sah(std::span<const PrimRef> refs, const SahBuildOptions& options,
                              SahBuildStats* stats) {
  return checked_build<N>(refs.size(), "primitive references", options, stats,
                          [&] { return sah::prepare(refs); });
}

template <int N>
BuildTree<N> build_binned_sah(const TriangleMesh& mesh, const SahBuildOptions& options,
                              SahBuildStats* stats) {
  return checked_build<N>(mesh.size(), "triangles", options, stats, [&] { return sah::prepare(mesh); });
}

template BuildTree<2> build_binned_sah<2>(std::span<const PrimRef>, const SahBuildOptions&,
                                          SahBuildStats*);
template BuildTree<2> build_binned_sah<2>(const TriangleMesh&, const SahBuildOptions&, SahBuildStats*);
template BuildTree<4> build_binned_sah<4>(const TriangleMesh&, const SahBuildOptions&, SahBuildStats*);
template BuildTree<8> build_binned_sah<8>(const TriangleMesh&, const SahBuildOptions&, SahBuildStats*);
template BuildTree<16> build_binned_sah<16>(const TriangleMesh&, const SahBuildOptions&, SahBuildStats*);
template BuildTree<4> build_binned_sah<4>(std::span<const PrimRef>, const SahBuildOptions&,
                                          SahBuildStats*);
template BuildTree<8> build_binned_sah<8>(std::span<const PrimRef>, const SahBuildOptions&,
                                          SahBuildStats*);
template BuildTree<16> build_binned_sah<16>(std::span<const PrimRef>, const SahBuildOptions&,
                                            SahBuildStats*);

void check_sah_options(const SahBuildOptions& o, const std::string& who) {
  auto fail = [&](const std::string& what) { throw std::invalid_argument(who + ": " + what); };
  if (o.bins < 2 || o.bins > kMaxSahBins)
    fail("bins must be in [2, " + std::to_string(kMaxSahBins) + "], got " + std::to_string(o.bins));
  if (o.max_leaf_size < 1)
    fail("max_leaf_size must be at least 1, got " + std::to_string(o.max_leaf_size));
  if (o.leaf_block < 1 || o.leaf_block > 16 || (o.leaf_block & (o.leaf_block - 1)) != 0)
    fail("leaf_block must be 1, 2, 4, 8 or 16, got " + std::to_string(o.leaf_block));
  if (!std::isfinite(o.traversal_cost) || o.traversal_cost < 0.0f)
    fail("traversal_cost must be finite and not negative");
  if (!std::isfinite(o.intersection_cost) || o.intersection_cost <= 0.0f)
    fail("intersection_cost must be finite and positive");
  if (o.threads < 0)
    fail("threads must be 0 (the caller's arena) or positive, got " + std::to_string(o.threads));
  if (o.isa && !isa_supported(*o.isa))
    fail("isa " + std::string(isa_name(*o.isa)) + " is not supported by this CPU");
}

}  // namespace rtk
