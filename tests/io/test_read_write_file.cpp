// lib/io's whole-file reading and writing: reading is bounded (devices, folders and endless
// pipes are refused), writing is all or nothing, and output paths can be checked before work.
#include <doctest/doctest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include "io/file_error.h"
#include "io/read_file.h"

namespace fs = std::filesystem;

namespace {

struct Scratch {
  fs::path dir = fs::temp_directory_path() / ("rtk_io_files_" + std::to_string(::getpid()));
  Scratch() {
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  ~Scratch() { fs::remove_all(dir); }
  // The names in the folder, for checking that no temporary file was left behind.
  size_t entries() const {
    return static_cast<size_t>(
        std::distance(fs::directory_iterator(dir), fs::directory_iterator()));
  }
};

std::string error_of(auto&& call) {
  try {
    call();
  } catch (const rtk::FileError& e) {
    return e.what();
  }
  return "";
}

bool contains(const std::string& text, const std::string& words) {
  return text.find(words) != std::string::npos;
}

}  // namespace

TEST_CASE(
    "io: read_file refuses devices, folders and files above their limit, without reading them") {
  Scratch s;
  CHECK(contains(error_of([] { rtk::read_file("/dev/zero"); }), "/dev/zero: is a device"));
  CHECK(contains(error_of([&] { rtk::read_file(s.dir); }), "is a folder"));
  CHECK(contains(error_of([&] { rtk::read_file(s.dir / "missing"); }), "cannot open"));
  std::ofstream(s.dir / "ten") << "0123456789";
  CHECK(rtk::read_file(s.dir / "ten", 10) == "0123456789");
  CHECK(contains(error_of([&] { rtk::read_file(s.dir / "ten", 9); }),
                 "10 bytes, more than the 9 bytes"));
}

TEST_CASE("io: a pipe is read up to the limit and refused past it") {
  Scratch s;
  const fs::path fifo = s.dir / "pipe";
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  // The writer fits in the pipe's buffer, so it finishes whether or not the reader stops early.
  std::thread writer([&] { std::ofstream(fifo) << std::string(5000, 'x'); });
  CHECK(contains(error_of([&] { rtk::read_file(fifo, 1000); }), "more than 1000 bytes"));
  writer.join();
  std::thread writer2([&] { std::ofstream(fifo) << "short"; });
  CHECK(rtk::read_file(fifo, 1000) == "short");
  writer2.join();
}

TEST_CASE("io: write_file replaces a file all at once and leaves no temporary file") {
  Scratch s;
  const fs::path out = s.dir / "out.bin";
  rtk::write_file(out, "first");
  rtk::write_file(out, "second, longer");
  CHECK(rtk::read_file(out) == "second, longer");
  CHECK(s.entries() == 1);
  // A link keeps pointing at its file, which gets the new bytes.
  fs::create_symlink(out, s.dir / "link.bin");
  rtk::write_file(s.dir / "link.bin", "through the link");
  CHECK(fs::is_symlink(s.dir / "link.bin"));
  CHECK(rtk::read_file(out) == "through the link");
  // A failed write names the file and leaves nothing behind.
  CHECK(contains(error_of([&] { rtk::write_file(s.dir / "no" / "such" / "folder.bin", "x"); }),
                 "cannot create"));
  CHECK(contains(error_of([&] { rtk::write_file(s.dir, "x"); }), "is a folder"));
  CHECK(s.entries() == 2);
  // Devices are written in place, and a full one is an error, not a silent loss.
  rtk::write_file("/dev/null", "discarded");
  CHECK(contains(error_of([] { rtk::write_file("/dev/full", "lost"); }), "/dev/full: write error"));
}

TEST_CASE("io: check_output_path finds what would fail before any work is done") {
  Scratch s;
  rtk::check_output_path(s.dir / "new.png");
  rtk::check_output_path("relative_name.png");
  rtk::check_output_path("/dev/null");
  CHECK(contains(error_of([&] { rtk::check_output_path(s.dir / "missing" / "x.png"); }),
                 "does not exist"));
  CHECK(contains(error_of([&] { rtk::check_output_path(s.dir); }), "is a folder"));
  std::ofstream(s.dir / "file") << "x";
  CHECK(contains(error_of([&] { rtk::check_output_path(s.dir / "file" / "x.png"); }),
                 "is not a folder"));
  CHECK(contains(error_of([] { rtk::check_output_path(""); }), "needs a name"));
  CHECK(s.entries() == 1);  // nothing was created
}
