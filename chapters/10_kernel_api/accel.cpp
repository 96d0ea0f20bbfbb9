#include "10_kernel_api/accel.h"

#include <unistd.h>

#include <algorithm>
#include <limits>
#include <stdexcept>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "01_base/timer.h"
#include "07_intersectors/triangle_config.h"
#include "10_kernel_api/motion_accel.h"
#include "10_kernel_api/backends.h"

namespace rtk {

namespace {

using api::BackendEntry;
using api::backend_table;

constexpr int kMaxThreads = 1024;
// Rays per task when tracing with several threads: large enough that scheduling costs nothing
// next to traversal, small enough that two cores stay balanced on incoherent rays.
constexpr size_t kRaysPerTask = 1024;

std::string accel_name(const BackendEntry& e) { return std::string(e.base) + "." + std::string(e.split); }
std::string tri_name(const BackendEntry& e) { return e.tri.name(); }

std::string join(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
  return out.empty() ? "none yet" : out;
}

// "bvh4.spatialsplit" -> {"bvh4", "spatialsplit"}; no dot -> {name, ""}.
std::pair<std::string, std::string> split_spec(const std::string& spec) {
  const size_t dot = spec.find('.');
  if (dot == std::string::npos) return {spec, ""};
  return {spec.substr(0, dot), spec.substr(dot + 1)};
}

// The node width the ISA's registers fit, as the guide recommends BVH4 for SSE and the wider
// layout for AVX: the preferred bases in order.
std::vector<std::string_view> preferred_bases(Isa isa) {
  if (isa == Isa::avx2 || isa == Isa::avx512) return {"bvh8", "bvh4", "bvh2"};
  return {"bvh4", "bvh8", "bvh2"};
}
// The memory the leaves of a default layout may take: the caller's budget, or half of the
// machine's physical memory.
size_t memory_budget(const AccelConfig& config) {
  if (config.memory_budget) return config.memory_budget;
  const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
  return pages > 0 && page > 0 ? size_t(pages) * size_t(page) / 2 : std::numeric_limits<size_t>::max();
}

// The table row for a configuration, resolving defaults for a scene of `triangles` (0 when
// not known yet); `choice` receives why the layout was chosen. Throws naming the option.
const BackendEntry& resolve(const AccelConfig& config, Isa isa, size_t triangles = 0,
                            std::string* choice = nullptr) {
  const auto& table = backend_table();
  // Step 1: the acceleration structure and its split strategy.
  auto [base, split] = split_spec(config.accel);
  if (base.empty()) {
    for (std::string_view b : preferred_bases(isa)) {
      const bool have = std::any_of(table.begin(), table.end(), [&](const BackendEntry& e) { return e.base == b; });
      if (have) {
        base = b;
        break;
      }
    }
    if (base.empty()) throw std::invalid_argument("-accel: no acceleration structure is available yet");
  }
  if (split.empty()) {
    // Object splits are the guide's default; a structure built only with another strategy
    // takes that one.
    split = "objectsplit";
    const bool have = std::any_of(table.begin(), table.end(),
                                  [&](const BackendEntry& e) { return e.base == base && e.split == split; });
    if (!have)
      for (const BackendEntry& e : table)
        if (e.base == base) {
          split = e.split;
          break;
        }
  }
  const std::string accel = base + "." + split;
  std::vector<const BackendEntry*> rows;
  for (const BackendEntry& e : table)
    if (e.base == base && e.split == split) rows.push_back(&e);
  if (base == "bvh4mb")  // chapter 8's structure is built from two meshes: api/motion_accel.h
    throw std::invalid_argument("-accel: bvh4mb is built by Accel(t0, t1, config) (10_kernel_api/motion_accel.h)");
  if (rows.empty())
    throw std::invalid_argument("-accel: '" + config.accel + "' is not available; supported: " +
                                join(supported_accels()));

  // Step 2: the triangle layout and its intersector. Chapter 6's parser resolves `.fast` and
  // `.accurate` for the layout named; without -tri, chapter 6's rule picks the layout: the
  // ISA's fastest blocks, unless the scene would not fit the memory budget with them (model no
  // more than the scene needs).
  auto row_for = [&](const TriangleConfig& c) -> const BackendEntry* {
    for (const BackendEntry* e : rows)
      if (e->tri == c) return e;
    return nullptr;
  };
  auto say = [&](const std::string& why) {
    if (choice) *choice = why;
  };
  if (config.tri.empty()) {
    const size_t budget = memory_budget(config);
    const int width = base == "bvh8" ? 8 : base == "bvh2" ? 2 : 4;
    const TriangleLayout fastest = choose_default_layout(0, isa, width);
    const TriangleLayout chosen = choose_default_layout(triangles, isa, width, budget);
    if (const BackendEntry* e = row_for({chosen, IntersectorKind::moeller})) {
      say(chosen == fastest ? "default: " + std::string(layout_name(chosen)) + ", the fastest blocks for " +
                                  std::string(isa_name(isa))
                            : "default: " + std::string(layout_name(chosen)) + ", the leanest layout: " +
                                  std::string(layout_name(fastest)) + " would need about " +
                                  std::to_string(size_t(estimated_bytes_per_triangle(fastest, width) * double(triangles)) >> 20) +
                                  " MiB of the " + std::to_string(budget >> 20) + " MiB budget");
      return *e;
    }
    say("default: " + tri_name(*rows.front()) + ", the only leaves " + accel + " has");
    return *rows.front();
  }
  TriangleConfig wanted;
  try {
    wanted = parse_triangle_config(config.tri);
  } catch (const std::invalid_argument&) {
    throw std::invalid_argument("-tri: '" + config.tri + "' is not a supported configuration; supported with " +
                                accel + ": " + join(supported_tris(accel)) +
                                " (a layout alone, or with .fast or .accurate, takes its fastest or most accurate intersector)");
  }
  if (const BackendEntry* e = row_for(wanted)) {
    say("asked for " + config.tri);
    return *e;
  }
  throw std::invalid_argument("-tri: '" + config.tri + "' is not available with " + accel + "; supported: " +
                              join(supported_tris(accel)));
}

Isa resolve_isa(const AccelConfig& config) {
  if (!config.isa) return best_isa();
  if (!isa_supported(*config.isa))
    throw std::invalid_argument("-isa: this CPU cannot run '" + std::string(isa_name(*config.isa)) + "'");
  return *config.isa;
}

void check_threads(int threads) {
  if (threads < 1 || threads > kMaxThreads)
    throw std::invalid_argument("-threads: " + std::to_string(threads) + " is not from 1 to " +
                                std::to_string(kMaxThreads));
}

// Runs work() on `threads` threads: in a task arena of that many, or inline for one thread, so
// that single-threaded timings carry no scheduling cost at all.
template <class Work>
void with_threads(int threads, const Work& work) {
  if (threads <= 1) return work();
  tbb::task_arena arena(threads);
  arena.execute(work);
}

// Runs body(begin, end) over [0, n) in chunks on the threads of the current task arena (inline
// for one thread or few rays).
template <class Body>
void run_parallel(size_t n, int threads, const Body& body) {
  if (threads <= 1 || n <= kRaysPerTask) return body(size_t(0), n);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, n, kRaysPerTask),
                    [&](const tbb::blocked_range<size_t>& r) { body(r.begin(), r.end()); });
}

}  // namespace

