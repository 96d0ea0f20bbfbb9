// The OBJ loader: every accepted form gives the right triangles, every malformed line is an
// error that names the file and the line.
#include <doctest/doctest.h>

#include <unistd.h>

#include <filesystem>
#include <string>

#include "io/file_error.h"
#include "io/obj_loader.h"
#include "io/obj_writer.h"
#include "io/read_file.h"
#include "testing/scenes.h"

namespace {

using rtk::FileError;
using rtk::parse_obj;
using rtk::TriangleMesh;

// The message of the FileError that parsing `text` throws ("" when it throws none).
std::string error_of(const std::string& text) {
  try {
    parse_obj(text, "scene.obj");
  } catch (const FileError& e) {
    return e.what();
  }
  return "";
}

// Checks that `text` fails at `line` with a message containing `words`.
void check_error(const std::string& text, size_t line, const std::string& words) {
  CAPTURE(text);
  const std::string message = error_of(text);
  CAPTURE(message);
  CHECK(message.starts_with("scene.obj:" + std::to_string(line) + ": "));
  CHECK(message.find(words) != std::string::npos);
}

const char* const kSquare =
    "v 0 0 0\n"
    "v 1 0 0\n"
    "v 1 1 0\n"
    "v 0 1 0\n";

}  // namespace

TEST_CASE("io: OBJ vertices and a triangle") {
  const TriangleMesh mesh = parse_obj("v 1 2 3\nv -4.5 5e2 +6\nv .5 -0 1e-3\nf 1 2 3\n", "t.obj");
  REQUIRE(mesh.vertices.size() == 3);
  CHECK(mesh.vertices[1] == rtk::Vec3f{-4.5f, 500.0f, 6.0f});
  CHECK(mesh.vertices[2] == rtk::Vec3f{0.5f, -0.0f, 0.001f});
  REQUIRE(mesh.triangles.size() == 1);
  CHECK(mesh.triangles[0] == std::array<uint32_t, 3>{0, 1, 2});
}

TEST_CASE("io: OBJ face corner forms i, i/t, i//n, i/t/n") {
  const std::string head = std::string(kSquare) + "vt 0 0\nvt 1 0\nvt 1 1\nvn 0 0 1\n";
  for (const char* face : {"f 1 2 3", "f 1/1 2/2 3/3", "f 1//1 2//1 3//1", "f 1/1/1 2/2/1 3/3/1",
                           "f 1/1/1 2//1 3"}) {
    CAPTURE(face);
    const TriangleMesh mesh = parse_obj(head + face + "\n", "t.obj");
    REQUIRE(mesh.triangles.size() == 1);
    CHECK(mesh.triangles[0] == std::array<uint32_t, 3>{0, 1, 2});
  }
}

TEST_CASE("io: OBJ negative indices count back from the last vertex read") {
  const TriangleMesh mesh = parse_obj(std::string(kSquare) + "f -4 -3 -2\nv 5 5 5\nf -1 -2 -5\n", "t.obj");
  REQUIRE(mesh.triangles.size() == 2);
  CHECK(mesh.triangles[0] == std::array<uint32_t, 3>{0, 1, 2});
  CHECK(mesh.triangles[1] == std::array<uint32_t, 3>{4, 3, 0});
}

TEST_CASE("io: OBJ polygons are fans in file order and primIDs follow the file") {
  const TriangleMesh mesh = parse_obj(std::string(kSquare) + "v 2 2 2\nf 1 2 3 4 5\nf 4 3 2\n", "t.obj");
  REQUIRE(mesh.triangles.size() == 4);
  CHECK(mesh.triangles[0] == std::array<uint32_t, 3>{0, 1, 2});
  CHECK(mesh.triangles[1] == std::array<uint32_t, 3>{0, 2, 3});
  CHECK(mesh.triangles[2] == std::array<uint32_t, 3>{0, 3, 4});
  CHECK(mesh.triangles[3] == std::array<uint32_t, 3>{3, 2, 1});
}

TEST_CASE("io: OBJ statements that are not geometry change nothing") {
  const std::string text =
      "# a comment\n"
      "mtllib scene.mtl\n"
      "o object\n"
      "g group one\n"
      "s off\n"
      "usemtl red\n"
      "\n"
      "   \t \n"
      "v 0 0 0 # trailing comment\n"
      "v 1 0 0 1.0\n"           // a weight w
      "v 0 1 0 0.5 0.5 0.5\n"   // a vertex colour
      "vp 0.5\n"
      "l 1 2\n"
      "f 1 2 3# comment right after\n";
  const TriangleMesh mesh = parse_obj(text, "t.obj");
  CHECK(mesh.vertices.size() == 3);
  REQUIRE(mesh.triangles.size() == 1);
  CHECK(mesh.vertices[2] == rtk::Vec3f{0, 1, 0});
}

TEST_CASE("io: OBJ line ends, byte-order mark and a last line without a line end") {
  const TriangleMesh crlf = parse_obj("\xEF\xBB\xBFv 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nf 1 2 3", "t.obj");
  CHECK(crlf.vertices.size() == 3);
  CHECK(crlf.triangles.size() == 1);
  CHECK(parse_obj("", "empty.obj").triangles.empty());
}

TEST_CASE("io: OBJ degenerate faces keep their primIDs") {
  const TriangleMesh mesh = parse_obj(std::string(kSquare) + "f 1 1 1\nf 1 2 3\n", "t.obj");
  REQUIRE(mesh.triangles.size() == 2);
  CHECK(mesh.triangles[1] == std::array<uint32_t, 3>{0, 1, 2});
}

