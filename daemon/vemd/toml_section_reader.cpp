#include "vemd/toml_section_reader.h"

#include <charconv>
#include <cmath>

#include <fmt/format.h>

namespace vem::vemd {

namespace {

std::string shortest(double value) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

}  // namespace

std::string describeTomlNode(const toml::node& node) {
  switch (node.type()) {
    case toml::node_type::table: return "a table";
    case toml::node_type::array: return "an array";
    case toml::node_type::string: return fmt::format("the string \"{}\"", node.as_string()->get());
    case toml::node_type::integer: return fmt::format("the integer {}", node.as_integer()->get());
    case toml::node_type::floating_point:
      return "the number " + shortest(node.as_floating_point()->get());
    case toml::node_type::boolean: return node.as_boolean()->get() ? "true" : "false";
    case toml::node_type::date: return "a date";
    case toml::node_type::time: return "a time";
    case toml::node_type::date_time: return "a date-time";
    case toml::node_type::none: break;
  }
  return "nothing";
}

TomlSectionReader::TomlSectionReader(const toml::table& table, std::string section,
                                     ConfigStatus& status)
    : table_(&table), section_(std::move(section)), status_(&status) {}

std::string TomlSectionReader::field(std::string_view key) const {
  return section_.empty() ? std::string(key) : fmt::format("{}.{}", section_, key);
}

void TomlSectionReader::fail(std::string_view key, std::string_view expected,
                             std::string_view found) {
  if (!status_->ok()) return;
  status_->failure =
      fmt::format("{}: {}: expected {}, found {}", status_->source, field(key), expected, found);
}

void TomlSectionReader::onlyKeys(std::span<const std::string_view> known) {
  for (const auto& [key, node] : *table_) {
    bool listed = false;
    for (std::string_view k : known) listed = listed || k == key.str();
    if (listed || !status_->ok()) continue;
    std::string list;
    for (std::string_view k : known) list += (list.empty() ? "" : ", ") + std::string(k);
    status_->failure = fmt::format("{}: {}: unknown {} (expected one of: {})", status_->source,
                                   field(key.str()), node.is_table() ? "section" : "key", list);
  }
}

const toml::node* TomlSectionReader::find(std::string_view key) const {
  if (!status_->ok()) return nullptr;
  return table_->get(key);
}

std::string TomlSectionReader::numberText(const toml::node& node) {
  if (node.is_integer()) return std::to_string(node.as_integer()->get());
  return shortest(node.as_floating_point()->get());
}

void TomlSectionReader::wholeNumber(std::string_view key, std::int64_t min, std::int64_t max,
                                    std::int64_t& out, std::string_view why) {
  const toml::node* node = find(key);
  if (node == nullptr) return;
  std::string expected = fmt::format("a whole number from {} to {}", min, max);
  if (!why.empty()) expected += fmt::format(" ({})", why);
  if (!node->is_integer()) return fail(key, expected, describeTomlNode(*node));
  const std::int64_t value = node->as_integer()->get();
  if (value < min || value > max) return fail(key, expected, std::to_string(value));
  out = value;
}

void TomlSectionReader::number(std::string_view key, double min, double max, double& out) {
  const toml::node* node = find(key);
  if (node == nullptr) return;
  const std::string expected = fmt::format("a number from {} to {}", shortest(min), shortest(max));
  if (!node->is_number()) return fail(key, expected, describeTomlNode(*node));
  const double value =
      node->is_integer() ? double(node->as_integer()->get()) : node->as_floating_point()->get();
  if (!std::isfinite(value) || value < min || value > max) {
    return fail(key, expected, shortest(value));
  }
  out = value;
}

void TomlSectionReader::boolean(std::string_view key, bool& out) {
  const toml::node* node = find(key);
  if (node == nullptr) return;
  if (!node->is_boolean()) return fail(key, "true or false", describeTomlNode(*node));
  out = node->as_boolean()->get();
}

void TomlSectionReader::text(std::string_view key, std::string& out) {
  const toml::node* node = find(key);
  if (node == nullptr) return;
  if (!node->is_string()) return fail(key, "a string", describeTomlNode(*node));
  out = node->as_string()->get();
}

void TomlSectionReader::choice(std::string_view key, const std::vector<std::string_view>& names,
                               std::size_t& out) {
  const toml::node* node = find(key);
  if (node == nullptr) return;
  if (node->is_string()) {
    for (std::size_t i = 0; i < names.size(); ++i) {
      if (names[i] == node->as_string()->get()) {
        out = i;
        return;
      }
    }
  }
  std::string list;
  for (std::size_t i = 0; i < names.size(); ++i) {
    list +=
        fmt::format("{}\"{}\"", i == 0 ? "" : (i + 1 == names.size() ? " or " : ", "), names[i]);
  }
  fail(key, list, describeTomlNode(*node));
}

}  // namespace vem::vemd
