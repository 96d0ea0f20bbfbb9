#include "05_spatial/build_spatial.h"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>

#include "04_sah/binning.h"
#include "04_sah/node_filling.h"
#include "04_sah/occluder_order.h"
#include "04_sah/partition.h"
#include "04_sah/rotations.h"
#include "05_spatial/spatial_split.h"

namespace rtk {

namespace spatial {
namespace {

using sah::half_area;

/// A set of references as the builder carries it: unlike chapter 4's ranges of one array, a
/// spatial split makes sets that hold more references than their parent, so each set owns its
/// references. It arrives evaluated: its best object split and (where tried) its best spatial
/// split are known, and choose() picks between them under the set's share of the budget.
struct Set {
  std::vector<PrimRef> refs;
  Box3f bounds, centroids;
  size_t budget = 0;  ///< duplicates this set's subtree may add
  sah::BinMapping map;
  sah::Split object;
  std::vector<SpatialSplit> planes;  ///< the spatial split planes priced (none if not tried)
  SpatialSplit spatial;              ///< the cheapest of them the budget affords
  /// Whether spatial splits were priced: not for a set evaluated with no budget (most of them,
  /// deep down, where the shares have run out), unless a later share gives it some.
  bool spatial_tried = false;
  bool use_spatial = false;
  bool wants_split = false;
  double gain = 0.0;

  uint32_t size() const { return uint32_t(refs.size()); }
  bool splittable() const { return object.valid() || use_spatial; }
  double split_cost() const { return use_spatial ? spatial.cost : object.cost; }
};

/// Counts every job adds to; the sums do not depend on the schedule.
struct Counters {
  std::atomic<size_t> inner{0}, leaves{0}, searches{0}, object{0}, spatial{0}, unsplit{0},
      fallback{0}, rotations{0};
};

/// A subtree built depth-first by one thread, in local indices.
template <int N>
struct Subtree {
  std::vector<typename BuildTree<N>::Node> nodes;
  std::vector<PrimRef> refs;  ///< leaf references in leaf order
  sah::OccluderSummary summary;
};

/// `total` * part / whole without overflow, rounded down.
size_t share(size_t total, size_t part, size_t whole) {
  return whole == 0 ? 0 : size_t((unsigned __int128)total * part / whole);
}

template <int N>
class Builder {
 public:
  using Tree = BuildTree<N>;
  using Node = typename Tree::Node;
  using Child = typename Tree::Child;

  /// Past this node depth nodes are filled by median splits (chapter 4's bound).
  static constexpr int kMedianDepth = kMedianFillDepth<N>;

  Builder(const TriangleMesh& mesh, const SpatialBuildOptions& options, double root_area,
          Counters& counters)
      : mesh_(mesh), options_(options), sah_(with_binning_isa(options.sah)), root_area_(root_area),
        counters_(counters) {
    spatial_on_ = options.mode != SpatialSplitMode::none && options.budget > 0.0f;
    min_priced_refs_ = uint64_t(options.min_leaves) * uint64_t(options.sah.max_leaf_size);
  }

  /// Makes a set of `refs` with `budget`, and evaluates it.
  Set make_set(std::vector<PrimRef>&& refs, size_t budget) const {
    Set s;
    s.refs = std::move(refs);
    s.budget = budget;
    for (const PrimRef& r : s.refs) s.bounds.extend(r.box()), s.centroids.extend(sah::centroid(r));
    evaluate(s);
    return s;
  }

