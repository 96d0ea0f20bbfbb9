#include "io/read_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>

#include "io/file_error.h"

namespace rtk {

namespace {

struct FileCloser {
  void operator()(std::FILE* f) const { std::fclose(f); }
};
using FilePtr = std::unique_ptr<std::FILE, FileCloser>;

}  // namespace

std::string read_file(const std::filesystem::path& path) {
  const std::string name = path.string();
  FilePtr file(std::fopen(name.c_str(), "rb"));
  if (!file) throw FileError(name, 0, std::string("cannot open: ") + std::strerror(errno));
  // Read in blocks rather than trusting a size from the file system: pipes and /proc files
  // have none, and a file may change while it is read.
  std::string bytes;
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  if (!ec) bytes.reserve(size);
  char block[1 << 16];
  for (;;) {
    const std::size_t n = std::fread(block, 1, sizeof block, file.get());
    bytes.append(block, n);
    if (n < sizeof block) break;
  }
  if (std::ferror(file.get())) throw FileError(name, 0, std::string("read error: ") + std::strerror(errno));
  return bytes;
}

void write_file(const std::filesystem::path& path, std::string_view bytes) {
  const std::string name = path.string();
  FilePtr file(std::fopen(name.c_str(), "wb"));
  if (!file) throw FileError(name, 0, std::string("cannot create: ") + std::strerror(errno));
  if (std::fwrite(bytes.data(), 1, bytes.size(), file.get()) != bytes.size())
    throw FileError(name, 0, std::string("write error: ") + std::strerror(errno));
  // fclose flushes; a failure there (disk full) must be reported too.
  if (std::fclose(file.release()) != 0)
    throw FileError(name, 0, std::string("write error: ") + std::strerror(errno));
}

}  // namespace rtk
