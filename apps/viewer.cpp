// The interactive viewer: a GLFW window, the renderer's framebuffer as an OpenGL texture, and
// the guide's controls (section 2.3) mapped onto chapter 16's OrbitCamera. One thread drives
// the window; each frame it asks chapter 15's device (chapter 14's renderer, whose tiles run on
// oneTBB's workers) for one more sample per pixel, so the window answers the mouse between any
// two passes. A gesture commits a new camera version; the scene is committed once.
#include "viewer.h"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <thread>

#include "14_pathtracer/render.h"
#include "15_device/device.h"
#include "16_viewer/orbit_camera.h"
#include "device_objects.h"
#include "image/image_io.h"
#include "interrupt.h"
#include "options.h"
#include "render_kernels/choose_kernels.h"

namespace rtk::cli {

namespace {

constexpr float kHalfTurn = std::numbers::pi_v<float>;  // radians per window height dragged
constexpr int kPreviewScale = 4;  // pixels per preview pixel, on each axis, during a drag

const char* const kHowToRender =
    "render to a file instead with -o, e.g. rtk -c scene.ecs -spp 16 -o image.png";

// What the window's callbacks change and the render loop reads (one thread: no locks).
struct ViewerState {
  OrbitCamera camera;
  const RayKernels* kernels = nullptr;
  bool moved = true;    // the camera changed: restart accumulation
  bool refine = true;   // the guide's `r`: accumulate samples while the camera is still
  int drag_button = -1;  // the mouse button held down, or -1
  bool drag_roll = false;  // Alt was held when the drag began
  double last_x = 0, last_y = 0;
};

ViewerState& state_of(GLFWwindow* window) {
  return *static_cast<ViewerState*>(glfwGetWindowUserPointer(window));
}

// The film point under the cursor and the window's aspect, in window coordinates.
Vec2f film_point(GLFWwindow* window, double x, double y, float& aspect) {
  int w = 1, h = 1;
  glfwGetWindowSize(window, &w, &h);
  w = std::max(w, 1);
  h = std::max(h, 1);
  aspect = static_cast<float>(w) / static_cast<float>(h);
  return {static_cast<float>(x / w), static_cast<float>(y / h)};
}

// Mouse buttons: Ctrl+left picks the centre of interest, Ctrl+Shift+left the focal distance;
// any other press starts a drag (left rotates, Alt+left rolls, middle pans, right dollies).
void on_mouse_button(GLFWwindow* window, int button, int action, int mods) {
  ViewerState& s = state_of(window);
  double x = 0, y = 0;
  glfwGetCursorPos(window, &x, &y);
  if (action == GLFW_RELEASE) {
    if (button == s.drag_button) s.drag_button = -1;
    return;
  }
  if (button == GLFW_MOUSE_BUTTON_LEFT && (mods & GLFW_MOD_CONTROL)) {
    float aspect = 1;
    const Vec2f film = film_point(window, x, y, aspect);
    const std::optional<Vec3f> point = s.camera.pick(*s.kernels, film, aspect);
    if (!point) return;  // clicked the background: nothing to pick
    const bool changed = (mods & GLFW_MOD_SHIFT) ? s.camera.focus_on(*point) : s.camera.look_at(*point);
    s.moved = s.moved || changed;
    return;
  }
  s.drag_button = button;
  s.drag_roll = (mods & GLFW_MOD_ALT) != 0;
  s.last_x = x;
  s.last_y = y;
}

// A drag: the cursor's motion in window heights (widths for roll) becomes the gesture.
void on_cursor(GLFWwindow* window, double x, double y) {
  ViewerState& s = state_of(window);
  if (s.drag_button < 0) return;
  int w = 1, h = 1;
  glfwGetWindowSize(window, &w, &h);
  const float dx = static_cast<float>((x - s.last_x) / std::max(h, 1));
  const float dy = static_cast<float>((y - s.last_y) / std::max(h, 1));
  s.last_x = x;
  s.last_y = y;
  if (dx == 0 && dy == 0) return;
  // [ch16-drag]
  if (s.drag_button == GLFW_MOUSE_BUTTON_LEFT && s.drag_roll)
    s.camera.roll(dx * static_cast<float>(h) / static_cast<float>(std::max(w, 1)) * kHalfTurn);
  else if (s.drag_button == GLFW_MOUSE_BUTTON_LEFT)
    s.camera.rotate(dx * kHalfTurn, dy * kHalfTurn);
  else if (s.drag_button == GLFW_MOUSE_BUTTON_MIDDLE)
    s.camera.pan(dx, -dy);  // the window's y grows downward, the image's up does not
  else if (s.drag_button == GLFW_MOUSE_BUTTON_RIGHT)
    s.camera.dolly(-2.0f * dy);  // dragging up comes closer
  else
    return;
  // [ch16-drag]
  s.moved = true;
}

// Keys: `L` / Shift+L change the lens radius by one world unit, `c` prints the camera as .ecs
// options, `r` toggles progressive refinement, Escape or `q` closes the window.
void on_key(GLFWwindow* window, int key, int /*scancode*/, int action, int mods) {
  if (action != GLFW_PRESS && action != GLFW_REPEAT) return;
  ViewerState& s = state_of(window);
  switch (key) {
    case GLFW_KEY_L:
      s.camera.lens_radius = std::max(0.0f, s.camera.lens_radius + ((mods & GLFW_MOD_SHIFT) ? 1.0f : -1.0f));
      s.moved = true;
      break;
    case GLFW_KEY_C:
      if (action == GLFW_PRESS) {
        std::printf("%s\n", s.camera.to_ecs_options().c_str());
        std::fflush(stdout);
      }
      break;
    case GLFW_KEY_R:
      if (action == GLFW_PRESS) {
        s.refine = !s.refine;
        s.moved = true;
      }
      break;
    case GLFW_KEY_ESCAPE:
    case GLFW_KEY_Q:
      glfwSetWindowShouldClose(window, GLFW_TRUE);
      break;
    default:
      break;
  }
}

// GLFW reports errors through a callback; the last one goes into the exception we throw.
std::string g_glfw_error;
void on_glfw_error(int /*code*/, const char* description) { g_glfw_error = description ? description : "?"; }

// glfwInit and glfwTerminate, paired even when an exception leaves the viewer.
struct GlfwSession {
  GlfwSession() {
    glfwSetErrorCallback(on_glfw_error);
    if (!glfwInit())
      throw std::runtime_error("cannot open a window (GLFW: " + g_glfw_error + "); " + kHowToRender);
  }
  ~GlfwSession() { glfwTerminate(); }
  GlfwSession(const GlfwSession&) = delete;
  GlfwSession& operator=(const GlfwSession&) = delete;
};

// The tone-mapped image, 8 bits per channel, rows from the top.
void tonemap_rgb8(const Image& image, const ToneMap& tone, std::vector<uint8_t>& rgb) {
  rgb.resize(image.pixels.size() * 3);
  for (size_t i = 0; i < image.pixels.size(); ++i) {
    const Color& c = image.pixels[i];
    rgb[3 * i + 0] = tone.to_8bit(c.r);
    rgb[3 * i + 1] = tone.to_8bit(c.g);
    rgb[3 * i + 2] = tone.to_8bit(c.b);
  }
}

// The image as a texture over the whole viewport, with nearest filtering: texel for pixel at
// full resolution, blocks of pixels in preview. Row 0 of the texture is the image's top row,
// so the top of the quad takes t = 0.
void draw_texture(GLuint texture, int image_width, int image_height, int width, int height,
                  const std::vector<uint8_t>& rgb) {
  glViewport(0, 0, width, height);
  glBindTexture(GL_TEXTURE_2D, texture);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, image_width, image_height, 0, GL_RGB, GL_UNSIGNED_BYTE,
               rgb.data());
  glEnable(GL_TEXTURE_2D);
  glBegin(GL_QUADS);
  glTexCoord2f(0, 1); glVertex2f(-1, -1);
  glTexCoord2f(1, 1); glVertex2f(1, -1);
  glTexCoord2f(1, 0); glVertex2f(1, 1);
  glTexCoord2f(0, 0); glVertex2f(-1, 1);
  glEnd();
}

// The window's pixels as drawn (the back buffer, before it is shown), to an image file.
// 8-bit values v are stored as v / 255 and written without gamma, so the file holds v.
void save_screenshot(const std::string& path, int width, int height) {
  std::vector<uint8_t> rgb(static_cast<size_t>(width) * height * 3);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadBuffer(GL_BACK);
  glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, rgb.data());
  Image image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const uint8_t* p = &rgb[(static_cast<size_t>(height - 1 - y) * width + x) * 3];  // GL rows go up
      image.at(x, y) = Color(p[0] / 255.0f, p[1] / 255.0f, p[2] / 255.0f);
    }
  write_image(path, image, ToneMap{});
  std::printf("wrote %s\n", path.c_str());
}

