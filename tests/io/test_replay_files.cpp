// The .rays, .hits and .occl files: round trips, and every damaged file refused by name.
#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <unistd.h>

#include <filesystem>
#include <limits>
#include <string>

#include "io/file_error.h"
#include "io/read_file.h"
#include "io/replay_files.h"

namespace {

// The message of the FileError that `f` throws ("" when none).
template <class F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const rtk::FileError& e) {
    return e.what();
  }
  return "";
}

std::vector<rtk::Ray> some_rays() {
  std::vector<rtk::Ray> rays(3);
  rays[0].org = {1, 2, 3};
  rays[0].dir = {0, 0, -1};
  rays[1].tnear = 0.5f;
  rays[1].tfar = 7.0f;
  rays[1].time = 0.25f;
  rays[1].dir = {1, 1, 1};
  rays[2].org = {std::numeric_limits<float>::quiet_NaN(), 0, 0};  // a bad ray is still a record
  return rays;
}

}  // namespace

TEST_CASE("io: .rays layout is the documented record, bytes and all") {
  const std::vector<rtk::Ray> rays = some_rays();
  const std::string bytes = rtk::format_rays(rays);
  REQUIRE(bytes.size() == 16 + 3 * 36);
  CHECK(bytes.substr(0, 8) == "RAYS0001");
  uint64_t count = 0;
  std::memcpy(&count, bytes.data() + 8, 8);
  CHECK(count == 3);
  // Record 1: org.x org.y org.z tnear dir.x dir.y dir.z time tfar.
  float record[9];
  std::memcpy(record, bytes.data() + 16 + 36, 36);
  CHECK(record[3] == 0.5f);
  CHECK(record[4] == 1.0f);
  CHECK(record[7] == 0.25f);
  CHECK(record[8] == 7.0f);
  const std::vector<rtk::Ray> back = rtk::parse_rays(bytes, "r.rays");
  REQUIRE(back.size() == 3);
  CHECK(std::memcmp(back.data(), rays.data(), 3 * sizeof(rtk::Ray)) == 0);
}

TEST_CASE("io: .hits and .occl round trip") {
  std::vector<rtk::Hit> hits(2);
  hits[0] = {1.5f, 0.25f, 0.5f, 42};
  const std::string bytes = rtk::format_hits(hits);
  CHECK(bytes.size() == 16 + 2 * 16);
  CHECK(bytes.substr(0, 8) == "HITS0001");
  const auto back = rtk::parse_hits(bytes, "h.hits");
  REQUIRE(back.size() == 2);
  CHECK(back[0].prim == 42);
  CHECK(back[0].t == 1.5f);
  CHECK(back[1].prim == rtk::kInvalidPrim);

  const std::vector<uint8_t> occl = {1, 0, 0, 1, 1};
  const std::string obytes = rtk::format_occlusion(occl);
  CHECK(obytes.size() == 16 + 5);
  CHECK(rtk::parse_occlusion(obytes, "o.occl") == occl);
  CHECK(rtk::parse_rays(rtk::format_rays({}), "empty.rays").empty());
}

TEST_CASE("io: damaged replay files are refused with the file's name") {
  const std::string good = rtk::format_rays(some_rays());
  // Bad magic, and a hits file given where rays are expected.
  std::string bad = good;
  bad[0] = 'X';
  CHECK(error_of([&] { rtk::parse_rays(bad, "a.rays"); }).starts_with("a.rays: not a .rays file"));
  CHECK(error_of([&] { rtk::parse_rays(rtk::format_hits({}), "h.hits"); }) ==
        "h.hits: not a .rays file: it begins with 'HITS0001', not 'RAYS0001'");
  // Truncated: shorter than the header, or records cut off.
  CHECK(error_of([&] { rtk::parse_rays(good.substr(0, 10), "t.rays"); }).starts_with("t.rays: truncated"));
  CHECK(error_of([&] { rtk::parse_rays(good.substr(0, good.size() - 1), "t.rays"); })
            .starts_with("t.rays: truncated: the header announces 3 records"));
  // Extra bytes after the records, and a count that would overflow a multiplication.
  CHECK(error_of([&] { rtk::parse_rays(good + "x", "x.rays"); }).starts_with("x.rays: count mismatch"));
  std::string huge = good;
  const uint64_t count = ~uint64_t(0) / 4;
  std::memcpy(huge.data() + 8, &count, 8);
  CHECK(error_of([&] { rtk::parse_rays(huge, "h.rays"); }).starts_with("h.rays: truncated"));
  // .occl bytes are 0 or 1.
  std::string occl = rtk::format_occlusion(std::vector<uint8_t>{0, 1, 0});
  occl[17] = 7;
  CHECK(error_of([&] { rtk::parse_occlusion(occl, "o.occl"); }) == "o.occl: record 1 is 7, not 0 or 1");
  CHECK(rtk::replay_file_kind(occl) == rtk::ReplayFile::occl);
  CHECK(!rtk::replay_file_kind("junk"));
}

TEST_CASE("io: replay files on disk") {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("rtk_io_tests_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const auto file = dir / "r.rays";
  rtk::write_rays(file, some_rays());
  CHECK(rtk::read_rays(file).size() == 3);
  std::filesystem::remove(file);
  CHECK(error_of([&] { rtk::read_hits(dir / "missing.hits"); }).find("missing.hits: cannot open") !=
        std::string::npos);
  CHECK(error_of([&] { rtk::write_hits(dir / "no_such_dir" / "h.hits", {}); }).find("cannot create") !=
        std::string::npos);
  std::filesystem::remove_all(dir);
}
