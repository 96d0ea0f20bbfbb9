// The slab test (slab.h) of every variant and width: box tests per second, and the speed-up
// over the scalar variant measured in the same run.
//
//   build/chapters/01_base/ch01_bench --benchmark_min_time=1
//
// Rows run in order: the scalar variant first (width 1 is a plain loop over the boxes; widths
// 4, 8 and 16 are the portable backend compiled without ISA flags), then each ISA the machine
// runs at widths 4, 8 and 16. Counters:
//   items_per_second  ray-box tests per second (CPU time)
//   vs_scalar1        speed-up over scalar width 1, the one-box-at-a-time loop
//   vs_scalar_same_w  speed-up over the portable backend at the same width, compiled without
//                     ISA flags: what the intrinsics (or the ISA's flags alone) buy
//   hits              hits per iteration: the same in every row, or a variant is wrong
#include <benchmark/benchmark.h>

#include <ctime>
#include <map>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "01_base/slab_kernels.h"

using namespace rtk;

namespace {

// 1,024 boxes (24 KB of planes: they stay in the L1 cache, so the figures measure arithmetic,
// not memory) and 64 rays through them.
struct Workload {
  std::vector<Box3f> box_list;
  BoxesSoA boxes;
  std::vector<Ray> rays;
};

const Workload& workload() {
  static const Workload w = [] {
    Workload w;
    std::mt19937_64 random(2024);
    auto uniform = [&] { return float(double(random() >> 11) * 0x1.0p-53); };
    for (int i = 0; i < 1024; ++i) {
      const Vec3f lo{uniform(), uniform(), uniform()};
      w.box_list.push_back({lo, lo + Vec3f{uniform(), uniform(), uniform()} * 0.2f});
    }
    w.boxes = BoxesSoA(w.box_list);
    for (int i = 0; i < 64; ++i) {
      Ray r;
      r.org = Vec3f{uniform(), uniform(), uniform()} * 3.0f - Vec3f(1.0f);
      r.dir = Vec3f{uniform(), uniform(), uniform()} - r.org;
      w.rays.push_back(r);
    }
    return w;
  }();
  return w;
}

double thread_cpu_seconds() {
  timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

// Box tests per CPU second of the rows run so far, for the speed-up counters.
std::map<std::pair<Isa, int>, double>& rates() {
  static std::map<std::pair<Isa, int>, double> r;
  return r;
}

void bench_slab(benchmark::State& state, Isa isa, int width) {
  const Workload& w = workload();
  const auto count = RTK_PICK_ISA(isa, count_box_hits);
  const double tests_per_iteration = double(w.rays.size() * w.boxes.padded_count());
  uint64_t hits = 0;
  const double start = thread_cpu_seconds();
  for (auto _ : state) {
    hits = count(width, w.rays, w.boxes);
    benchmark::DoNotOptimize(hits);
  }
  const double seconds = thread_cpu_seconds() - start;
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(tests_per_iteration));
  const double rate = double(state.iterations()) * tests_per_iteration / seconds;
  rates()[{isa, width}] = rate;
  state.counters["hits"] = double(hits);
  if (auto base = rates().find({Isa::scalar, 1}); base != rates().end())
    state.counters["vs_scalar1"] = rate / base->second;
  if (auto same = rates().find({Isa::scalar, width}); same != rates().end())
    state.counters["vs_scalar_same_w"] = rate / same->second;
}

const bool registered = [] {
  for (Isa isa : supported_isas())
    for (int width : kSlabWidths) {
      if (width == 1 && isa != Isa::scalar) continue;  // one box at a time: the scalar variant's loop only
      const std::string name = "slab/" + std::string(isa_name(isa)) + "/w" + std::to_string(width);
      benchmark::RegisterBenchmark(name.c_str(), bench_slab, isa, width);
    }
  return true;
}();

}  // namespace
