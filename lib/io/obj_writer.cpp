#include "io/obj_writer.h"

#include <charconv>

#include "io/read_file.h"

namespace rtk {

namespace {

void append_float(std::string& out, float value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.append(buffer, result.ptr);
}

void append_index(std::string& out, uint32_t value) {
  char buffer[16];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, uint64_t(value) + 1);
  out.append(buffer, result.ptr);
}

}  // namespace

std::string format_obj(const TriangleMesh& mesh) {
  std::string out;
  out.reserve(mesh.vertices.size() * 32 + mesh.triangles.size() * 24);
  for (const Vec3f& v : mesh.vertices) {
    out += "v ";
    append_float(out, v.x);
    out += ' ';
    append_float(out, v.y);
    out += ' ';
    append_float(out, v.z);
    out += '\n';
  }
  for (const auto& tri : mesh.triangles) {
    out += "f ";
    append_index(out, tri[0]);
    out += ' ';
    append_index(out, tri[1]);
    out += ' ';
    append_index(out, tri[2]);
    out += '\n';
  }
  return out;
}

void save_obj(const std::filesystem::path& path, const TriangleMesh& mesh) {
  write_file(path, format_obj(mesh));
}

}  // namespace rtk