  // [ch05-evaluate]
  /// Prices a set's splits: chapter 4's binned object split always; a spatial split only for a
  /// set of at least min_leaves full leaves, where the object split's children overlap by more
  /// than alpha times the root's area and by at least min_overlap times the set's own.
  void evaluate(Set& s) const {
    const uint32_t n = s.size();
    s.object = sah::Split{};
    s.planes.clear();
    if (n > 1) {
      s.map = sah::BinMapping(s.centroids, sah::bins_for(n, sah_.bins));
      auto bins = std::make_unique_for_overwrite<sah::Bins>();
      bins->reset(s.map.num_bins);
      if (n >= kSpatialLargeJobRefs)
        sah::parallel_bin_prims(s.refs.data(), n, s.map, *bins, binning_isa(sah_));
      else
        sah::bin_prims(s.refs.data(), n, s.map, *bins, binning_isa(sah_));
      s.object = sah::find_best_split(*bins, s.map, sah_.leaf_block);
      const double overlap = s.object.valid()
                                 ? half_area(intersection(s.object.left_bounds, s.object.right_bounds))
                                 : std::numeric_limits<double>::infinity();
      s.spatial_tried = spatial_on_ && s.budget > 0;
      if (s.spatial_tried && n >= min_priced_refs_ && overlap > kSpatialAlpha * root_area_ &&
          overlap >= double(options_.min_overlap) * half_area(s.bounds)) {
        ++counters_.searches;
        s.planes = options_.mode == SpatialSplitMode::centre
                       ? find_centre_splits(s.refs, s.bounds, mesh_, sah_.leaf_block)
                       : find_binned_splits(s.refs, s.bounds, mesh_, options_.spatial_bins,
                                            sah_.leaf_block);
      }
    }
    choose(s);
  }

  /// Picks the cheaper split the set's budget affords, then decides leaf or node with chapter
  /// 4's test. Called again whenever the set's budget changes.
  void choose(Set& s) const {
    const uint32_t n = s.size();
    s.spatial = cheapest_within(s.planes, n, s.budget);
    s.use_spatial = s.spatial.valid() && s.spatial.cost < s.object.cost;
    const double area = half_area(s.bounds);
    if (n <= 1) {
      s.wants_split = false;
    } else if (!s.splittable()) {
      s.wants_split = n > uint32_t(sah_.max_leaf_size);
      s.gain = -std::numeric_limits<double>::infinity();
    } else {
      const double tests = leaf_tests(n, sah_.leaf_block);
      const double leaf = double(sah_.intersection_cost) * area * tests;
      const double split = double(sah_.traversal_cost) * area + double(sah_.intersection_cost) * s.split_cost();
      s.wants_split = n > uint32_t(sah_.max_leaf_size) || split < leaf;
      // As in chapter 4: no extra block to fill a free slot without a large gain.
      const uint32_t left = s.use_spatial ? s.spatial.left_count : s.object.left_count;
      const uint32_t right = s.use_spatial ? s.spatial.right_count : n - s.object.left_count;
      s.gain = slot_fill_gain(area * tests - s.split_cost(), area * tests, n, left, right,
                              sah_.leaf_block);
    }
  }
  // [ch05-evaluate]

  // [ch05-split]
  /// Executes a set's split. The budget left after the split's duplicates is divided between
  /// the halves in proportion to their references.
  std::pair<Set, Set> split(Set&& s, bool median) {
    const size_t n = s.size();
    std::vector<PrimRef> left, right;
    bool done = false;
    if (!median && s.use_spatial) {
      SplitResult r = execute_spatial_split(s.refs, s.spatial, mesh_, options_.unsplit);
      if (!r.left.empty() && !r.right.empty()) {
        left = std::move(r.left), right = std::move(r.right);
        counters_.unsplit += r.unsplit;
        ++counters_.spatial;
        done = true;
      }
    }
    if (!done && !median && s.object.valid()) {
      const sah::SplitPlane plane{&s.map, s.object.axis, s.object.pos};
      left.reserve(s.object.left_count);
      right.reserve(n - s.object.left_count);
      for (const PrimRef& r : s.refs) (plane.goes_left(r) ? left : right).push_back(r);
      ++counters_.object;
      done = !left.empty() && !right.empty();
    }
    if (!done) {  // nothing separates the set (or the median rule): cut it in the middle
      left.assign(s.refs.begin(), s.refs.begin() + ptrdiff_t(n / 2));
      right.assign(s.refs.begin() + ptrdiff_t(n / 2), s.refs.end());
      ++counters_.fallback;
    }
    const size_t used = left.size() + right.size() - n;
    const size_t rest = s.budget > used ? s.budget - used : 0;
    const size_t left_budget = share(rest, left.size(), left.size() + right.size());
    s.refs = {}, s.planes = {};
    Set l = make_set(std::move(left), left_budget);
    Set r = make_set(std::move(right), rest - left_budget);
    return {std::move(l), std::move(r)};
  }
  // [ch05-split]

