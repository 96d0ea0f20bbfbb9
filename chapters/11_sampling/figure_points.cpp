// Draws the picture of chapter 11: 256 samples of one pixel from each sampler, on a 16 x 16 grid.
// Run: build/chapters/11_sampling/ch11_figure chapters/11_sampling/ch11_points.png
#include <stb/stb_image_write.h>

#include <cstdio>
#include <vector>

#include "11_sampling/sampler.h"

using namespace rtk;

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s output.png\n", argv[0]);
    return 2;
  }
  constexpr int kPanel = 256, kGap = 16, kWidth = 2 * kPanel + 3 * kGap,
                kHeight = kPanel + 2 * kGap;
  std::vector<unsigned char> rgb(kWidth * kHeight * 3, 255);
  auto plot = [&](int x, int y, unsigned char r, unsigned char g, unsigned char b) {
    if (x < 0 || y < 0 || x >= kWidth || y >= kHeight) return;
    unsigned char* p = &rgb[(y * kWidth + x) * 3];
    p[0] = r, p[1] = g, p[2] = b;
  };
  const SamplerType types[2] = {SamplerType::independent, SamplerType::sobol};
  for (int panel = 0; panel < 2; ++panel) {
    const int x0 = kGap + panel * (kPanel + kGap), y0 = kGap;
    // The 16 x 16 strata: a (0,8,2)-net puts one point in each (and in every other shape of
    // elementary interval of area 1/256).
    for (int i = 0; i <= kPanel; i += kPanel / 16)
      for (int t = 0; t <= kPanel; ++t) {
        plot(x0 + i, y0 + t, 200, 200, 200);
        plot(x0 + t, y0 + i, 200, 200, 200);
      }
    Sampler sampler(types[panel], 1);
    for (uint32_t s = 0; s < 256; ++s) {
      sampler.start_pixel_sample(0, 0, s);
      const Vec2f u = sampler.get_2d();
      const int px = x0 + static_cast<int>(u.x * kPanel),
                py = y0 + static_cast<int>((1 - u.y) * kPanel);
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
          plot(px + dx, py + dy, panel == 0 ? 200 : 20, 30, panel == 0 ? 30 : 200);
    }
  }
  if (!stbi_write_png(argv[1], kWidth, kHeight, 3, rgb.data(), kWidth * 3)) {
    std::fprintf(stderr, "cannot write %s\n", argv[1]);
    return 1;
  }
  return 0;
}
