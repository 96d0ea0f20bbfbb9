// Speed against accuracy for the three reciprocals of the wrappers (1/a, rcp, rcp_fast), in
// every variant at the width of its registers (the scalar variant at width 4).
//
//   build/chapters/01_base/ch01_bench --benchmark_filter=reciprocal --benchmark_min_time=1
//
// Counters:
//   items_per_second  reciprocals per second (CPU time), over 4,096 floats that stay in cache
//   vs_divide         speed-up over 1/a in the same variant
//   max_rel_error     the largest relative error over 2^16 inputs spanning the domain
//                     2^-126 <= |a| < 2^125 (every exponent, random mantissas, both signs)
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <ctime>
#include <map>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "01_base/simd_ops.h"

using namespace rtk;

namespace {

std::vector<float> domain_sample(size_t n, uint64_t seed) {
  std::mt19937_64 random(seed);
  std::vector<float> x(n);
  for (float& v : x) {
    const int exponent = int(random() % 251) - 126;  // 2^-126 ... 2^124
    const float mantissa = 1.0f + float(random() & 0x7FFFFF) * 0x1p-23f;
    v = std::ldexp(random() % 2 ? -mantissa : mantissa, exponent);
  }
  return x;
}

double max_relative_error(Isa isa, Reciprocal method, int width) {
  const std::vector<float> x = domain_sample(1 << 16, 7);
  std::vector<float> r(x.size());
  RTK_PICK_ISA(isa, reciprocal_array)(method, width, x.data(), r.data(), x.size());
  double worst = 0;
  for (size_t i = 0; i < x.size(); ++i) {
    const double exact = 1.0 / double(x[i]);
    worst = std::max(worst, std::fabs((double(r[i]) - exact) / exact));
  }
  return worst;
}

double thread_cpu_seconds() {
  timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

// Reciprocals per CPU second of the `divide` rows run so far, for the vs_divide counter.
std::map<Isa, double>& divide_rates() {
  static std::map<Isa, double> r;
  return r;
}

void bench_reciprocal(benchmark::State& state, Isa isa, Reciprocal method, int width) {
  static const std::vector<float> x = domain_sample(4096, 3);
  std::vector<float> out(x.size());
  const auto reciprocals = RTK_PICK_ISA(isa, reciprocal_array);
  const double start = thread_cpu_seconds();
  for (auto _ : state) {
    reciprocals(method, width, x.data(), out.data(), x.size());
    benchmark::ClobberMemory();
  }
  const double rate = double(state.iterations()) * double(x.size()) / (thread_cpu_seconds() - start);
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(x.size()));
  state.counters["max_rel_error"] = max_relative_error(isa, method, width);
  if (method == Reciprocal::divide) divide_rates()[isa] = rate;
  if (auto divide = divide_rates().find(isa); divide != divide_rates().end())
    state.counters["vs_divide"] = rate / divide->second;
}

const bool registered = [] {
  const char* names[] = {"divide", "rcp", "rcp_fast"};
  for (Isa isa : supported_isas()) {
    const int width = isa == Isa::scalar ? 4 : RTK_PICK_ISA(isa, simd_native_width)();
    for (Reciprocal method : {Reciprocal::divide, Reciprocal::rcp, Reciprocal::rcp_fast}) {
      const std::string name = "reciprocal/" + std::string(isa_name(isa)) + "/w" +
                               std::to_string(width) + "/" + names[int(method)];
      benchmark::RegisterBenchmark(name.c_str(), bench_reciprocal, isa, method, width);
    }
  }
  return true;
}();

}  // namespace