int parse_frames(std::string_view value) {
  int n = 0;
  for (const char ch : value) {
    if (ch < '0' || ch > '9' || n > 100000000) throw UsageError("-frames: expected a count >= 1, got '" + std::string(value) + "'");
    n = n * 10 + (ch - '0');
  }
  if (n < 1) throw UsageError("-frames: expected a count >= 1, got '" + std::string(value) + "'");
  return n;
}

}  // namespace

std::vector<std::string_view> take_viewer_options(std::span<const std::string_view> args,
                                                  ViewerOptions& options) {
  std::vector<std::string_view> rest;
  for (size_t i = 0; i < args.size(); ++i) {
    std::string_view name = args[i];
    if (name.starts_with("--")) name.remove_prefix(1);
    if (name != "-frames" && name != "-screenshot") {
      rest.push_back(args[i]);
      continue;
    }
    if (i + 1 >= args.size()) throw UsageError(std::string(name) + ": missing value");
    const std::string_view value = args[++i];
    if (name == "-frames") {
      options.frames = parse_frames(value);
    } else {
      try {
        image_format_from_path(std::string(value));
      } catch (const std::exception& e) {
        throw UsageError(std::string("-screenshot: ") + e.what());
      }
      options.screenshot = std::string(value);
    }
  }
  if (!options.screenshot.empty() && options.frames == 0)
    throw UsageError("-screenshot needs -frames N (the screenshot is taken after frame N)");
  return rest;
}