  /// Fills one node with chapter 4's skeleton (node_filling.h); a split is split() above.
  int fill_node(Set&& set, std::array<Set, N>& kids, int depth) {
    return sah::fill_node<N>(std::move(set), kids, depth, sah_.max_leaf_size,
                             [&](Set chosen, bool median) { return split(std::move(chosen), median); });
  }

  /// A leaf child over `s`, its references appended to `refs`.
  Child leaf(const Set& s, std::vector<PrimRef>& refs) {
    ++counters_.leaves;
    Child c;
    c.box = s.bounds;
    c.index = uint32_t(refs.size());
    c.leaf_count = s.size();
    refs.insert(refs.end(), s.refs.begin(), s.refs.end());
    return c;
  }

  /// A subtree built by one thread, depth first with chapter 4's skeleton, then rotated and
  /// ordered as in chapter 4.
  Subtree<N> build_subtree(Set&& root, int depth) {
    Subtree<N> out;
    const Box3f root_box = root.bounds;
    sah::build_depth_first<N>(
        out.nodes, std::move(root), depth,
        [&](Set&& set, std::array<Set, N>& kids, int d) { return fill_node(std::move(set), kids, d); },
        [&](Set& set) {
          Child c = leaf(set, out.refs);
          set.refs = {};
          return c;
        });
    // Tree rotations
    if (sah_.rotations) {
      const size_t applied = sah::rotate_tree<N>(out.nodes, kRotationRounds);
      counters_.rotations += applied;
      if (applied) out.nodes = sah::preorder<N>(out.nodes);
    }
    // Occluder ordering
    if (sah_.occluder_order != OccluderOrder::off)
      out.summary = sah::order_subtree<N>(out.nodes, root_box, out.refs.data(), sah_);
    counters_.inner += out.nodes.size();
    return out;
  }