std::vector<std::string> supported_accels() {
  std::vector<std::string> names;
  for (const BackendEntry& e : backend_table())
    if (std::find(names.begin(), names.end(), accel_name(e)) == names.end()) names.push_back(accel_name(e));
  return names;
}

std::vector<std::string> supported_tris(const std::string& accel) {
  std::vector<std::string> names;
  for (const BackendEntry& e : backend_table()) {
    if (!accel.empty() && accel_name(e) != accel) continue;
    if (std::find(names.begin(), names.end(), tri_name(e)) == names.end()) names.push_back(tri_name(e));
  }
  return names;
}

namespace {

// The configuration resolved for a scene of `triangles` triangles (0 when not known yet), and
// its table row.
std::pair<AccelInfo, const BackendEntry*> resolve_for(const AccelConfig& config, size_t triangles) {
  check_threads(config.threads);
  AccelInfo info;
  info.isa = resolve_isa(config);
  const BackendEntry& entry = resolve(config, info.isa, triangles, &info.choice);
  info.accel = accel_name(entry);
  info.tri = tri_name(entry);
  info.threads = config.threads;
  return {info, &entry};
}

}  // namespace

AccelInfo resolve_config(const AccelConfig& config) { return resolve_for(config, 0).first; }

Accel::Accel(const TriangleMesh& mesh, const AccelConfig& config) {
  // Chapter 8's motion structure on a static scene, as Embree 1.1 builds it: the mesh is its
  // own position at time 1, and every vertex stands still.
  if (config.accel == kMotionAccel || config.accel.starts_with(std::string(kMotionAccel) + ".")) {
    *this = Accel(mesh, mesh, config);
    return;
  }
  // As resolve_config(), for a scene of this size, which may change the default layout.
  const auto [info, row] = resolve_for(config, mesh.size());
  info_ = info;
  const BackendEntry& entry = *row;
  if (mesh.vertices.size() >= kInvalidPrim || mesh.triangles.size() >= kInvalidPrim)
    throw std::invalid_argument("the scene has more than 2^32 - 2 triangles or vertices");
  // A vertex index past the vertices is refused by the builder (chapters 4 and 5), in the pass
  // that reads the triangles anyway, before anything reads a vertex, naming the triangle.
  info_.triangles = mesh.size();
  Timer timer;
  api::BuiltStructure built = entry.build(mesh, info_.isa, config.threads, entry.tri);
  info_.build_seconds = timer.seconds();
  info_.bytes = built.bytes;
  structure_ = std::move(built.owner);
  traced_ = built.traced;
  kernels_ = built.kernels;
  given_ = config.packets && built.packets.intersect ? built.packets : built.kernels;
  choose_order(mesh.bounds(), config.order);
}

