/// \file
/// What a structure's kernels look like from outside: two plain functions, one for closest hits
/// and one for occlusion, each tracing a span of independent rays through one built structure.
#pragma once

#include <cstdint>
#include <span>

#include "01_base/ray.h"

namespace rtk {

// [ch02-trace-kernels]
/// The batch kernels of one kind of structure, for one ISA and one leaf configuration. Every
/// structure of the book hands out its kernels in this form, and the public API (chapter 10)
/// resolves a configuration string to one such pair when it builds the structure, so that a
/// batch reaches its traversal loop through one indirect call. The structure is passed untyped
/// so that one pair type serves every structure; each kernel was made for one structure type
/// and reads `structure` as that type.
struct TraceKernels {
  /// rays[i] gives hits[i], the closest hit (a miss for an invalid ray).
  void (*intersect)(const void* structure, std::span<const Ray> rays, std::span<Hit> hits) = nullptr;
  /// rays[i] gives occluded[i]: 1 when anything blocks [tnear, tfar], else 0.
  void (*occluded)(const void* structure, std::span<const Ray> rays, std::span<uint8_t> occluded) = nullptr;
};
// [ch02-trace-kernels]

}  // namespace rtk
