// TomlSectionReader: reads one section of vemd's TOML configuration into typed values, checking
// each value's type and range, and refusing keys it does not know. The first problem becomes the
// one sentence the user sees: "FILE: section.key: expected ..., found ...".
//
// All readers of one file share a ConfigStatus and stop at its first failure: later reads leave
// their targets untouched, so a loader reads straight through and checks once.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <toml++/toml.h>

namespace vem::vemd {

struct ConfigStatus {
  std::string source;                  // the file's name, first in every message
  std::optional<std::string> failure;  // the first problem
  [[nodiscard]] bool ok() const { return !failure.has_value(); }
};

// "the string \"x\"", "the integer 3", "the number 0.5", "true", "a table", ...
[[nodiscard]] std::string describeTomlNode(const toml::node& node);

class TomlSectionReader {
 public:
  // `section` prefixes every key in messages ("source" gives "source.rate").
  TomlSectionReader(const toml::table& table, std::string section, ConfigStatus& status);

  void onlyKeys(std::span<const std::string_view> known);

  // `why`, when given, says what the range protects, after it in the message: "expected a whole
  // number from 4 to 4096 (start-up time and memory grow with map_width x map_height), found
  // 16384".
  void wholeNumber(std::string_view key, std::int64_t min, std::int64_t max, std::int64_t& out,
                   std::string_view why = {});
  template <typename Int>
  void wholeNumber(std::string_view key, std::int64_t min, std::int64_t max, Int& out,
                   std::string_view why = {}) {
    std::int64_t value = std::int64_t(out);
    wholeNumber(key, min, max, value, why);
    out = Int(value);
  }
  void number(std::string_view key, double min, double max, double& out);
  void boolean(std::string_view key, bool& out);
  void text(std::string_view key, std::string& out);
  // One of `names` (their index into `out`), e.g. {"havran", "standard"}.
  void choice(std::string_view key, const std::vector<std::string_view>& names, std::size_t& out);
  // A string `parse` accepts; `expected` describes what it accepts.
  template <typename T, typename Parse>
  void parsed(std::string_view key, std::string_view expected, Parse parse, T& out) {
    const toml::node* node = find(key);
    if (node == nullptr) return;
    if (node->is_string()) {
      if (auto value = parse(node->as_string()->get())) {
        out = *value;
        return;
      }
    } else if (node->is_number()) {
      if (auto value = parse(numberText(*node))) {
        out = *value;
        return;
      }
    }
    fail(key, expected, describeTomlNode(*node));
  }

  void fail(std::string_view key, std::string_view expected, std::string_view found);
  [[nodiscard]] std::string field(std::string_view key) const;

 private:
  [[nodiscard]] const toml::node* find(std::string_view key) const;
  [[nodiscard]] static std::string numberText(const toml::node& node);

  const toml::table* table_;
  std::string section_;
  ConfigStatus* status_;
};

}  // namespace vem::vemd
