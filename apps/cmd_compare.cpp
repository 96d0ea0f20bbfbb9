// `rtk compare A B [-rays R.rays]`: do two tracers agree on the same rays? Works on two .hits
// files or two .occl files (lib/replay/compare.h defines agreement; with -rays the t tolerance
// scales with each ray's origin as well). Prints one JSON line with the counts, then one line
// per disagreeing ray for the first few; the exit status is 1 when more rays disagree than
// -allow permits (default: none), so that scripts can test it.
#include <cmath>
#include <cstdio>
#include <string>

#include "commands.h"
#include "io/file_error.h"
#include "io/read_file.h"
#include "io/replay_files.h"
#include "json_line.h"
#include "options.h"
#include "replay/compare.h"

namespace rtk::cli {

namespace {

std::string hit_json(const Hit& h) {
  JsonLine line;
  if (h.found()) {
    line.add("prim", h.prim).add("t", double(h.t)).add("u", double(h.u)).add("v", double(h.v));
  } else {
    line.add("prim", "miss");
  }
  return line.str();
}

int compare_hits_files(const std::string& name_a, std::string_view bytes_a, const std::string& name_b,
                       std::string_view bytes_b, const std::string& rays_file, double tolerance,
                       double allow_percent, size_t show) {
  const std::vector<Hit> a = parse_hits(bytes_a, name_a);
  const std::vector<Hit> b = parse_hits(bytes_b, name_b);
  if (a.size() != b.size())
    throw FileError(name_b, 0, "holds " + std::to_string(b.size()) + " hits, but " + name_a + " holds " +
                                   std::to_string(a.size()) + ": not the same rays");
  std::vector<Ray> rays;
  if (!rays_file.empty()) {
    rays = read_rays(rays_file);
    if (rays.size() != a.size())
      throw FileError(rays_file, 0, "holds " + std::to_string(rays.size()) + " rays, but " + name_a +
                                        " holds " + std::to_string(a.size()) + " hits");
  }
  const HitComparison c = compare_hit_arrays(a, b, tolerance, show, rays);
  const bool pass = double(c.differ()) <= allow_percent / 100.0 * double(c.rays);
  JsonLine()
      .add("op", "compare")
      .add("kind", "hits")
      .add("rays", c.rays)
      .add("agree", c.agree())
      .add("agree_percent", c.agree_percent())
      .add("both_miss", c.both_miss)
      .add("same_prim", c.same_prim)
      .add("t_mismatch", c.t_mismatch)
      .add("only_a_hit", c.only_a_hit)
      .add("only_b_hit", c.only_b_hit)
      .add("other_prim", c.other_prim)
      .add("other_prim_same_t", c.other_prim_same_t)
      .add("max_t_error", c.max_t_error)
      .add("mean_t_error", c.mean_t_error)
      .add("tolerance", tolerance)
      .add("scale", rays.empty() ? "max(|t|,1)" : "max(|t|,|org|/|dir|)")
      .add("pass", pass)
      .print();
  for (size_t i : c.first_differences)
    JsonLine().add("op", "difference").add("ray", i).add_raw("a", hit_json(a[i])).add_raw("b", hit_json(b[i])).print();
  return pass ? 0 : kExitDiffer;
}

int compare_occl_files(const std::string& name_a, std::string_view bytes_a, const std::string& name_b,
                       std::string_view bytes_b, double allow_percent, size_t show) {
  const std::vector<uint8_t> a = parse_occlusion(bytes_a, name_a);
  const std::vector<uint8_t> b = parse_occlusion(bytes_b, name_b);
  if (a.size() != b.size())
    throw FileError(name_b, 0, "holds " + std::to_string(b.size()) + " answers, but " + name_a + " holds " +
                                   std::to_string(a.size()) + ": not the same rays");
  const OcclusionComparison c = compare_occlusion_arrays(a, b, show);
  const bool pass = double(c.differ()) <= allow_percent / 100.0 * double(c.rays);
  JsonLine()
      .add("op", "compare")
      .add("kind", "occl")
      .add("rays", c.rays)
      .add("agree", c.agree())
      .add("agree_percent", c.agree_percent())
      .add("both_blocked", c.both_blocked)
      .add("both_free", c.both_free)
      .add("only_a", c.only_a)
      .add("only_b", c.only_b)
      .add("pass", pass)
      .print();
  for (size_t i : c.first_differences)
    JsonLine().add("op", "difference").add("ray", i).add("a", int(a[i])).add("b", int(b[i])).print();
  return pass ? 0 : kExitDiffer;
}

}  // namespace

int run_compare(std::span<const std::string_view> args) {
  const Options options("compare", args, {.with_value = {"tolerance", "allow", "show", "rays"}, .flags = {}, .positional = 2});
  const double tolerance = options.get_number("tolerance", 1e-4, 0.0, 1e30);
  const double allow_percent = options.get_number("allow", 0.0, 0.0, 100.0);
  const size_t show = options.get_count("show", 10, 0, 1000000);
  const std::string& name_a = options.positional()[0];
  const std::string& name_b = options.positional()[1];
  const std::string bytes_a = read_file(name_a);
  const std::string bytes_b = read_file(name_b);
  const auto kind_a = replay_file_kind(bytes_a);
  const auto kind_b = replay_file_kind(bytes_b);
  auto check = [](const std::string& name, std::optional<ReplayFile> kind) {
    if (!kind) throw FileError(name, 0, "not a .hits or .occl file (unknown magic)");
    if (*kind == ReplayFile::rays) throw FileError(name, 0, "is a .rays file; compare takes two .hits or two .occl files");
  };
  check(name_a, kind_a);
  check(name_b, kind_b);
  if (*kind_a != *kind_b)
    throw FileError(name_b, 0, "is not the same kind of file as " + name_a + " (one .hits, one .occl)");
  if (*kind_a == ReplayFile::hits)
    return compare_hits_files(name_a, bytes_a, name_b, bytes_b, options.get("rays", ""), tolerance,
                              allow_percent, show);
  return compare_occl_files(name_a, bytes_a, name_b, bytes_b, allow_percent, show);
}

}  // namespace rtk::cli
