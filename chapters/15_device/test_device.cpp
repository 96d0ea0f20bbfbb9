// Chapter 15's tests: commit semantics, reference counting, parameter errors, and a scene
// built through handles rendering exactly the image of the same RenderScene built directly.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <thread>
#include <string>
#include <vector>

#include "14_pathtracer/render.h"
#include "15_device/device.h"
#include "15_device/sphere_mesh.h"
#include "14_pathtracer/accel_kernels.h"

namespace {

using rtk::Device;
using rtk::Handle;
using rtk::Vec3f;

// A floor quad under a small box-less triangle "roof", lit by a quad light: small enough for
// the sanitizer builds, with shadows so that geometry changes show in the image.
const std::vector<float> kFloor = {-2, 0, -2, 2, 0, -2, 2, 0, 2, -2, 0, 2};
const std::vector<int> kFloorIdx = {0, 2, 1, 0, 3, 2};
const std::vector<float> kBlocker = {-0.5f, 1, -0.5f, 0.5f, 1, -0.5f, 0, 1, 0.5f};
const std::vector<int> kBlockerIdx = {0, 1, 2};

struct Built {
  Handle floor_material, floor, blocker, light, scene, camera, renderer, framebuffer;
};

Built build(Device& d) {
  Built b;
  b.floor_material = d.new_material("Matte");
  d.set(b.floor_material, "reflectance", Vec3f{0.7f, 0.6f, 0.5f});
  d.commit(b.floor_material);
  b.floor = d.new_shape("trianglemesh");
  d.set(b.floor, "positions", kFloor);
  d.set(b.floor, "indices", kFloorIdx);
  d.set(b.floor, "material", b.floor_material);
  d.commit(b.floor);
  b.blocker = d.new_shape("trianglemesh");
  d.set(b.blocker, "positions", kBlocker);
  d.set(b.blocker, "indices", kBlockerIdx);
  d.commit(b.blocker);  // no material: the default grey Matte
  b.light = d.new_light("quad");
  d.set(b.light, "P", Vec3f{-0.5f, 2.5f, -0.5f});
  d.set(b.light, "U", Vec3f{1, 0, 0});
  d.set(b.light, "V", Vec3f{0, 0, 1});
  d.set(b.light, "L", Vec3f{8, 8, 8});
  d.commit(b.light);
  b.scene = d.new_scene();
  d.set(b.scene, "shapes", std::vector<Handle>{b.floor, b.blocker});
  d.set(b.scene, "lights", std::vector<Handle>{b.light});
  d.commit(b.scene);
  b.camera = d.new_camera("pinhole");
  d.set(b.camera, "position", Vec3f{0, 4, -4});
  d.set(b.camera, "lookAt", Vec3f{0, 0, 0});
  d.set(b.camera, "fov", 50.0);
  d.commit(b.camera);
  b.renderer = d.new_renderer("pathtracer");
  d.set(b.renderer, "spp", 2);
  d.set(b.renderer, "maxDepth", 3);
  d.set(b.renderer, "threads", 2);
  d.commit(b.renderer);
  b.framebuffer = d.new_framebuffer();
  d.set(b.framebuffer, "width", 24);
  d.set(b.framebuffer, "height", 20);
  d.commit(b.framebuffer);
  return b;
}

rtk::Image render(Device& d, const Built& b) {
  d.render_frame(b.renderer, b.camera, b.scene, b.framebuffer);
  return d.read_image(b.framebuffer);
}

bool same(const rtk::Image& a, const rtk::Image& b) {
  if (a.width != b.width || a.height != b.height) return false;
  for (size_t i = 0; i < a.pixels.size(); ++i)
    if (a.pixels[i].r != b.pixels[i].r || a.pixels[i].g != b.pixels[i].g || a.pixels[i].b != b.pixels[i].b)
      return false;
  return true;
}

float sum(const rtk::Image& a) {
  float s = 0;
  for (const auto& c : a.pixels) s += c.r + c.g + c.b;
  return s;
}

// The scene of build(), by hand: shapes in order, one material per distinct material, the quad
// light's triangles last (what a scene commit merges them into).
rtk::RenderScene by_hand() {
  rtk::RenderScene s;
  rtk::ParameterList floor_params;
  floor_params.set("reflectance", rtk::Color(0.7f, 0.6f, 0.5f));
  const uint32_t m0 = s.add_material(rtk::make_material("Matte", floor_params));
  const uint32_t m1 = s.add_material(rtk::Material{});
  auto add = [&](const std::vector<float>& p, const std::vector<int>& idx, uint32_t m) {
    const auto first = static_cast<uint32_t>(s.mesh.vertices.size());
    for (size_t i = 0; i < p.size(); i += 3) s.mesh.vertices.push_back({p[i], p[i + 1], p[i + 2]});
    for (size_t i = 0; i < idx.size(); i += 3) {
      s.mesh.triangles.push_back({first + idx[i], first + idx[i + 1], first + idx[i + 2]});
      s.triangle_material.push_back(m);
      s.triangle_light.push_back(rtk::kNoLight);
    }
  };
  add(kFloor, kFloorIdx, m0);
  add(kBlocker, kBlockerIdx, m1);
  rtk::Material light_material;
  light_material.prototype = rtk::Lambertian{rtk::Color(0.0f)};
  light_material.emission = rtk::Color(8.0f);
  const uint32_t ml = s.add_material(light_material);
  for (auto& t : rtk::make_quad_light({-0.5f, 2.5f, -0.5f}, {1, 0, 0}, {0, 0, 1}, rtk::Color(8.0f)))
    s.add_triangle_light(t, ml);
  s.camera.position = {0, 4, -4};
  s.camera.look_at = {0, 0, 0};
  s.camera.fov_degrees = 50;
  return s;
}

// What the renderer object of build() says, as chapter 14's options for a 24 x 20 image.
rtk::RenderOptions built_options() {
  rtk::RenderOptions options;
  options.width = 24;
  options.height = 20;
  options.spp = 2;
  options.max_depth = 3;
  options.threads = 2;
  return options;
}

// The message of the exception `f` throws (empty if none).
template <class F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("ch15: a scene built through handles renders the image of the same RenderScene built directly") {
  Device d;
  const Built b = build(d);
  const rtk::Image via_device = render(d, b);
  CHECK(via_device.width == 24);
  CHECK(via_device.height == 20);
  CHECK(sum(via_device) > 0.0f);

  const rtk::RenderScene s = by_hand();
  const rtk::AccelKernels kernels(s, rtk::AccelConfig{});
  rtk::Framebuffer fb(24, 20);
  rtk::Renderer(s, kernels, built_options()).render(fb);
  CHECK(same(via_device, fb.resolve()));
}

TEST_CASE("ch15: an imported scene renders chapter 14's image, frame by frame or sample by sample") {
  // rtk render and the viewer hand lib/scene's RenderScene to the device: the frame must be
  // chapter 14's image of that scene, bit for bit, and progressive passes must add up to it.
  Device d;
  Built b = build(d);
  b.scene = d.import_scene(by_hand());
  CHECK(error_of([&] { render(d, b); }).find("not committed") != std::string::npos);
  d.commit(b.scene);
  const rtk::Image frame = render(d, b);
  const rtk::RenderScene s = by_hand();
  const rtk::AccelKernels kernels(s, rtk::AccelConfig{});
  rtk::Framebuffer fb(24, 20);
  const rtk::RenderStats direct = rtk::Renderer(s, kernels, built_options()).render(fb);
  CHECK(same(frame, fb.resolve()));

  // Samples 0 and 1 in two passes of one: the same image, and the statistics count the same work.
  d.commit(b.framebuffer);  // a new, empty buffer
  const rtk::RenderStats first = d.render_samples(b.renderer, b.camera, b.scene, b.framebuffer, 0, 1);
  const rtk::RenderStats second = d.render_samples(b.renderer, b.camera, b.scene, b.framebuffer, 1, 1);
  CHECK(same(d.read_image(b.framebuffer), frame));
  CHECK(first.samples + second.samples == direct.samples);
  CHECK(first.rays + second.rays == direct.rays);

  // It takes the build parameters of a scene, and only those: its content is given.
  d.set(b.scene, "accel", "bvh4");
  d.set(b.scene, "tri", "triangle4v.watertight");
  d.commit(b.scene);
  CHECK(d.kernels_summary(b.scene).find("triangle4v.watertight") != std::string::npos);
  d.set(b.scene, "shapes", std::vector<Handle>{b.floor});
  CHECK(error_of([&] { d.commit(b.scene); }).find("parameter 'shapes': an imported scene has its content already") !=
        std::string::npos);
}

TEST_CASE("ch15: a device builds its scenes' kernels with the factory it was given") {
  // rtk render -kernels embree gives the device a factory that builds Embree's kernels; here a
  // factory that counts its calls and answers with RTK's kernels under another name.
  int calls = 0;
  Device d({}, [&](const rtk::RenderScene& scene, const rtk::AccelConfig& config) {
    ++calls;
    rtk::RenderKernels k = rtk::make_rtk_kernels(scene, config);
    k.summary = "counted: " + k.summary;
    return k;
  });
  const Built b = build(d);
  CHECK(calls == 1);
  CHECK(d.kernels_summary(b.scene).starts_with("counted: accel "));
  // The kernels of a committed version outlive a new commit of the scene for whoever holds them.
  const std::shared_ptr<const rtk::RayKernels> held = d.kernels(b.scene);
  d.commit(b.scene);
  CHECK(calls == 2);
  CHECK(d.kernels(b.scene) != held);
  std::vector<rtk::Ray> rays(1);
  rays[0].org = {0, 2, 0};  // below the quad light at y = 2.5
  rays[0].dir = {0, -1, 0};
  std::vector<rtk::Hit> hits(1);
  held->tracer().intersect(rays, hits);
  CHECK(hits[0].found());
  CHECK(hits[0].t == doctest::Approx(1.0f));  // the blocker at y = 1
}


TEST_CASE("ch15: a commit leaves the versions others hold unchanged") {
  Device d;
  Built b = build(d);
  const rtk::Image before = render(d, b);

  // Buffered parameters change nothing until commit.
  d.set(b.blocker, "positions", std::vector<float>{-1.5f, 1, -1.5f, 1.5f, 1, -1.5f, 0, 1, 1.5f});
  d.set(b.camera, "fov", 20.0);
  CHECK(same(render(d, b), before));

  // A re-committed shape does not change the scene that was committed with its old version.
  d.commit(b.blocker);
  CHECK(same(render(d, b), before));

  // Re-committing the scene takes the shape's new version (a bigger blocker).
  d.commit(b.scene);
  const rtk::Image bigger = render(d, b);
  CHECK_FALSE(same(bigger, before));

  // The camera's new version shows at its commit.
  d.commit(b.camera);
  CHECK_FALSE(same(render(d, b), bigger));

  // A failed commit keeps the previous version.
  d.set(b.blocker, "indices", std::vector<int>{0, 1, 7});
  CHECK_THROWS_AS(d.commit(b.blocker), std::invalid_argument);
  d.commit(b.scene);  // still the valid blocker
  CHECK(d.committed(b.scene));
}

TEST_CASE("ch15: frames rendered while another thread commits see one whole version or the other") {
  Device d;
  Built b = build(d);
  const std::vector<float> small = kBlocker;
  const std::vector<float> big = {-1.5f, 1, -1.5f, 1.5f, 1, -1.5f, 0, 1, 1.5f};
  const rtk::Image old_image = render(d, b);
  d.set(b.blocker, "positions", big);
  d.commit(b.blocker);
  d.commit(b.scene);
  const rtk::Image new_image = render(d, b);
  REQUIRE_FALSE(same(old_image, new_image));

  // The viewer: frames into its own framebuffer, never waiting for the editor.
  const Handle viewer_fb = d.new_framebuffer();
  d.set(viewer_fb, "width", 24);
  d.set(viewer_fb, "height", 20);
  d.commit(viewer_fb);
  int frames = 0, torn = 0;
  std::thread viewer([&] {
    for (int i = 0; i < 12; ++i) {
      d.render_frame(b.renderer, b.camera, b.scene, viewer_fb);
      const rtk::Image image = d.read_image(viewer_fb);
      ++frames;
      if (!same(image, old_image) && !same(image, new_image)) ++torn;
    }
  });
  // The editor: switches the blocker back and forth, committing shape then scene.
  for (int i = 0; i < 12; ++i) {
    d.set(b.blocker, "positions", i % 2 ? big : small);
    d.commit(b.blocker);
    d.commit(b.scene);
  }
  viewer.join();
  CHECK(frames == 12);
  CHECK(torn == 0);
}

TEST_CASE("ch15: objects and versions are freed with their last user") {
  Device d;
  CHECK(d.counts().objects == 0);
  {
    Built b = build(d);
    CHECK(d.counts().objects == 8);
    CHECK(d.counts().versions == 8);
    // Handles count: the floor is held by the test and by the scene's "shapes" parameter.
    CHECK(b.floor.use_count() == 2);
    Handle copy = b.floor;
    CHECK(b.floor.use_count() == 3);

    // Dropping every handle of the shapes leaves their objects alive in the scene's
    // parameters; dropping the scene's parameters frees the objects but not the versions the
    // committed scene holds.
    copy = Handle();
    b.floor = Handle();
    b.blocker = Handle();
    CHECK(d.counts().objects == 8);
    d.set(b.scene, "shapes", std::vector<Handle>{});
    CHECK(d.counts().objects == 6);
    CHECK(d.counts().versions == 8);
    CHECK(sum(render(d, b)) > 0.0f);  // the committed scene still renders its shapes

    // A failed commit of the scene keeps the old version...
    d.set(b.scene, "accel", "bvh3");
    CHECK_THROWS_AS(d.commit(b.scene), std::invalid_argument);
    CHECK(d.counts().versions == 8);
    d.unset(b.scene, "accel");
    // ...and a committed replacement frees it, with the shape versions only it held.
    const Handle sphere = d.new_shape("sphere");
    d.set(sphere, "numTheta", 4);
    d.set(sphere, "numPhi", 6);
    d.commit(sphere);
    d.set(b.scene, "shapes", std::vector<Handle>{sphere});
    d.commit(b.scene);
    CHECK(d.counts().objects == 7);
    CHECK(d.counts().versions == 7);  // 8 - 2 shapes - old scene + new scene + sphere
  }
  CHECK(d.counts().objects == 0);
  CHECK(d.counts().versions == 0);
}

TEST_CASE("ch15: parameter errors name the object and the parameter") {
  Device d;
  CHECK(error_of([&] { d.new_shape("cube"); }).find("unknown shape type 'cube'") != std::string::npos);

  const Handle mesh = d.new_shape("trianglemesh");
  // Required parameters.
  CHECK(error_of([&] { d.commit(mesh); }).find("'trianglemesh': parameter 'positions': required") != std::string::npos);
  d.set(mesh, "positions", std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1});
  d.set(mesh, "indices", std::vector<int>{0, 1, 2});
  CHECK(error_of([&] { d.commit(mesh); }).find("parameter 'positions': length 8 is not a multiple of 3") != std::string::npos);
  d.set(mesh, "positions", std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0});
  d.set(mesh, "indices", std::vector<int>{0, 1, 3});
  CHECK(error_of([&] { d.commit(mesh); }).find("parameter 'indices': index 3 at position 2 is out of range") != std::string::npos);
  d.set(mesh, "indices", std::vector<int>{0, 1, 2});
  // Wrong types, unknown names, NaN.
  d.set(mesh, "normals", 1.0);
  CHECK(error_of([&] { d.commit(mesh); }).find("parameter 'normals': expected a float array, got a float") != std::string::npos);
  d.unset(mesh, "normals");
  d.set(mesh, "colour", Vec3f{1, 0, 0});
  CHECK(error_of([&] { d.commit(mesh); }).find("parameter 'colour': unknown parameter") != std::string::npos);
  d.unset(mesh, "colour");
  d.set(mesh, "positions", std::vector<float>{0, 0, 0, 1, 0, 0, 0, std::numeric_limits<float>::quiet_NaN(), 0});
  CHECK(error_of([&] { d.commit(mesh); }).find("element 7 is not finite") != std::string::npos);
  d.set(mesh, "positions", std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0});
  // A handle of a material never committed.
  const Handle material = d.new_material("Plastic");
  d.set(mesh, "material", material);
  CHECK(error_of([&] { d.commit(mesh); }).find("parameter 'material': material #") != std::string::npos);
  CHECK(error_of([&] { d.commit(mesh); }).find("was never committed") != std::string::npos);
  d.commit(material);
  d.commit(mesh);
  CHECK(d.committed(mesh));

  // References that could make a cycle, or that cross devices, are refused at set().
  const Handle scene = d.new_scene();
  CHECK(error_of([&] { d.set(scene, "shapes", scene); }).find("a scene cannot refer to a scene") != std::string::npos);
  CHECK(error_of([&] { d.set(mesh, "material", mesh); }).find("a shape cannot refer to a shape") != std::string::npos);
  Device other;
  CHECK(error_of([&] { other.commit(mesh); }).find("belongs to another device") != std::string::npos);
  // A handle of the wrong kind in a list.
  d.set(scene, "lights", std::vector<Handle>{mesh});
  d.set(scene, "shapes", mesh);
  CHECK(error_of([&] { d.commit(scene); }).find("parameter 'lights': expected a light, got shape #") != std::string::npos);

  // Values out of range.
  const Handle camera = d.new_camera("pinhole");
  d.set(camera, "fov", 180.0);
  CHECK(error_of([&] { d.commit(camera); }).find("camera #") != std::string::npos);
  d.set(camera, "fov", 45.0);
  d.set(camera, "radius", 0.1);  // a pinhole has no lens
  CHECK(error_of([&] { d.commit(camera); }).find("parameter 'radius': unknown parameter") != std::string::npos);
  const Handle fb = d.new_framebuffer();
  d.set(fb, "width", 0);
  CHECK(error_of([&] { d.commit(fb); }).find("parameter 'width': must be in [1, 32768]") != std::string::npos);
  const Handle renderer = d.new_renderer("pathtracer");
  d.set(renderer, "sampler", "nonsense");
  CHECK(error_of([&] { d.commit(renderer); }).find("parameter 'sampler'") != std::string::npos);

  // Rendering needs committed objects of the right kinds.
  CHECK(error_of([&] { d.render_frame(renderer, camera, scene, fb); }).find("not committed") != std::string::npos);
  CHECK(error_of([&] { d.render_frame(camera, camera, scene, fb); }).find("the renderer argument is a camera") != std::string::npos);
  CHECK(error_of([&] { d.commit(Handle()); }).find("null handle") != std::string::npos);
}

