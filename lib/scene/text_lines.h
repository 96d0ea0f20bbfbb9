/// \file
/// Line-by-line reading of the text formats of scenes (OBJ, MTL): comments stripped, a
/// backslash at the end of a line joins the next one, tokens split at blanks.
#pragma once

#include <deque>
#include <string>
#include <string_view>
#include <vector>

#include "scene/parse_number.h"

namespace rtk::scene_io {

/// One logical line: its number in the file (the first physical line of a joined line) and
/// its tokens.
struct TextLine {
  size_t line = 0;
  std::vector<std::string_view> tokens;
};

/// Splits `text` into lines of tokens; blank and comment-only lines are left out. A control
/// byte (binary data) is refused with the file and line. The views point into `text`, except
/// that joined lines are copied into `storage`.
inline std::vector<TextLine> split_lines(std::string_view text, const std::string& file,
                                         std::deque<std::string>& storage) {
  std::vector<TextLine> lines;
  if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);
  size_t number = 0, pos = 0;
  std::string joined;
  size_t joined_line = 0;
  while (pos <= text.size()) {
    size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(pos, end - pos);
    ++number;
    pos = end + 1;
    for (char c : line) {
      const unsigned char u = static_cast<unsigned char>(c);
      if ((u < 0x20 && c != '\t' && c != '\r') || u == 0x7f)
        fail({file, number}, "control byte in the text (binary data?)");
    }
    if (const size_t hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ' || line.back() == '\t'))
      line.remove_suffix(1);
    const bool continues = !line.empty() && line.back() == '\\';
    if (continues) line.remove_suffix(1);
    if (continues || !joined.empty()) {
      if (joined.empty()) joined_line = number;
      joined.append(line).push_back(' ');
      if (continues && pos <= text.size()) continue;
      storage.push_back(std::move(joined));
      joined.clear();
      line = storage.back();
    } else {
      joined_line = number;
    }
    TextLine out{joined_line, {}};
    size_t i = 0;
    while (i < line.size()) {
      while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
      const size_t start = i;
      while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
      if (i > start) out.tokens.push_back(line.substr(start, i - start));
    }
    if (!out.tokens.empty()) lines.push_back(std::move(out));
    if (end == text.size()) break;
  }
  return lines;
}

}  // namespace rtk::scene_io
