#include "02_bvh2/bench_support.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string_view>

#include "testing/scenes.h"

namespace rtk::bench {

std::vector<SceneSource> bench_scenes() {
  std::vector<SceneSource> scenes = {{"sphere_130k", ""}, {"terrain_130k", ""}, {"soup_100k", ""}};
  const char* root = std::getenv("RTK_SCENES");
  if (!root) return scenes;
  const std::pair<const char*, const char*> real[] = {
      {"teapot", "teapot_newell/teapot.obj"},
      {"bunny", "bunny_stanford_full/stanford-bunny.obj"},
      {"sponza", "sponza_dabrovic/sponza.obj"},
      {"buddha", "happy_buddha_100k/buddha.obj"},
  };
  for (const auto& [name, file] : real) {
    const std::filesystem::path path = std::filesystem::path(root) / file;
    if (std::filesystem::exists(path)) scenes.push_back({name, path.string()});
  }
  return scenes;
}

const TriangleMesh& scene_mesh(const SceneSource& source) {
  static std::map<std::string, TriangleMesh> cache;
  auto it = cache.find(source.name);
  if (it != cache.end()) return it->second;
  TriangleMesh mesh;
  if (!source.path.empty()) mesh = read_obj_vf(source.path);
  else if (source.name == "sphere_130k") mesh = test::make_sphere(256, 256);
  else if (source.name == "terrain_130k") mesh = test::make_terrain(256, 7);
  else if (source.name == "soup_100k") mesh = test::make_random_soup(100000, 7, 0.02f);
  else throw std::invalid_argument("unknown scene " + source.name);
  return cache.emplace(source.name, std::move(mesh)).first->second;
}

namespace {

// Parses one face corner, "i", "i/t", "i//n" or "i/t/n": the vertex index, 0-based.
uint32_t parse_corner(std::string_view token, size_t vertex_count, const std::string& where) {
  const std::string_view index = token.substr(0, token.find('/'));
  long value = 0;
  const auto [end, ec] = std::from_chars(index.data(), index.data() + index.size(), value);
  if (ec != std::errc() || end != index.data() + index.size() || value == 0)
    throw std::runtime_error(where + ": bad vertex index '" + std::string(token) + "'");
  const long resolved = value > 0 ? value - 1 : long(vertex_count) + value;
  if (resolved < 0 || resolved >= long(vertex_count))
    throw std::runtime_error(where + ": vertex index " + std::to_string(value) + " out of range");
  return uint32_t(resolved);
}

}  // namespace

TriangleMesh read_obj_vf(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open");
  TriangleMesh mesh;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    const std::string where = path + ":" + std::to_string(number);
    std::vector<std::string_view> tokens;
    for (size_t i = 0; i < line.size();) {
      while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
      const size_t start = i;
      while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i]))) ++i;
      if (i > start) tokens.emplace_back(line.data() + start, i - start);
    }
    if (tokens.empty() || tokens[0].starts_with("#")) continue;
    if (tokens[0] == "v") {
      if (tokens.size() < 4) throw std::runtime_error(where + ": a vertex needs three coordinates");
      float xyz[3];
      for (int k = 0; k < 3; ++k) {
        const std::string_view t = tokens[size_t(k) + 1];
        const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), xyz[k]);
        if (ec != std::errc() || end != t.data() + t.size())
          throw std::runtime_error(where + ": bad number '" + std::string(t) + "'");
      }
      mesh.vertices.push_back({xyz[0], xyz[1], xyz[2]});
    } else if (tokens[0] == "f") {
      if (tokens.size() < 4) throw std::runtime_error(where + ": a face needs three vertices");
      const uint32_t first = parse_corner(tokens[1], mesh.vertices.size(), where);
      uint32_t previous = parse_corner(tokens[2], mesh.vertices.size(), where);
      for (size_t k = 3; k < tokens.size(); ++k) {
        const uint32_t next = parse_corner(tokens[k], mesh.vertices.size(), where);
        mesh.triangles.push_back({first, previous, next});
        previous = next;
      }
    }
  }
  return mesh;
}

std::vector<Ray> primary_rays(const TriangleMesh& mesh, int width, int height) {
  const Box3f box = mesh.bounds();
  const Vec3f center = box.center();
  const float radius = 0.5f * length(box.size());
  // Looking down on the scene from a corner, far enough to see all of it.
  const Vec3f eye = center + normalize(Vec3f{0.8f, 0.6f, 1.0f}) * (2.2f * radius);
  const Vec3f forward = normalize(center - eye);
  const Vec3f right = normalize(cross(forward, Vec3f{0, 1, 0}));
  const Vec3f up = cross(right, forward);
  const float half = std::tan(0.5f * 50.0f * std::numbers::pi_v<float> / 180.0f);
  std::vector<Ray> rays;
  rays.reserve(size_t(width) * size_t(height));
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const float sx = (2.0f * (float(x) + 0.5f) / float(width) - 1.0f) * half;
      const float sy = (1.0f - 2.0f * (float(y) + 0.5f) / float(height)) * half;
      Ray r;
      r.org = eye;
      r.dir = normalize(forward + right * sx + up * sy);
      rays.push_back(r);
    }
  return rays;
}

std::vector<Ray> diffuse_rays(const TriangleMesh& mesh, int count, uint64_t seed) {
  std::mt19937_64 random(seed);
  auto uniform = [&] { return float(double(random() >> 11) * 0x1.0p-53); };
  const float offset = 1e-4f * length(mesh.bounds().size());
  std::vector<Ray> rays;
  rays.reserve(size_t(count));
  while (rays.size() < size_t(count)) {
    const uint32_t prim = uint32_t(random() % mesh.size());
    const Vec3f p0 = mesh.vertex(prim, 0), p1 = mesh.vertex(prim, 1), p2 = mesh.vertex(prim, 2);
    const Vec3f n = cross(p1 - p0, p2 - p0);
    if (!(dot(n, n) > 0.0f)) continue;  // zero-area: no normal to scatter about
    Vec3f normal = normalize(n);
    if (random() & 1) normal = -normal;
    float a = uniform(), b = uniform();
    if (a + b > 1.0f) a = 1.0f - a, b = 1.0f - b;
    // A cosine-distributed direction in the frame of the normal.
    const Vec3f t = normalize(std::fabs(normal.x) > 0.5f ? cross(normal, Vec3f{0, 1, 0}) : cross(normal, Vec3f{1, 0, 0}));
    const Vec3f s = cross(normal, t);
    const float phi = 2.0f * std::numbers::pi_v<float> * uniform(), r2 = uniform();
    const float r = std::sqrt(r2);
    Ray ray;
    ray.org = p0 + (p1 - p0) * a + (p2 - p0) * b + normal * offset;
    ray.dir = t * (r * std::cos(phi)) + s * (r * std::sin(phi)) + normal * std::sqrt(1.0f - r2);
    rays.push_back(ray);
  }
  return rays;
}

}  // namespace rtk::bench
