// OpenEXR files, through the OpenEXR library (Debian's libopenexr-dev): RTK reads and writes
// them in memory, so that reading keeps lib/image's rules (the whole file in hand, dimensions
// checked before anything is allocated, every failure a FileError naming the file) and writing
// stays all or nothing.
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>

#include <cstring>
#include <exception>
#include <string>

#include "image/image_decoders.h"
#include "image/image_exr.h"

namespace rtk {

namespace {

// A file held in memory, read through OpenEXR's stream interface; a read past its end is an
// error (OpenEXR turns it into an exception), never a read of other memory.
class MemoryIStream final : public Imf::IStream {
 public:
  MemoryIStream(std::string_view bytes, const char* name) : Imf::IStream(name), bytes_(bytes) {}
  bool read(char c[], int n) override {
    if (n < 0 || pos_ > bytes_.size() || static_cast<uint64_t>(n) > bytes_.size() - pos_)
      throw std::runtime_error("truncated");
    std::memcpy(c, bytes_.data() + pos_, static_cast<size_t>(n));
    pos_ += static_cast<uint64_t>(n);
    return pos_ < bytes_.size();
  }
  uint64_t tellg() override { return pos_; }
  void seekg(uint64_t pos) override { pos_ = pos; }
  void clear() override {}

 private:
  std::string_view bytes_;
  uint64_t pos_ = 0;
};

// A file made in memory, written through OpenEXR's stream interface.
class MemoryOStream final : public Imf::OStream {
 public:
  explicit MemoryOStream(std::string& out) : Imf::OStream("memory"), out_(out) {}
  void write(const char c[], int n) override {
    if (pos_ + static_cast<uint64_t>(n) > out_.size()) out_.resize(pos_ + static_cast<uint64_t>(n));
    std::memcpy(out_.data() + pos_, c, static_cast<size_t>(n));
    pos_ += static_cast<uint64_t>(n);
  }
  uint64_t tellp() override { return pos_; }
  void seekp(uint64_t pos) override { pos_ = pos; }

 private:
  std::string& out_;
  uint64_t pos_ = 0;
};

}  // namespace

namespace image_detail {

// [image-exr-read]
DecodedImage decode_exr(std::string_view bytes, const std::string& name) {
  try {
    MemoryIStream stream(bytes, name.c_str());
    Imf::InputFile file(stream);
    const Imath::Box2i window = file.header().dataWindow();
    const int64_t w = int64_t(window.max.x) - window.min.x + 1, h = int64_t(window.max.y) - window.min.y + 1;
    if (w < 1 || h < 1) fail(name, "an EXR image with an empty data window");
    check_dimensions(name, static_cast<uint64_t>(w), static_cast<uint64_t>(h));
    const Imf::ChannelList& channels = file.header().channels();
    const bool rgb = channels.findChannel("R") || channels.findChannel("G") || channels.findChannel("B");
    const bool grey = !rgb && channels.findChannel("Y");
    if (!rgb && !grey) fail(name, "an EXR image without R, G, B or Y channels");
    DecodedImage out;
    out.linear = true;
    out.image.width = static_cast<int>(w);
    out.image.height = static_cast<int>(h);
    out.image.pixels.resize(static_cast<size_t>(w * h));
    // Each channel lands in its float of the colour; a missing one is 0. Slice::Make places
    // the data window's corner at the first pixel.
    Imf::FrameBuffer buffer;
    const size_t xs = sizeof(Color), ys = sizeof(Color) * static_cast<size_t>(w);
    Color* first = out.image.pixels.data();
    if (rgb) {
      buffer.insert("R", Imf::Slice::Make(Imf::FLOAT, &first->r, window, xs, ys));
      buffer.insert("G", Imf::Slice::Make(Imf::FLOAT, &first->g, window, xs, ys));
      buffer.insert("B", Imf::Slice::Make(Imf::FLOAT, &first->b, window, xs, ys));
    } else {
      buffer.insert("Y", Imf::Slice::Make(Imf::FLOAT, &first->r, window, xs, ys));
    }
    file.setFrameBuffer(buffer);
    file.readPixels(window.min.y, window.max.y);
    if (grey)
      for (Color& c : out.image.pixels) c.g = c.b = c.r;
    return out;
  } catch (const FileError&) {
    throw;
  } catch (const std::exception& e) {
    fail(name, std::string("not a valid EXR image: ") + e.what());
  }
}
// [image-exr-read]

}  // namespace image_detail

std::string encode_exr(const Image& image) {
  // Linear floats, losslessly compressed (ZIP): an EXR keeps exactly what was rendered.
  Imf::Header header(image.width, image.height);
  header.compression() = Imf::ZIP_COMPRESSION;
  for (const char* c : {"R", "G", "B"}) header.channels().insert(c, Imf::Channel(Imf::FLOAT));
  std::string out;
  MemoryOStream stream(out);
  Imf::OutputFile file(stream, header);
  Imf::FrameBuffer buffer;
  const size_t xs = sizeof(Color), ys = sizeof(Color) * static_cast<size_t>(image.width);
  // OpenEXR's slices are not const; it only reads them here.
  Color* first = const_cast<Color*>(image.pixels.data());
  buffer.insert("R", Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(&first->r), xs, ys));
  buffer.insert("G", Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(&first->g), xs, ys));
  buffer.insert("B", Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(&first->b), xs, ys));
  file.setFrameBuffer(buffer);
  file.writePixels(image.height);
  return out;
}

}  // namespace rtk