TEST_CASE("ch15: materials warn as the scene files do, and spheres follow Embree's tessellation") {
  std::vector<std::string> warnings;
  Device d([&](const std::string& w) { warnings.push_back(w); });
  const Handle m = d.new_material("Velour");
  d.set(m, "softness", 0.5);
  d.commit(m);
  REQUIRE(warnings.size() >= 1);
  CHECK(warnings[0].find("material #1 'Velour'") != std::string::npos);

  const rtk::SphereMesh s = rtk::tessellate_sphere({1, 2, 3}, 2.0f, 5, 7);
  CHECK(s.vertices.size() == 6u * 7u);
  CHECK(s.triangles.size() == 2u * 7u * 4u);
  for (size_t i = 0; i < s.vertices.size(); ++i) {
    const Vec3f d = s.vertices[i] - Vec3f{1, 2, 3};
    CHECK(std::abs(std::sqrt(dot(d, d)) - 2.0f) < 1e-5f);
  }
  // Every triangle faces outward, as its vertex normals do (a glass sphere wound the other way
  // would refract as if its inside were its outside).
  for (const auto& t : s.triangles) {
    const Vec3f a = s.vertices[t[0]], b = s.vertices[t[1]], c = s.vertices[t[2]];
    const Vec3f ng = cross(b - a, c - a);
    CHECK(dot(ng, (a + b + c) * (1.0f / 3.0f) - Vec3f{1, 2, 3}) > 0.0f);
    CHECK(dot(ng, s.normals[t[0]]) > 0.0f);
  }
  CHECK_THROWS_AS(rtk::tessellate_sphere({0, 0, 0}, -1.0f, 5, 7), std::invalid_argument);
  CHECK_THROWS_AS(rtk::tessellate_sphere({0, 0, 0}, 1.0f, 1, 7), std::invalid_argument);
}
