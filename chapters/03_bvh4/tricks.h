/// \file
/// The traversal tricks of the guide (section 4.1.1), each one a switch, so that the book can
/// show what each one buys.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace rtk {

// [ch03-tricks]
/// Which of the guide's traversal optimisations a BVH4/BVH8 traversal uses. The traversal is a
/// template over this struct: every switch is decided at compile time, so a trick that is off
/// costs nothing, and the variant with all tricks on is the fast path.
struct Tricks {
  /// Load the near and far planes of each axis from offsets chosen once per ray by the sign
  /// of the direction, instead of loading both planes and sorting them with min and max.
  bool near_far_by_sign = true;
  /// Read the top of the stack before the box test, so that when no child is hit the next
  /// node is already in a register ("0 children hit").
  bool early_pop = true;
  /// With one child hit, go to it directly, with no push and pop.
  bool one_hit_path = true;
  /// With two children hit, push the farther and go to the nearer.
  bool two_hit_path = true;
  /// Keep each pushed child's entry distance on the stack, and skip a popped child that
  /// begins beyond the closest hit found since.
  bool cull_at_pop = true;
  /// With more than two children hit, push them all and sort the pushed entries by distance,
  /// closest on top; without it they are popped in the order of the node's slots.
  bool sorted_push = true;
  /// Ask the cache for each child node as soon as the ray is known to enter it, so that the
  /// node's lines are on their way while the ray finishes the current node or the ones before
  /// it on the stack (Embree's kernels do the same).
  bool prefetch_children = true;
  /// Shadow rays (occlusion) visit the hit children in the order the builder stored them
  /// (chapter 4 puts the likely blockers first) and keep no distances: any hit ends the ray,
  /// so the nearest child is not worth sorting for. Without it, shadow rays visit nearest first
  /// like closest-hit rays.
  bool shadow_rays_in_stored_order = true;
  /// Widen every box's exit distance by the slab test's rounding bound (chapter 2's
  /// conservative_exit.h), so that no box whose triangle the leaf test would hit is culled.
  /// Not a speed trick but a correctness one: it is a switch only so that chapter 7 can measure
  /// the leaks it stops and this chapter what it costs.
  bool conservative_exits = true;

  constexpr bool operator==(const Tricks&) const = default;
};
// [ch03-tricks]

/// A trick configuration with a name for tables and benchmarks.
struct NamedTricks {
  std::string_view name;
  Tricks tricks;
};

/// The configurations the kernels are compiled for: all tricks on, each one off alone, and all
/// off (not all 2^8 combinations: the ablation asks what each trick adds to the others).
inline constexpr NamedTricks kTrickConfigs[] = {
    {"all", Tricks{}},
    {"no_near_far", Tricks{.near_far_by_sign = false}},
    {"no_early_pop", Tricks{.early_pop = false}},
    {"no_one_hit", Tricks{.one_hit_path = false}},
    {"no_two_hit", Tricks{.two_hit_path = false}},
    {"no_cull_at_pop", Tricks{.cull_at_pop = false}},
    {"no_sorted_push", Tricks{.sorted_push = false}},
    {"no_prefetch", Tricks{.prefetch_children = false}},
    {"no_stored_order", Tricks{.shadow_rays_in_stored_order = false}},
    {"no_conservative_exits", Tricks{.conservative_exits = false}},
    {"none", Tricks{false, false, false, false, false, false, false, false, false}},
};
inline constexpr size_t kTrickConfigCount = sizeof(kTrickConfigs) / sizeof(kTrickConfigs[0]);

/// The index of `tricks` in kTrickConfigs, or kTrickConfigCount when it is not compiled.
constexpr size_t trick_config_index(const Tricks& tricks) {
  for (size_t i = 0; i < kTrickConfigCount; ++i)
    if (kTrickConfigs[i].tricks == tricks) return i;
  return kTrickConfigCount;
}

/// The names of the compiled configurations, for error messages: "all, no_near_far, ...".
inline std::string trick_config_names() {
  std::string names;
  for (const NamedTricks& c : kTrickConfigs) names += (names.empty() ? "" : ", ") + std::string(c.name);
  return names;
}

}  // namespace rtk
