/// \file
/// The table behind the public API: one entry per configuration the chapters implement, each
/// with the function that builds it for an ISA. Adding a kernel to the API is adding a row.
#pragma once

#include <memory>
#include <span>
#include <string_view>
#include <utility>
#include <vector>

#include "09_kernel_api/accel.h"

namespace rtk::api {

/// A built BVH of any kind and the ISA whose kernels trace it: the structure's own
/// `intersect(isa, bvh, ...)` and `occluded(isa, bvh, ...)`, found for `Bvh`'s type. The
/// chapters' kernels already make invalid rays miss and check the leaf layout; this class only
/// binds the choices.
namespace detail {
// Unqualified calls: argument-dependent lookup finds, where BvhBackend<Bvh> is instantiated,
// the `intersect` and `occluded` that the chapter of `Bvh` declares next to it.
template <class Bvh>
void trace(Isa isa, const Bvh& bvh, std::span<const Ray> rays, std::span<Hit> hits) {
  intersect(isa, bvh, rays, hits);
}
template <class Bvh>
void trace(Isa isa, const Bvh& bvh, std::span<const Ray> rays, std::span<uint8_t> blocked) {
  occluded(isa, bvh, rays, blocked);
}
}  // namespace detail

template <class Bvh>
class BvhBackend final : public AccelBackend {
 public:
  BvhBackend(Bvh bvh, Isa isa) : bvh_(std::move(bvh)), isa_(isa) {}
  void intersect(std::span<const Ray> rays, std::span<Hit> hits) const override {
    detail::trace(isa_, bvh_, rays, hits);
  }
  void occluded(std::span<const Ray> rays, std::span<uint8_t> occluded) const override {
    detail::trace(isa_, bvh_, rays, occluded);
  }
  size_t bytes() const override { return bvh_.bytes(); }

 private:
  Bvh bvh_;
  Isa isa_;
};

/// Builds one configuration's structure for an ISA with at most `threads` threads.
using BuildFunction = std::unique_ptr<AccelBackend> (*)(const TriangleMesh& mesh, Isa isa, int threads);

/// One configuration: `accel` = base + "." + split, `tri` = layout + "." + intersector.
struct BackendEntry {
  std::string_view base;         ///< "bvh2", "bvh4", "bvh8"
  std::string_view split;        ///< "objectsplit" or "spatialsplit"
  std::string_view layout;       ///< "triangle1", "triangle4", ...
  std::string_view intersector;  ///< "moeller" or "pluecker"
  BuildFunction build;
};

/// Every configuration RTK has, in order of preference within a base and layout.
const std::vector<BackendEntry>& backend_table();

}  // namespace rtk::api
