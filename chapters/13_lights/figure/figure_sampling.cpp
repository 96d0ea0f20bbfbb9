// The picture of chapter 13: where two ways of choosing directions toward the HDR sky put 1,024
// of them, drawn on the map itself (longitude across, latitude down): uniformly over the upper
// hemisphere (left), and by the environment light's importance sampling (right), which finds the
// sun. It also prints how much each way's estimate of the irradiance on a floor facing up varies
// (relative standard deviation of 16-sample estimates over 2,000 trials). Run by
// `bash scripts/measure.sh ch13`:
//   build/chapters/13_lights/ch13_figure scenes/environment/sky.hdr OUTPUT.png
#include <stb/stb_image_write.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "11_sampling/rng.h"
#include "11_sampling/warp.h"
#include "13_lights/environment_light.h"

using namespace rtk;

namespace {

/// Irradiance on a surface facing up (world y) from one direction and its density.
float contribution(const EnvironmentLight& sky, Vec3f w, float pdf) {
  return pdf > 0 && w.y > 0 ? luminance(sky.le(w)) * w.y / pdf : 0.0f;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: %s SKY.hdr OUTPUT.png\n", argv[0]);
    return 2;
  }
  const EnvironmentLight sky(load_environment_image(argv[1]), Color(1, 1, 1));
  const LightQuery up{{0, 0, 0}, {0, 1, 0}};
  auto uniform = [](Vec2f u) {  // the upper hemisphere, z up in warp.h's frame, y up here
    const Vec3f l = sample_uniform_hemisphere(u);
    return Vec3f{l.x, l.z, l.y};
  };

  // The sun: the brightest direction of the map, on the grid the picture uses.
  Vec3f sun{0, 1, 0};
  float brightest = -1;
  for (int y = 0; y < 256; ++y)
    for (int x = 0; x < 512; ++x) {
      const Vec3f w = sky.direction({(static_cast<float>(x) + 0.5f) / 512.0f, (static_cast<float>(y) + 0.5f) / 256.0f});
      if (const float l = luminance(sky.le(w)); l > brightest) brightest = l, sun = w;
    }
  const float near_sun = std::cos(3.0f * kPi / 180.0f);
  int at_sun[2] = {0, 0};

  // The map, twice, with the samples of each way on it.
  constexpr int kW = 512, kH = 256, kGap = 12, kWidth = 2 * kW + 3 * kGap, kHeight = kH + 2 * kGap;
  std::vector<unsigned char> rgb(kWidth * kHeight * 3, 255);
  auto put = [&](int x, int y, Color c) {
    if (x < 0 || y < 0 || x >= kWidth || y >= kHeight) return;
    unsigned char* p = &rgb[(y * kWidth + x) * 3];
    p[0] = static_cast<unsigned char>(255.0f * c.r), p[1] = static_cast<unsigned char>(255.0f * c.g);
    p[2] = static_cast<unsigned char>(255.0f * c.b);
  };
  auto tone = [](float x) { return std::pow(std::min(x / (1.0f + x), 1.0f), 1.0f / 2.2f); };
  for (int panel = 0; panel < 2; ++panel) {
    const int x0 = kGap + panel * (kW + kGap);
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x) {
        const Color l = sky.le(sky.direction({(static_cast<float>(x) + 0.5f) / kW, (static_cast<float>(y) + 0.5f) / kH}));
        put(x0 + x, kGap + y, Color(tone(l.r), tone(l.g), tone(l.b)));
      }
    Pcg32 rng(1, static_cast<uint64_t>(panel));
    const Color dot = panel == 0 ? Color(0.1f, 0.3f, 0.9f) : Color(0.9f, 0.1f, 0.1f);
    for (int i = 0; i < 1024; ++i) {
      const Vec2f u{rng.next_float(), rng.next_float()};
      Vec3f w = uniform(u);
      if (panel == 1) {
        const auto s = sky.sample_li(up, u);
        if (!s) continue;
        w = s->wi;
      }
      if (rtk::dot(w, sun) > near_sun) ++at_sun[panel];
      const Vec2f uv = sky.coordinates(w);
      const int px = x0 + static_cast<int>(uv.x * kW), py = kGap + static_cast<int>(uv.y * kH);
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) put(px + dx, py + dy, dot);
    }
  }
  if (!stbi_write_png(argv[2], kWidth, kHeight, 3, rgb.data(), kWidth * 3)) {
    std::fprintf(stderr, "%s: cannot write %s\n", argv[0], argv[2]);
    return 1;
  }

  std::printf("within 3 degrees of the sun: %d of 1024 uniform directions, %d of 1024 importance samples\n",
              at_sun[0], at_sun[1]);

  // How much a 16-sample estimate of the irradiance varies with each way.
  constexpr int kTrials = 2000, kSamples = 16;
  for (int way = 0; way < 2; ++way) {
    Pcg32 rng(7, static_cast<uint64_t>(way));
    double sum = 0, sum2 = 0;
    for (int t = 0; t < kTrials; ++t) {
      double e = 0;
      for (int i = 0; i < kSamples; ++i) {
        const Vec2f u{rng.next_float(), rng.next_float()};
        if (way == 0) {
          e += contribution(sky, uniform(u), pdf_uniform_hemisphere());
        } else if (const auto s = sky.sample_li(up, u)) {
          e += contribution(sky, s->wi, s->pdf);
        }
      }
      e /= kSamples;
      sum += e, sum2 += e * e;
    }
    const double mean = sum / kTrials, sd = std::sqrt(std::max(0.0, sum2 / kTrials - mean * mean));
    std::printf("%s: irradiance %.4f, relative standard deviation of %d-sample estimates %.3f\n",
                way == 0 ? "uniform hemisphere" : "importance sampling", mean, kSamples, sd / mean);
  }
  return 0;
}
