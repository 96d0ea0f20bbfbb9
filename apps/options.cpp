#include "options.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>

namespace rtk::cli {

namespace {

// "--name" and "-name" are the same option; "-" alone and plain words are not options.
std::string_view option_name(std::string_view arg) {
  if (arg.size() > 2 && arg.starts_with("--")) return arg.substr(2);
  if (arg.size() > 1 && arg.starts_with("-") && arg != "--") return arg.substr(1);
  return {};
}

std::string format_number(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g", x);
  return buffer;
}

bool contains(const std::vector<std::string_view>& list, std::string_view name) {
  return std::find(list.begin(), list.end(), name) != list.end();
}

}  // namespace

Options::Options(std::string_view command, std::span<const std::string_view> args, const OptionSpec& spec)
    : command_(command) {
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string_view name = option_name(args[i]);
    if (name.empty()) {
      positional_.emplace_back(args[i]);
      continue;
    }
    const bool takes_value = contains(spec.with_value, name);
    if (!takes_value && !contains(spec.flags, name))
      throw error("unknown option '" + std::string(args[i]) + "'");
    if (has(name)) throw error("option -" + std::string(name) + " is given twice");
    if (takes_value) {
      if (i + 1 == args.size()) throw error("option -" + std::string(name) + " needs a value");
      values_[std::string(name)] = std::string(args[++i]);
    } else {
      values_[std::string(name)] = "";
    }
  }
  if (positional_.size() > spec.positional)
    throw error("unexpected argument '" + positional_[spec.positional] + "'");
  if (positional_.size() < spec.positional)
    throw error("expected " + std::to_string(spec.positional) + " file arguments, got " +
                std::to_string(positional_.size()));
}

UsageError Options::error(const std::string& message) const { return UsageError(message); }

const std::string& Options::required(std::string_view name) const {
  const auto it = values_.find(std::string(name));
  if (it == values_.end()) throw error("missing option -" + std::string(name));
  return it->second;
}

std::string Options::get(std::string_view name, std::string_view fallback) const {
  const auto it = values_.find(std::string(name));
  return it == values_.end() ? std::string(fallback) : it->second;
}

uint64_t Options::get_count(std::string_view name, uint64_t fallback, uint64_t min, uint64_t max) const {
  if (!has(name)) return fallback;
  const std::string& text = required(name);
  uint64_t value = 0;
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || ptr != text.data() + text.size() || value < min || value > max)
    throw error("option -" + std::string(name) + ": '" + text + "' is not a whole number from " +
                std::to_string(min) + " to " + std::to_string(max));
  return value;
}

double Options::get_number(std::string_view name, double fallback, double min, double max) const {
  if (!has(name)) return fallback;
  const std::string& text = required(name);
  double value = 0;
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || ptr != text.data() + text.size() || !std::isfinite(value) || value < min ||
      value > max)
    throw error("option -" + std::string(name) + ": '" + text + "' is not a number from " +
                format_number(min) + " to " + format_number(max));
  return value;
}

}  // namespace rtk::cli
