/// \file
/// The command line's small option parser: `-name value` or `--name value`, flags without a
/// value, and positional arguments. Every error names the command and the option.
#pragma once

#include <cstdint>
#include <map>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace rtk::cli {

/// A command line the user got wrong: the message names the option; `rtk` prints it after the
/// command's name, with a pointer to the usage, and exits with status 2.
struct UsageError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

/// What one command accepts.
struct OptionSpec {
  std::vector<std::string_view> with_value;  ///< options followed by a value (`-n 100`)
  std::vector<std::string_view> flags;       ///< options without a value (`-help`)
  size_t positional = 0;                     ///< how many arguments that are not options
};

/// A parsed command line. Option names are stored without their dashes.
class Options {
 public:
  /// Parses `args` for `command` ("trace", ...). An argument starting with '-' (but not "-"
  /// alone) is an option; one or two dashes are the same. The argument after an option that
  /// takes a value is that value, whatever it looks like (so `-seed -1` is a bad seed, not a
  /// missing one). Throws UsageError for an unknown option, a repeated one, a missing value or
  /// a wrong number of positional arguments.
  Options(std::string_view command, std::span<const std::string_view> args, const OptionSpec& spec);

  /// Whether the option (or flag) was given.
  bool has(std::string_view name) const { return values_.count(std::string(name)) != 0; }
  /// The option's value; throws UsageError "missing -name" when it was not given.
  const std::string& required(std::string_view name) const;
  /// The option's value, or `fallback` when it was not given.
  std::string get(std::string_view name, std::string_view fallback) const;
  /// The option as an integer in [min, max]; `fallback` when not given. The message of a bad
  /// value names the option and the accepted range.
  uint64_t get_count(std::string_view name, uint64_t fallback, uint64_t min, uint64_t max) const;
  /// The option as a finite number in [min, max]; `fallback` when not given.
  double get_number(std::string_view name, double fallback, double min, double max) const;
  /// The positional arguments, in order.
  const std::vector<std::string>& positional() const { return positional_; }
  /// The command these options belong to.
  std::string_view command() const { return command_; }

  /// A UsageError with this message.
  UsageError error(const std::string& message) const;

 private:
  std::string command_;
  std::map<std::string, std::string> values_;
  std::vector<std::string> positional_;
};

}  // namespace rtk::cli
