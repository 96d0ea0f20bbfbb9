// A program on the device API: a Cornell-like box with a glass sphere under a quad light,
// made through handles (no scene file), committed, rendered, written to the file named on the
// command line. It then moves the sphere and renders again while the first scene version is
// still valid, which is the point of commit. Exit status 0 when both images were written and
// are not black, 1 otherwise (so that a test can run it).
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "15_device/device.h"

namespace {

// Adds an axis-aligned quad (two triangles) from its four corners, given counter-clockwise as
// seen from the side that should face the light.
rtk::Handle quad(rtk::Device& d, const std::vector<float>& corners, const rtk::Handle& material) {
  rtk::Handle shape = d.new_shape("trianglemesh");
  d.set(shape, "positions", corners);
  d.set(shape, "indices", std::vector<int>{0, 1, 2, 0, 2, 3});
  d.set(shape, "material", material);
  d.commit(shape);
  return shape;
}

rtk::Handle matte(rtk::Device& d, rtk::Vec3f colour) {
  rtk::Handle m = d.new_material("Matte");
  d.set(m, "reflectance", colour);
  d.commit(m);
  return m;
}

double mean(const rtk::Image& image) {
  double sum = 0;
  for (const rtk::Color& c : image.pixels) sum += (c.r + c.g + c.b) / 3.0;
  return image.pixels.empty() ? 0 : sum / image.pixels.size();
}

}  // namespace

int main(int argc, char** argv) {
  const std::string out = argc > 1 ? argv[1] : "device.png";
  try {
    rtk::Device d([](const std::string& w) { std::fprintf(stderr, "warning: %s\n", w.c_str()); });

    // Materials and shapes: a white floor, back wall and ceiling, red and green side walls.
    const rtk::Handle white = matte(d, {0.75f, 0.75f, 0.75f});
    const rtk::Handle red = matte(d, {0.65f, 0.05f, 0.05f});
    const rtk::Handle green = matte(d, {0.12f, 0.45f, 0.15f});
    const std::vector<rtk::Handle> walls = {
        quad(d, {0, 0, 0, 0, 0, 1, 1, 0, 1, 1, 0, 0}, white),  // floor
        quad(d, {0, 1, 0, 1, 1, 0, 1, 1, 1, 0, 1, 1}, white),  // ceiling
        quad(d, {0, 0, 1, 0, 1, 1, 1, 1, 1, 1, 0, 1}, white),  // back
        quad(d, {0, 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1}, red),    // left
        quad(d, {1, 0, 0, 1, 0, 1, 1, 1, 1, 1, 1, 0}, green),  // right
    };
    const rtk::Handle glass = d.new_material("Dielectric");
    d.set(glass, "etaInside", 1.5);
    d.commit(glass);
    const rtk::Handle sphere = d.new_shape("sphere");
    d.set(sphere, "center", rtk::Vec3f{0.35f, 0.22f, 0.55f});
    d.set(sphere, "radius", 0.22);
    d.set(sphere, "material", glass);
    d.commit(sphere);

    // A quad light just under the ceiling, facing down.
    const rtk::Handle lamp = d.new_light("quad");
    d.set(lamp, "P", rtk::Vec3f{0.4f, 0.999f, 0.4f});
    d.set(lamp, "U", rtk::Vec3f{0.2f, 0, 0});
    d.set(lamp, "V", rtk::Vec3f{0, 0, 0.2f});
    d.set(lamp, "L", rtk::Vec3f{12, 12, 12});
    d.commit(lamp);

    std::vector<rtk::Handle> shapes = walls;
    shapes.push_back(sphere);
    const rtk::Handle scene = d.new_scene();
    d.set(scene, "shapes", shapes);
    d.set(scene, "lights", std::vector<rtk::Handle>{lamp});
    d.commit(scene);

    const rtk::Handle camera = d.new_camera("pinhole");
    d.set(camera, "position", rtk::Vec3f{0.5f, 0.5f, -1.4f});
    d.set(camera, "lookAt", rtk::Vec3f{0.5f, 0.5f, 0.5f});
    d.set(camera, "fov", 40.0);
    d.commit(camera);
    const rtk::Handle renderer = d.new_renderer("pathtracer");
    d.set(renderer, "spp", 16);
    d.set(renderer, "maxDepth", 6);
    d.commit(renderer);
    const rtk::Handle framebuffer = d.new_framebuffer();
    d.set(framebuffer, "width", 128);
    d.set(framebuffer, "height", 128);
    d.commit(framebuffer);

    d.render_frame(renderer, camera, scene, framebuffer);
    const double first = mean(d.read_image(framebuffer));
    d.write_image(framebuffer, out, rtk::ToneMap{2.2f});

    // Move the sphere: a new shape version, then a new scene version. The first scene version
    // stayed valid the whole time; a viewer could have kept rendering it.
    d.set(sphere, "center", rtk::Vec3f{0.65f, 0.22f, 0.45f});
    d.commit(sphere);
    d.commit(scene);
    d.render_frame(renderer, camera, scene, framebuffer);
    const double second = mean(d.read_image(framebuffer));

    std::printf("wrote %s (128 x 128, 16 spp): mean radiance %.4f, after moving the sphere %.4f\n",
                out.c_str(), first, second);
    return first > 0 && second > 0 ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
}
