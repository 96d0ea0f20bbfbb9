// How fast the strict OBJ loader reads: a 1M-triangle terrain written as OBJ text (shortest
// round-trip decimals, as an exporter writes them), parsed from memory and loaded from a file.
//   build/bench/bench_obj --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>

#include <filesystem>
#include <string>

#include "io/obj_loader.h"
#include "io/obj_writer.h"
#include "testing/scenes.h"

namespace {

// 708 x 708 quads = 1,002,528 triangles.
const std::string& terrain_text() {
  static const std::string text = rtk::format_obj(rtk::test::make_terrain(708, 1));
  return text;
}

void report(benchmark::State& state, size_t bytes, size_t triangles) {
  state.SetBytesProcessed(int64_t(state.iterations()) * int64_t(bytes));
  state.counters["MB"] = double(bytes) * 1e-6;
  state.counters["triangles"] = double(triangles);
  state.counters["Mtris/s"] =
      benchmark::Counter(double(triangles) * 1e-6, benchmark::Counter::kIsIterationInvariantRate);
}

void BM_parse_obj_memory(benchmark::State& state) {
  const std::string& text = terrain_text();
  size_t triangles = 0;
  for (auto _ : state) {
    const rtk::TriangleMesh mesh = rtk::parse_obj(text, "terrain.obj");
    triangles = mesh.size();
    benchmark::DoNotOptimize(mesh.triangles.data());
  }
  report(state, text.size(), triangles);
}

void BM_load_obj_file(benchmark::State& state) {
  const std::filesystem::path file = std::filesystem::temp_directory_path() / "rtk_bench_terrain.obj";
  rtk::save_obj(file, rtk::test::make_terrain(708, 1));
  size_t triangles = 0;
  for (auto _ : state) {
    const rtk::TriangleMesh mesh = rtk::load_obj(file);
    triangles = mesh.size();
    benchmark::DoNotOptimize(mesh.triangles.data());
  }
  report(state, std::filesystem::file_size(file), triangles);
  std::filesystem::remove(file);
}

}  // namespace

BENCHMARK(BM_parse_obj_memory)->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK(BM_load_obj_file)->Unit(benchmark::kMillisecond)->MinTime(2.0);