 private:
  const TriangleMesh& mesh_;
  const SpatialBuildOptions& options_;
  const SahBuildOptions sah_;  // options.sah, its binning ISA chosen
  double root_area_;
  Counters& counters_;
  bool spatial_on_ = false;
  uint64_t min_priced_refs_ = 0;  ///< the smallest set whose spatial splits are priced
};

void check_options(const SpatialBuildOptions& o) {
  check_sah_options(o.sah, "build_spatial_sah");
  auto fail = [](const std::string& what) { throw std::invalid_argument("build_spatial_sah: " + what); };
  if (o.spatial_bins < 2 || o.spatial_bins > kMaxSpatialBins)
    fail("spatial_bins must be in [2, " + std::to_string(kMaxSpatialBins) + "], got " +
         std::to_string(o.spatial_bins));
  if (!std::isfinite(o.budget) || o.budget < 0.0f) fail("budget must be finite and not negative");
  if (!(o.min_overlap >= 0.0f && o.min_overlap <= 1.0f)) fail("min_overlap must be in [0, 1]");
}

template <int N>
BuildTree<N> build(const TriangleMesh& mesh, const SpatialBuildOptions& options,
                   SpatialBuildStats* stats, std::vector<PrimRef>* leaf_refs_out) {
  using Tree = BuildTree<N>;
  using Node = typename Tree::Node;
  Tree tree;
  Counters counters;
  const SahBuildOptions& sah_options = options.sah;

  // The buildable references, with -0 turned into +0 as chapter 4 does.
  std::vector<PrimRef> input = make_prim_refs(mesh);
  const size_t total_input = input.size();
  std::erase_if(input, [](const PrimRef& r) { return !is_buildable(r); });
  for (PrimRef& r : input) r.lower = r.lower + Vec3f(0.0f), r.upper = r.upper + Vec3f(0.0f);
  const size_t triangles = input.size();
  const size_t budget = size_t(std::floor(double(options.budget) * double(triangles)));
  Box3f scene;
  for (const PrimRef& r : input) scene.extend(r.box());
  Builder<N> builder(mesh, options, half_area(scene), counters);

  std::vector<Node> top;           // nodes of the breadth-first levels, in creation order
  std::vector<Box3f> top_boxes;    // their boxes, for occluder ordering
  std::vector<PrimRef> refs;       // leaf references: the top levels' leaves first
  struct Pending {
    Set set;
    int64_t referrer;  // node index * N + slot, or -1 for the root
    int depth;
  };
  std::vector<Pending> frontier, jobs;
  size_t levels = 0;

  auto place_leaf = [&](Pending& p) {
    const auto c = builder.leaf(p.set, refs);
    if (p.referrer < 0) tree.root = c;
    else top[size_t(p.referrer / N)].children[size_t(p.referrer % N)] = c;
    p.set.refs = {};
  };

  // [ch05-breadth-first]
  // Breadth-first upper levels: every level first pools the budget nobody has spent and deals
  // it out again to all unfinished sets, the next level's and the waiting subtree jobs, in
  // proportion to their references; then it splits the level's sets in parallel. A set's
  // share thus follows its size, never the order in which the tree happens to be built.
  Set root = builder.make_set(std::move(input), budget);
  if (root.size() > 0) {
    const bool small = root.size() < kSmallJobPrims;
    (small ? jobs : frontier).push_back({std::move(root), -1, 1});
  }
  auto pool_budget = [&] {
    size_t held = refs.size(), unfinished = 0;
    for (const auto* list : {&frontier, &jobs})
      for (const Pending& p : *list) held += p.set.size(), unfinished += p.set.size();
    const size_t spent = held - triangles;
    const size_t pool = budget > spent ? budget - spent : 0;
    for (auto* list : {&frontier, &jobs}) {
      for (Pending& p : *list) {
        p.set.budget = share(pool, p.set.size(), unfinished);
        if (p.set.budget > 0 && !p.set.spatial_tried)
          builder.evaluate(p.set);
        else
          builder.choose(p.set);
        if (!p.set.wants_split) place_leaf(p);
      }
      std::erase_if(*list, [](const Pending& p) { return !p.set.wants_split; });
    }
  };
  while (!frontier.empty()) {
    ++levels;
    pool_budget();
    if (frontier.empty()) break;
    std::vector<std::array<Set, N>> kids(frontier.size());
    std::vector<int> count(frontier.size());
    tbb::parallel_for(size_t(0), frontier.size(), [&](size_t i) {
      count[i] = builder.fill_node(std::move(frontier[i].set), kids[i], frontier[i].depth);
    });
    std::vector<Pending> next;
    for (size_t i = 0; i < frontier.size(); ++i) {
      const uint32_t index = uint32_t(top.size());
      const Pending& p = frontier[i];
      if (p.referrer < 0) tree.root.index = index, tree.root.leaf_count = 0;
      else top[size_t(p.referrer / N)].children[size_t(p.referrer % N)].index = index;
      Node& node = top.emplace_back();
      top_boxes.push_back(Box3f());
      node.num_children = count[i];
      ++counters.inner;
      for (int c = 0; c < count[i]; ++c) {
        Set& kid = kids[i][c];
        top_boxes.back().extend(kid.bounds);
        Pending child{std::move(kid), int64_t(index) * N + c, p.depth + 1};
        if (!child.set.wants_split) {
          place_leaf(child);
          continue;
        }
        node.children[c].box = child.set.bounds;
        (child.set.size() < kSmallJobPrims ? jobs : next).push_back(std::move(child));
      }
    }
    frontier = std::move(next);
  }
  pool_budget();
  // [ch05-breadth-first]

  // Subtree jobs: each built depth-first by one thread, with the budget it was dealt.
  std::vector<Subtree<N>> subtrees(jobs.size());
  tbb::parallel_for(size_t(0), jobs.size(), [&](size_t j) {
    subtrees[j] = builder.build_subtree(std::move(jobs[j].set), jobs[j].depth);
  });

  // Assembly: the top nodes first, then each subtree's nodes and leaf references in job order.
  std::vector<size_t> node_at(jobs.size()), ref_at(jobs.size());
  size_t nodes_total = top.size(), refs_total = refs.size();
  for (size_t j = 0; j < jobs.size(); ++j) {
    node_at[j] = nodes_total, ref_at[j] = refs_total;
    nodes_total += subtrees[j].nodes.size(), refs_total += subtrees[j].refs.size();
  }
  tree.nodes.resize(nodes_total);
  std::copy(top.begin(), top.end(), tree.nodes.begin());
  refs.resize(refs_total);
  std::vector<sah::OccluderSummary> job_summary(nodes_total);
  for (size_t j = 0; j < jobs.size(); ++j) {
    const int64_t referrer = jobs[j].referrer;
    if (referrer < 0) tree.root.index = uint32_t(node_at[j]), tree.root.leaf_count = 0;
    else tree.nodes[size_t(referrer / N)].children[size_t(referrer % N)].index = uint32_t(node_at[j]);
    job_summary[node_at[j]] = subtrees[j].summary;
  }
  tbb::parallel_for(size_t(0), jobs.size(), [&](size_t j) {
    const auto& sub = subtrees[j];
    for (size_t k = 0; k < sub.nodes.size(); ++k) {
      Node node = sub.nodes[k];
      for (int c = 0; c < node.num_children; ++c)
        node.children[c].index += uint32_t(node.children[c].is_leaf() ? ref_at[j] : node_at[j]);
      tree.nodes[node_at[j] + k] = node;
    }
    std::copy(sub.refs.begin(), sub.refs.end(), refs.begin() + ptrdiff_t(ref_at[j]));
  });
  if (!tree.nodes.empty()) tree.root.box = scene;  // (a leaf root has its box already)

  // Occluder ordering of the top nodes, bottom-up (children come after their parents).
  if (sah_options.occluder_order != OccluderOrder::off) {
    std::vector<sah::OccluderSummary> summary(top.size());
    for (size_t t = top.size(); t-- > 0;) {
      Node& node = tree.nodes[t];
      std::array<sah::OccluderSummary, N> kids{};
      for (int c = 0; c < node.num_children; ++c) {
        const auto& ch = node.children[c];
        kids[c] = ch.is_leaf() ? sah::leaf_summary(refs.data() + ch.index, ch.leaf_count, ch.box,
                                                   sah_options)
                  : ch.index < top.size() ? summary[ch.index]
                                          : job_summary[ch.index];
      }
      summary[t] = sah::order_children<N>(node, kids, top_boxes[t], sah_options);
    }
  }

  tree.prim_ids.resize(refs.size());
  for (size_t i = 0; i < refs.size(); ++i) tree.prim_ids[i] = refs[i].prim;
  if (stats) {
    *stats = SpatialBuildStats{};
    stats->triangles = triangles;
    stats->skipped = total_input - triangles;
    stats->references = refs.size();
    stats->budget = budget;
    stats->inner_nodes = counters.inner;
    stats->leaves = counters.leaves;
    stats->spatial_searches = counters.searches;
    stats->object_splits = counters.object;
    stats->spatial_splits = counters.spatial;
    stats->unsplit = counters.unsplit;
    stats->fallback_splits = counters.fallback;
    stats->rotations = counters.rotations;
    stats->breadth_first_levels = levels;
    stats->subtree_jobs = jobs.size();
  }
  if (leaf_refs_out) *leaf_refs_out = std::move(refs);
  return tree;
}

}  // namespace
}  // namespace spatial

template <int N>
BuildTree<N> build_spatial_sah(const TriangleMesh& mesh, const SpatialBuildOptions& options,
                               SpatialBuildStats* stats, std::vector<PrimRef>* leaf_refs) {
  static_assert(N == 2 || N == 4 || N == 8 || N == 16, "nodes of 2, 4, 8 or 16 children");
  spatial::check_options(options);
  if (mesh.size() > size_t(std::numeric_limits<uint32_t>::max() / 2))
    throw std::length_error("build_spatial_sah: more than 2^31 triangles");
  if (options.sah.threads == 0) return spatial::build<N>(mesh, options, stats, leaf_refs);
  tbb::task_arena arena(options.sah.threads);
  return arena.execute([&] { return spatial::build<N>(mesh, options, stats, leaf_refs); });
}

template BuildTree<2> build_spatial_sah<2>(const TriangleMesh&, const SpatialBuildOptions&,
                                           SpatialBuildStats*, std::vector<PrimRef>*);
template BuildTree<4> build_spatial_sah<4>(const TriangleMesh&, const SpatialBuildOptions&,
                                           SpatialBuildStats*, std::vector<PrimRef>*);
template BuildTree<8> build_spatial_sah<8>(const TriangleMesh&, const SpatialBuildOptions&,
                                           SpatialBuildStats*, std::vector<PrimRef>*);
template BuildTree<16> build_spatial_sah<16>(const TriangleMesh&, const SpatialBuildOptions&,
                                             SpatialBuildStats*, std::vector<PrimRef>*);

}  // namespace rtk
