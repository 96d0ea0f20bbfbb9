/// \file
/// A strict Wavefront OBJ loader for triangle geometry: `v` and `f` lines, nothing guessed.
///
/// Why not tinyobjloader, the loader most projects reach for? Because it is forgiving by
/// design: a number it cannot read becomes 0, an index out of range is clamped or skipped with a
/// warning, a line it does not understand is dropped. That is right for a viewer and wrong for
/// ray replay (shared/ray-replay.md), where two tracers must see exactly the same triangles with
/// exactly the same primIDs, and a damaged file must stop the run with the file and line to
/// fix. So the rules here are few and enforced:
///
/// - `v x y z` adds a vertex. A fourth number (the weight w of the OBJ specification, which
///   only rational curves and surfaces use) and six numbers (`v x y z r g b`, the common
///   vertex-colour extension) are accepted; the extra numbers are checked and ignored.
///   Coordinates must be finite floats; a leading '+' is allowed; a number that underflows
///   to zero in float is zero, one that overflows float is an error.
/// - `f a b c ...` adds a face of at least three corners. A corner is `i`, `i/t`, `i//n` or
///   `i/t/n`. Indices count from 1; a negative index counts back from the last vertex read
///   (-1 is the last). Texture and normal indices must name a `vt`/`vn` line read before
///   (the OBJ rule) but are otherwise unused.
/// - A face with n corners becomes n - 2 triangles by a fan: (c0,c1,c2), (c0,c2,c3), ...
///   The primID of a triangle is its index in file order. A degenerate face is kept (its
///   triangles have zero area and are never hit, but they keep their primIDs).
/// - Every other statement (o, g, s, usemtl, mtllib, vt, vn, vp, l, p, ...) is skipped, but its
///   keyword must begin with a letter: a line that begins with anything else is an error.
/// - `#` starts a comment, also after the numbers of a line. Blank lines, tabs, CR LF line
///   ends, a final line without a line end and a UTF-8 byte-order mark are fine.
/// - An error: a number that is not one (`1.5x`, `1e`, `--1`), a missing or extra number,
///   index 0 or out of range, fewer than three corners, a control byte (NUL, binary junk)
///   anywhere in the file, a line longer than kMaxObjLineBytes. The exception is a FileError
///   whose message reads `FILE:LINE: what is wrong`.
///
/// Numbers are read with std::from_chars, which is exact (correctly rounded), locale-free and
/// fast; the whole file is read into memory and parsed in one pass.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string_view>

#include "01_base/triangle_mesh.h"

namespace rtk {

/// The longest line the loader accepts (1 MiB, a face of some 40,000 corners). Longer lines
/// are taken for a damaged or hostile file rather than buffered without bound.
inline constexpr std::size_t kMaxObjLineBytes = std::size_t(1) << 20;

/// Loads the triangles of an OBJ file. Throws FileError (file and line) on any malformed line,
/// or naming the file when it cannot be read.
TriangleMesh load_obj(const std::filesystem::path& path);

/// Parses OBJ text held in memory; `name` stands for the file in error messages.
TriangleMesh parse_obj(std::string_view text, std::string_view name);

}  // namespace rtk
