#include "12_materials/texture.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "image/image_decode.h"

namespace rtk {

ImageTexture::ImageTexture(int width, int height, std::vector<Color> texels, WrapMode wrap,
                           TextureLookup lookup, TextureOrigin origin)
    : width_(width), height_(height), texels_(std::move(texels)), wrap_(wrap), lookup_(lookup),
      origin_(origin) {
  if (width <= 0 || height <= 0 ||
      texels_.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height))
    throw std::invalid_argument("ImageTexture: " + std::to_string(texels_.size()) +
                                " texels do not make a " + std::to_string(width) + " x " +
                                std::to_string(height) + " image");
}

namespace {
int wrap_index(int i, int n, WrapMode mode) {
  if (mode == WrapMode::clamp) return std::clamp(i, 0, n - 1);
  const int r = i % n;
  return r < 0 ? r + n : r;
}
}  // namespace

Color ImageTexture::texel(int x, int y) const {
  x = wrap_index(x, width_, wrap_);
  y = wrap_index(y, height_, wrap_);
  return texels_[static_cast<std::size_t>(y) * width_ + x];
}

// [ch12-bilinear]
Color ImageTexture::eval(Vec2f uv) const {
  // Coordinates that are not numbers (a degenerate mesh's) look up texel (0, 0) rather than
  // turning into an out-of-range integer.
  if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) return texel(0, 0);
  // Continuous texel coordinates with texel centres at integers + 0.5; v = 0 is the bottom.
  // The repeat mode first folds the coordinates into [0, 1) so that huge values keep their
  // fraction's precision and fit in an int.
  float u = uv.x, v = uv.y;
  if (wrap_ == WrapMode::repeat) {
    u -= std::floor(u);
    v -= std::floor(v);
  } else {
    u = std::clamp(u, -1.0f, 2.0f);
    v = std::clamp(v, -1.0f, 2.0f);
  }
  // The image row coordinate: from the top, which is v = 1 in the OBJ convention, v = 0 in
  // Embree 1.1's.
  const float row = origin_ == TextureOrigin::bottom ? 1.0f - v : v;
  if (lookup_ == TextureLookup::nearest)
    // row reaches 1 at v = 0 with the bottom origin: that point belongs to the last row.
    return texel(static_cast<int>(std::floor(u * width_)),
                 std::min(static_cast<int>(std::floor(row * height_)), height_ - 1));
  const float x = u * width_ - 0.5f, y = row * height_ - 0.5f;
  const float fx = std::floor(x), fy = std::floor(y);
  const int x0 = static_cast<int>(fx), y0 = static_cast<int>(fy);
  const float tx = x - fx, ty = y - fy;
  // Blend the four nearest texels.
  return (texel(x0, y0) * (1 - tx) + texel(x0 + 1, y0) * tx) * (1 - ty) +
         (texel(x0, y0 + 1) * (1 - tx) + texel(x0 + 1, y0 + 1) * tx) * ty;
}
// [ch12-bilinear]

float srgb_to_linear(float c) {
  return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

// [ch12-load-texture]
std::shared_ptr<ImageTexture> load_image_texture(const std::string& path,
                                                 const TextureConventions& conventions, WrapMode wrap) {
  return load_image_texture(path, conventions.encoding, wrap, conventions.lookup, conventions.origin);
}

std::shared_ptr<ImageTexture> load_image_texture(const std::string& path, ColorEncoding encoding,
                                                 WrapMode wrap, TextureLookup lookup,
                                                 TextureOrigin origin) {
  // lib/image's bounded reader: a damaged or truncated file is an error naming it, never a
  // hang or a texture of whatever memory held.
  DecodedImage file = read_image_file(path);
  if (!file.linear) {
    // Decode through a 256-entry table: the curve costs a pow per channel otherwise. Values of
    // 16-bit files fall between its entries and take the curve itself.
    float table[256];
    for (int i = 0; i < 256; ++i)
      table[i] = encoding == ColorEncoding::srgb ? srgb_to_linear(i / 255.0f) : i / 255.0f;
    auto decode = [&](float v) {
      const float scaled = v * 255.0f;
      const int i = static_cast<int>(scaled + 0.5f);
      if (std::fabs(scaled - static_cast<float>(i)) < 1e-3f) return table[i];
      return encoding == ColorEncoding::srgb ? srgb_to_linear(v) : v;
    };
    for (Color& c : file.image.pixels) c = {decode(c.r), decode(c.g), decode(c.b)};
  }
  return std::make_shared<ImageTexture>(file.image.width, file.image.height,
                                        std::move(file.image.pixels), wrap, lookup, origin);
}
// [ch12-load-texture]

}  // namespace rtk
