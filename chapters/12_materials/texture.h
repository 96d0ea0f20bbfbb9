/// \file
/// Textures: colours that vary over a surface with its (u, v) coordinates.
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "01_base/color.h"
#include "11_sampling/vec2.h"

namespace rtk {

/// A colour as a function of texture coordinates.
class Texture {
 public:
  virtual ~Texture() = default;
  /// The colour at (u, v).
  virtual Color eval(Vec2f uv) const = 0;
};

/// The same colour everywhere.
class ConstantTexture final : public Texture {
 public:
  /// A texture of colour c.
  explicit ConstantTexture(Color c) : color_(c) {}
  Color eval(Vec2f) const override { return color_; }
  /// The colour.
  Color color() const { return color_; }

 private:
  Color color_;
};

/// What happens to coordinates outside [0, 1].
enum class WrapMode {
  repeat,  ///< the image tiles the plane
  clamp,   ///< the border texels extend outward
};

/// How an 8-bit image file encodes its values.
enum class ColorEncoding {
  srgb,    ///< the sRGB transfer curve (photographs, painted textures): decoded to linear
  linear,  ///< values are linear already (data maps)
};

/// How an image is read between its texel centres.
enum class TextureLookup {
  bilinear,  ///< the four nearest texels blended (RTK)
  nearest,   ///< the texel the point falls in (Embree 1.1)
};

/// Which row of the image texture coordinate v = 0 names.
enum class TextureOrigin {
  bottom,  ///< v = 0 is the bottom row, v grows upward (the OBJ convention; RTK)
  top,     ///< v = 0 is the top row, the first in the file (Embree 1.1)
};

// [ch12-texture-conventions]
/// The conventions a scene's image files were made for. RTK's are today's: the OBJ
/// convention's origin, bilinear lookups and 8-bit files decoded from sRGB. Embree 1.1's
/// scenes were made for its own: t = 0 the image's top row, the nearest texel, and 8-bit
/// values read as linear (so that its lines.ppm gives twice the light an sRGB decoding gives).
struct TextureConventions {
  TextureLookup lookup = TextureLookup::bilinear;
  TextureOrigin origin = TextureOrigin::bottom;
  ColorEncoding encoding = ColorEncoding::srgb;  ///< of 8- and 16-bit files
  /// Embree 1.1's environment maps (chapter 13) are mirrored against RTK's and interpolated.
  bool embree11_environment = false;

  /// Embree 1.1's conventions.
  static TextureConventions embree11() {
    return {TextureLookup::nearest, TextureOrigin::top, ColorEncoding::linear, true};
  }
  /// Whether these are Embree 1.1's.
  bool is_embree11() const { return embree11_environment; }
};
// [ch12-texture-conventions]

/// An image looked up between texel centres by `lookup`. With the bottom origin texture
/// coordinate (0, 0) is the bottom-left corner of the image and (1, 1) the top-right (the OBJ
/// convention): texel (x, y) with y = 0 the top row covers [x, x+1] / width by
/// [h - y - 1, h - y] / height; with the top origin (0, 0) is the top-left corner and texel
/// (x, y) covers [x, x+1] / width by [y, y + 1] / height.
class ImageTexture final : public Texture {
 public:
  /// An image of width x height linear colours, top row first; throws std::invalid_argument
  /// for a non-positive size or a texel count that does not match.
  ImageTexture(int width, int height, std::vector<Color> texels, WrapMode wrap = WrapMode::repeat,
               TextureLookup lookup = TextureLookup::bilinear,
               TextureOrigin origin = TextureOrigin::bottom);

  Color eval(Vec2f uv) const override;
  /// The texel at column x and row y (top row 0), after wrapping.
  Color texel(int x, int y) const;
  /// The image's width.
  int width() const { return width_; }
  /// The image's height.
  int height() const { return height_; }

 private:
  int width_, height_;
  std::vector<Color> texels_;
  WrapMode wrap_;
  TextureLookup lookup_;
  TextureOrigin origin_;
};

/// Another texture seen through an affine map of its coordinates: eval(uv) =
/// base(offset + scale * uv), the guide's MatteTextured parameters s0 and ds.
class MappedTexture final : public Texture {
 public:
  /// base's coordinates are offset + scale * uv.
  MappedTexture(std::shared_ptr<const Texture> base, Vec2f offset, Vec2f scale)
      : base_(std::move(base)), offset_(offset), scale_(scale) {}
  Color eval(Vec2f uv) const override { return base_->eval(offset_ + scale_ * uv); }

 private:
  std::shared_ptr<const Texture> base_;
  Vec2f offset_, scale_;
};

/// The sRGB transfer curve inverted: an encoded value in [0, 1] to linear (IEC 61966-2-1).
float srgb_to_linear(float encoded);

/// Loads an image file as a texture through lib/image's bounded reader (PNG, JPEG, TGA,
/// PPM/PGM, Radiance HDR, PFM: image/image_decode.h). HDR and PFM files are linear; 8- and
/// 16-bit files are decoded by `encoding`. Throws FileError (a std::runtime_error) naming the
/// file and the reason when it cannot be read or is not a complete, valid image.
std::shared_ptr<ImageTexture> load_image_texture(const std::string& path,
                                                 ColorEncoding encoding = ColorEncoding::srgb,
                                                 WrapMode wrap = WrapMode::repeat,
                                                 TextureLookup lookup = TextureLookup::bilinear,
                                                 TextureOrigin origin = TextureOrigin::bottom);

/// load_image_texture with the encoding, lookup and origin of `conventions`.
std::shared_ptr<ImageTexture> load_image_texture(const std::string& path,
                                                 const TextureConventions& conventions,
                                                 WrapMode wrap = WrapMode::repeat);

}  // namespace rtk
