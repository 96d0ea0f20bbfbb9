#include "api/backends.h"

#include "02_bvh2/bvh2.h"
#include "03_bvh4/bvh4.h"
#include "04_sah/build_sah.h"

namespace rtk::api {

namespace {

// A built BVH of any width and the ISA whose kernels trace it. The chapters' kernels already
// make invalid rays miss and check the leaf layout; this class only binds the choices.
template <class Bvh>
class BvhBackend final : public AccelBackend {
 public:
  BvhBackend(Bvh bvh, Isa isa) : bvh_(std::move(bvh)), isa_(isa) {}
  void intersect(std::span<const Ray> rays, std::span<Hit> hits) const override {
    rtk::intersect(isa_, bvh_, rays, hits);
  }
  void occluded(std::span<const Ray> rays, std::span<uint8_t> occluded) const override {
    rtk::occluded(isa_, bvh_, rays, occluded);
  }
  size_t bytes() const override { return bvh_.bytes(); }

 private:
  Bvh bvh_;
  Isa isa_;
};

// Object splits: chapter 4's binned SAH builder with its default options, on `threads`
// threads (the tree is the same for any count), then the node layout of width N with
// triangle1 leaves (Möller-Trumbore on precomputed edges).
template <int N>
std::unique_ptr<AccelBackend> build_objectsplit_triangle1(const TriangleMesh& mesh, Isa isa, int threads) {
  SahBuildOptions options;
  options.threads = threads;
  const BuildTree<N> tree = build_binned_sah<N>(make_prim_refs(mesh), options);
  if constexpr (N == 2) {
    return std::make_unique<BvhBackend<BVH2>>(make_bvh2<Triangle1Layout>(tree, mesh), isa);
  } else {
    return std::make_unique<BvhBackend<BVHN<N>>>(make_bvh<N, Triangle1Layout>(tree, mesh), isa);
  }
}

}  // namespace

const std::vector<BackendEntry>& backend_table() {
  static const std::vector<BackendEntry> table = {
      {"bvh2", "objectsplit", "triangle1", "moeller", &build_objectsplit_triangle1<2>},
      {"bvh4", "objectsplit", "triangle1", "moeller", &build_objectsplit_triangle1<4>},
      {"bvh8", "objectsplit", "triangle1", "moeller", &build_objectsplit_triangle1<8>},
  };
  return table;
}

}  // namespace rtk::api