int run_viewer(SceneScript& script, const ViewerOptions& viewer) {
  // Step 1: a display, checked before anything slow, with the way out in the message.
  const char* display = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  if ((display == nullptr || *display == 0) && (wayland == nullptr || *wayland == 0))
    throw std::runtime_error(std::string("no -o given, so the viewer would open a window, but there is "
                                         "no display (DISPLAY is not set); ") + kHowToRender);
  GlfwSession glfw;

  // Step 2: the device, the scene and the renderer, as `rtk render` makes them. The camera
  // and the framebuffer change while the window is open: new versions are committed then.
  RenderOptions options = script.options;
  options.progress = false;
  if (options.threads == 0) options.threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  Device device([](const std::string& w) { std::fprintf(stderr, "rtk view: warning: %s\n", w.c_str()); },
                kernel_factory(script.kernels));
  const Handle scene = at_given_place(script, {"-kernels", "-isa", "-accel", "-tri"}, [&] {
    return commit_scene(device, script, options.threads);
  });
  at_given_place(script, {"-vi", "-vp", "-vu", "-fov", "-radius", "-focaldistance"}, [&] {
    return commit_camera(device, script.scene.camera);
  });  // checked before the window opens
  const Handle renderer = commit_renderer(device, options);
  const std::shared_ptr<const RayKernels> kernels = device.kernels(scene);  // for picking
  std::printf("scene: %zu triangles; kernels: %s\n", script.scene.mesh.size(), device.kernels_summary(scene).c_str());
  std::fflush(stdout);

  // Step 3: the window, at the scene's image size; an OpenGL 2.1 context is all it needs
  // (and what Mesa's software rasteriser gives under Xvfb).
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 2);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 1);
  // -fullscreen: a window of the primary monitor's size on that monitor; the framebuffer
  // follows the window's size, as for any resize.
  GLFWmonitor* monitor = script.fullscreen ? glfwGetPrimaryMonitor() : nullptr;
  const GLFWvidmode* mode = monitor ? glfwGetVideoMode(monitor) : nullptr;
  GLFWwindow* window = mode ? glfwCreateWindow(mode->width, mode->height, "rtk viewer", monitor, nullptr)
                            : glfwCreateWindow(options.width, options.height, "rtk viewer", nullptr, nullptr);
  if (window == nullptr)
    throw std::runtime_error("cannot open a window (GLFW: " + g_glfw_error + "); " + kHowToRender);
  glfwMakeContextCurrent(window);
  glfwSwapInterval(0);  // the renderer, not the display, sets the pace
  ViewerState state;
  state.refine = script.refine;
  state.camera = OrbitCamera::from_params(script.scene.camera);
  state.kernels = kernels.get();
  glfwSetWindowUserPointer(window, &state);
  glfwSetMouseButtonCallback(window, on_mouse_button);
  glfwSetCursorPosCallback(window, on_cursor);
  glfwSetKeyCallback(window, on_key);
  GLuint texture = 0;
  glGenTextures(1, &texture);
  glBindTexture(GL_TEXTURE_2D, texture);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);

  // Step 4: the loop. A moved camera commits a new camera version, a resized window (or the
  // preview's smaller size) a new framebuffer, and either empties the framebuffer (committing
  // a framebuffer makes a new, empty buffer); a still camera adds sample `spp` of every pixel,
  // one pass per frame.
  Handle camera = device.new_camera("thinlens");  // a lens radius of 0 is a pinhole
  Handle framebuffer = device.new_framebuffer();
  int fb_width = 0, fb_height = 0;
  std::vector<uint8_t> rgb;
  uint32_t spp = 0;
  int frames = 0;
  double frame_seconds = 0, render_seconds = 0;
  using clock = std::chrono::steady_clock;
  // SIGINT or SIGTERM closes the window as its close button does: the frame under way stops at
  // its next tile, and the loop ends.
  const Interrupt interrupt;
  while (!glfwWindowShouldClose(window) && !interrupt.requested()) {
    const auto start = clock::now();
    glfwPollEvents();
    int width = 0, height = 0;
    glfwGetFramebufferSize(window, &width, &height);
    if (width < 1 || height < 1) {  // minimised: nothing to draw (waking now and then for a signal)
      glfwWaitEventsTimeout(0.1);
      continue;
    }
    // [ch16-frame]
    // While a gesture is under way the frame is rendered at a quarter of the resolution (a
    // sixteenth of the paths) and drawn enlarged: the camera follows the mouse, and full
    // resolution returns, and refines, as soon as it stops.
    const bool preview = state.drag_button >= 0;
    const int scale = preview ? kPreviewScale : 1;
    const int render_width = (width + scale - 1) / scale, render_height = (height + scale - 1) / scale;
    const bool resized = render_width != fb_width || render_height != fb_height;
    if (state.moved || resized) {
      commit_camera(device, camera, state.camera.to_params(static_cast<float>(render_width) / render_height));
    }
    if (state.moved || resized || !state.refine || spp == 0) {
      commit_framebuffer(device, framebuffer, render_width, render_height);  // a new, empty buffer
      fb_width = render_width, fb_height = render_height;
      spp = 0;
    }
    state.moved = false;
    const RenderStats stats =
        device.render_samples(renderer, camera, scene, framebuffer, spp, 1, interrupt.flag());
    ++spp;
    tonemap_rgb8(device.read_image(framebuffer), script.tone, rgb);
    // [ch16-frame]
    draw_texture(texture, render_width, render_height, width, height, rgb);
    ++frames;
    const bool last = viewer.frames > 0 && frames >= viewer.frames;
    if (last && !viewer.screenshot.empty()) save_screenshot(viewer.screenshot, width, height);
    glfwSwapBuffers(window);

    const double seconds = std::chrono::duration<double>(clock::now() - start).count();
    frame_seconds += seconds;
    render_seconds += stats.seconds;
    char title[160];
    std::snprintf(title, sizeof title, "rtk viewer: %.1f ms/frame, %u spp%s", seconds * 1e3, spp,
                  preview ? " (preview)" : state.refine ? "" : " (refinement off)");
    glfwSetWindowTitle(window, title);
    if (last) break;
  }
  if (frames > 0)
    std::printf("viewer: %d frames, %dx%d, mean frame time %.1f ms (rendering %.1f ms), %u spp at the end\n",
                frames, fb_width, fb_height, frame_seconds / frames * 1e3,
                render_seconds / frames * 1e3, spp);
  glDeleteTextures(1, &texture);
  glfwDestroyWindow(window);
  if (interrupt.requested()) {
    std::fprintf(stderr, "rtk view: interrupted by %s; the window is closed\n",
                 interrupt.signal_name());
    return interrupt.exit_status();
  }
  return 0;
}

}  // namespace rtk::cli
