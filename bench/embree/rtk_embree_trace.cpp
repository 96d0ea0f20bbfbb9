// rtk-embree-trace: `rtk trace` with Embree 3 in place of RTK, so that the two tracers can be
// compared hit for hit on the same rays:
//   rtk rays    -i scene.obj -kind diffuse -n 1000000 -o d.rays
//   rtk trace   -i scene.obj -rays d.rays -hits rtk.hits
//   rtk-embree-trace -i scene.obj -rays d.rays -hits embree.hits
//   rtk compare rtk.hits embree.hits
// Same options (less -accel, -tri and -isa, which are Embree's own business) and the same JSON
// lines; -threads sets Embree's build threads and the tracing threads (oneTBB).
#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "01_base/timer.h"
#include "embree/embree_scene.h"
#include "io/obj_loader.h"
#include "io/replay_files.h"
#include "json_line.h"
#include "options.h"

namespace {

using namespace rtk;
using rtk::cli::JsonLine;

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

template <class Body>
void run_parallel(size_t n, int threads, const Body& body) {
  if (threads <= 1) {
    body(size_t(0), n);
    return;
  }
  tbb::task_arena arena(threads);
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 1024),
                      [&](const tbb::blocked_range<size_t>& r) { body(r.begin(), r.end()); });
  });
}

int run(std::span<const std::string_view> args) {
  const cli::Options options("", args,
                             {.with_value = {"i", "rays", "hits", "occl", "threads", "repeat"}, .flags = {}});
  const std::string scene = options.required("i");
  const std::string rays_file = options.required("rays");
  const bool want_hits = options.has("hits");
  if (want_hits == options.has("occl"))
    throw options.error(want_hits ? "options -hits and -occl exclude each other"
                                  : "missing option -hits or -occl (what to write)");
  const std::string output = options.required(want_hits ? "hits" : "occl");
  const int threads = int(options.get_count("threads", 1, 1, 1024));
  const size_t repeat = options.get_count("repeat", 1, 1, 1000);

  const TriangleMesh mesh = load_obj(scene);
  const std::vector<Ray> rays = read_rays(rays_file);
  std::vector<double> build_seconds;
  std::unique_ptr<EmbreeScene> embree;
  for (size_t r = 0; r < repeat; ++r) {
    embree.reset();
    embree = std::make_unique<EmbreeScene>(mesh, threads);
    build_seconds.push_back(embree->build_seconds());
  }
  const double build = median(build_seconds);
  JsonLine()
      .add("op", "build")
      .add("accel", "embree-" + EmbreeScene::version())
      .add("tri", "embree")
      .add("isa", "embree")
      .add("triangles", mesh.size())
      .add("seconds", build)
      .add("mtris_per_s", build > 0 ? double(mesh.size()) / build * 1e-6 : 0.0)
      .add("bytes", embree->total_bytes())
      .add("threads", threads)
      .print();

  std::vector<Hit> hits(want_hits ? rays.size() : 0);
  std::vector<uint8_t> occluded(want_hits ? 0 : rays.size());
  std::vector<double> seconds;
  for (size_t r = 0; r < repeat; ++r) {
    Timer timer;
    run_parallel(rays.size(), threads, [&](size_t b, size_t e) {
      const std::span<const Ray> part(rays.data() + b, e - b);
      if (want_hits) embree->intersect(part, std::span<Hit>(hits.data() + b, e - b));
      else embree->occluded(part, std::span<uint8_t>(occluded.data() + b, e - b));
    });
    seconds.push_back(timer.seconds());
  }
  const double s = median(seconds);
  JsonLine line;
  line.add("op", want_hits ? "intersect" : "occluded")
      .add("rays", rays.size())
      .add("seconds", s)
      .add("mrays_per_s", s > 0 ? double(rays.size()) / s * 1e-6 : 0.0)
      .add("threads", threads);
  if (want_hits) {
    line.add("hits", size_t(std::count_if(hits.begin(), hits.end(), [](const Hit& h) { return h.found(); })));
    write_hits(output, hits);
  } else {
    line.add("occluded", size_t(std::count(occluded.begin(), occluded.end(), uint8_t(1))));
    write_occlusion(output, occluded);
  }
  line.add("repeat", repeat).add("output", output).print();
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string_view> args(argv + 1, argv + argc);
  try {
    return run(args);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "rtk-embree-trace: %s\n", e.what());
    std::fprintf(stderr,
                 "usage: rtk-embree-trace -i SCENE.obj -rays R.rays (-hits H.hits | -occl O.occl) "
                 "[-threads N] [-repeat N]\n");
    return 2;
  }
}