void Accel::choose_order(const Box3f& scene, RayOrderPolicy::Mode mode) {
  order_key_ = RayOrderKey(scene);
  order_policy_.mode = mode;
}

Accel::~Accel() = default;
Accel::Accel(Accel&&) noexcept = default;
Accel& Accel::operator=(Accel&&) noexcept = default;

// [ch10-intersect]
namespace {

/// Rays sorted at a time: the sort's memory (42 bytes a ray: a copy of the ray, where it came
/// from, its key) stays bounded however large the batch, and half a million rays are dense
/// enough in any scene for neighbours in the order to share nodes.
constexpr size_t kOrderWindow = size_t(1) << 19;

/// Traces rays[i] into answers[i] in windows, each sorted when the policy says so and then
/// traced by `in_order` (chapter 9's intersect_sorted or occluded_sorted, one ray at a time
/// with `kernels`), or else traced as given by `given` (closest hits or occlusion: in packets
/// where the configuration has them), on `threads` threads.
template <class Answer>
void trace_batch(std::span<const Ray> rays, std::span<Answer> answers,
                 void (*given)(const void*, std::span<const Ray>, std::span<Answer>),
                 void (*in_order)(const TraceKernels&, const void*, const SortedRays&, size_t, size_t,
                                  std::span<Answer>),
                 const TraceKernels& kernels, const void* structure, const RayOrderKey& key,
                 const RayOrderPolicy& policy, int threads) {
  // One task arena for the sorts and the traces (TBB warns when arenas come and go faster
  // than its threads move between them), and none for a batch too small to share.
  if (rays.size() <= kRaysPerTask) threads = 1;
  with_threads(threads, [&] {
    SortedRays window;
    for (size_t first = 0; first < rays.size(); first += kOrderWindow) {
      const size_t n = std::min(kOrderWindow, rays.size() - first);
      const std::span<Answer> out = answers.subspan(first, n);
      if (sort_rays(rays.subspan(first, n), key, policy, window, threads))
        run_parallel(n, threads, [&](size_t begin, size_t end) {
          in_order(kernels, structure, window, begin, end - begin, out);
        });
      else
        run_parallel(n, threads, [&](size_t begin, size_t end) {
          given(structure, rays.subspan(first + begin, end - begin), out.subspan(begin, end - begin));
        });
    }
  });
}

}  // namespace

void Accel::intersect(std::span<const Ray> rays, std::span<Hit> hits) const {
  if (rays.size() != hits.size()) throw std::invalid_argument("intersect: rays and hits differ in length");
  trace_batch(rays, hits, given_.intersect, intersect_sorted, kernels_, traced_, order_key_, order_policy_,
              info_.threads);
}

void Accel::occluded(std::span<const Ray> rays, std::span<uint8_t> occluded) const {
  if (rays.size() != occluded.size()) throw std::invalid_argument("occluded: rays and answers differ in length");
  trace_batch(rays, occluded, given_.occluded, occluded_sorted, kernels_, traced_, order_key_,
              order_policy_, info_.threads);
}
// [ch10-intersect]

}  // namespace rtk