TEST_CASE("io: OBJ numbers are read exactly, tiny ones round to zero") {
  const TriangleMesh mesh = parse_obj("v 0.1 3.4028235e38 1e-50\n", "t.obj");
  CHECK(mesh.vertices[0].x == 0.1f);
  CHECK(mesh.vertices[0].y == 3.4028235e38f);
  CHECK(mesh.vertices[0].z == 0.0f);
}

TEST_CASE("io: OBJ bad numbers name the file and the line") {
  check_error("v 1 2 3\nv 1 2 x\n", 2, "bad number 'x'");
  check_error("v 1 2 3.5.5\n", 1, "bad number '3.5.5'");
  check_error("v 1 2 1e\n", 1, "bad number '1e'");
  check_error("v 1 2 --1\n", 1, "bad number '--1'");
  check_error("v 1 2 +-1\n", 1, "bad number '+-1'");
  check_error("v 1 2 0x10\n", 1, "bad number '0x10'");
  check_error("v 1 2 3,5\n", 1, "bad number '3,5'");
  check_error("v 1 2 nan\n", 1, "not finite");
  check_error("v 1 2 inf\n", 1, "not finite");
  check_error("v 1 2 1e39\n", 1, "not finite");
  check_error("v 1 2 1e999\n", 1, "out of range");
}

TEST_CASE("io: OBJ vertices with too few or too many numbers") {
  check_error("v 1 2\n", 1, "found 2");
  check_error("v\n", 1, "found 0");
  check_error("v 1 2 3 4 5\n", 1, "found 5");
  check_error("v 1 2 3 4 5 6 7\n", 1, "more than 6");
  check_error("v 1 2 3 # fine\nv 1 2 # three numbers needed\n", 2, "found 2");
}

TEST_CASE("io: OBJ face errors: index 0, out of range, too few corners, bad corners") {
  const std::string sq = kSquare;  // four vertices: lines 1-4
  check_error(sq + "f 1 2 0\n", 5, "vertex index 0 is invalid");
  check_error(sq + "f 1 2 5\n", 5, "vertex index 5 is out of range (4 read so far)");
  check_error(sq + "f 1 2 -5\n", 5, "vertex index -5 reaches before the first");
  check_error(sq + "f 1 2\n", 5, "at least 3 corners, found 2");
  check_error(sq + "f\n", 5, "found 0");
  check_error(sq + "f 1 2 3x\n", 5, "bad face corner '3x'");
  check_error(sq + "f 1 2 3/\n", 5, "bad texture index");
  check_error(sq + "f 1 2 3//\n", 5, "bad normal index");
  check_error(sq + "f 1 2 3/1\n", 5, "texture index 1 is out of range (0 read so far)");
  check_error(sq + "vn 0 0 1\nf 1 2 3//2\n", 6, "normal index 2 is out of range");
  check_error(sq + "vt 0 0\nvn 0 0 1\nf 1 2 3/1/1/1\n", 7, "bad face corner '3/1/1/1'");
  check_error(sq + "f 1 2 99999999999999999999\n", 5, "out of range");
  check_error(sq + "f 1 2 -9223372036854775808\n", 5, "reaches before the first");
  check_error(sq + "f 1 2 a\n", 5, "bad vertex index 'a'");
  // A face may only use vertices read before it.
  check_error("v 0 0 0\nf 1 2 3\nv 1 0 0\nv 0 1 0\n", 2, "out of range (1 read so far)");
}

TEST_CASE("io: OBJ lines that are not statements") {
  check_error("v 0 0 0\n1 2 3\n", 2, "expected a statement");
  check_error("v 0 0 0\n/f 1 2 3\n", 2, "expected a statement");
}

TEST_CASE("io: OBJ binary junk, NUL bytes and huge lines are errors") {
  check_error(std::string("v 0 0 0\nv 1 0 0\0junk\n", 20), 2, "control byte 0x00 at column 8");
  check_error("v 0 0 0\n# comment with a bell \a\n", 2, "control byte 0x07");
  check_error("v 0 0 0\ng name\x7f\n", 2, "control byte 0x7F");
  std::string huge = "# " + std::string(rtk::kMaxObjLineBytes, 'x') + "\nv 0 0 0\n";
  check_error(huge, 1, "line longer than");
  // A truncated file: the last line is cut in the middle of a face or a number.
  check_error(std::string(kSquare) + "f 1 2", 5, "found 2");
  check_error("v 0 0 0\nv 1 0", 2, "found 2");
}

TEST_CASE("io: OBJ files: a missing file names the file; write and load round trip") {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("rtk_io_tests_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  try {
    rtk::load_obj(dir / "does_not_exist.obj");
    FAIL("no exception");
  } catch (const FileError& e) {
    CHECK(std::string(e.what()).find("does_not_exist.obj") != std::string::npos);
    CHECK(e.line() == 0);
  }
  TriangleMesh mesh = rtk::test::make_random_soup(200, 7);
  rtk::test::add_degenerate_triangles(mesh, 5, 3);
  const std::filesystem::path file = dir / "soup.obj";
  rtk::save_obj(file, mesh);
  const TriangleMesh back = rtk::load_obj(file);
  CHECK(back.vertices == mesh.vertices);  // shortest round-trip decimal: bit for bit
  CHECK(back.triangles == mesh.triangles);
  std::filesystem::remove(file);
  std::filesystem::remove_all(dir);
}

TEST_CASE("io: FileError carries file and line") {
  try {
    parse_obj("v 0 0 0\n\n\nf 1 1\n", "dir/model.obj");
    FAIL("no exception");
  } catch (const FileError& e) {
    CHECK(e.file() == "dir/model.obj");
    CHECK(e.line() == 4);
  }
}
