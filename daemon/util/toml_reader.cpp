#include "util/toml_reader.h"

#include <charconv>
#include <cmath>
#include <numbers>
#include <sstream>
#include <utility>

#include <fmt/format.h>

namespace vem::util {
namespace {

// fmt rather than operator+ chains: GCC 12 at -O3 warns falsely (-Wrestrict) on the latter.
std::string quoted(std::string_view text) { return fmt::format("\"{}\"", text); }

std::string quantityShape(std::string_view valueShape, std::string_view unit) {
  return "{ value = " + std::string(valueShape) + ", unit = " + quoted(unit) + " }";
}

std::string countText(std::size_t count, std::string_view noun) {
  return std::to_string(count) + " " + std::string(noun) + (count == 1 ? "" : "s");
}

const toml::table& emptyTable() {
  static const toml::table empty;
  return empty;
}

}  // namespace

std::expected<toml::table, TomlFailure> parseToml(const std::string& text,
                                                  const std::string& source) {
  try {
    return toml::parse(text, source);
  } catch (const toml::parse_error& e) {
    const auto& begin = e.source().begin;
    return std::unexpected(TomlFailure{
        TomlProblem::BadSyntax, fmt::format("{}: line {}, column {}: not valid TOML ({})", source,
                                            begin.line, begin.column, e.description())});
  }
}

std::string describeTomlNode(const toml::node& node) {
  switch (node.type()) {
    case toml::node_type::table: return "a table";
    case toml::node_type::array: return "an array";
    case toml::node_type::string: return "the string " + quoted(node.as_string()->get());
    case toml::node_type::integer: return "the integer " + std::to_string(node.as_integer()->get());
    case toml::node_type::floating_point:
      return "the number " + shortestText(node.as_floating_point()->get());
    case toml::node_type::boolean: return node.as_boolean()->get() ? "true" : "false";
    case toml::node_type::date: return "a date";
    case toml::node_type::time: return "a time";
    case toml::node_type::date_time: return "a date-time";
    case toml::node_type::none: break;
  }
  return "nothing";
}

std::string shortestText(double value) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

TomlReader::TomlReader(const toml::table& table, std::string prefix, TomlStatus& status)
    : table_(&table), prefix_(std::move(prefix)), status_(&status) {}

void TomlReader::fail(std::string_view key, TomlProblem cause, std::string_view what) {
  if (!ok()) return;
  status_->failure =
      TomlFailure{cause, fmt::format("{}: {}: {}", status_->source, field(key), what)};
}

void TomlReader::require(bool condition, std::string_view key, std::string_view what) {
  if (!condition) fail(key, TomlProblem::BadValue, what);
}

void TomlReader::onlyKeys(std::span<const std::string_view> known, UnknownKeyWords words) {
  for (const auto& [key, node] : *table_) {
    bool listed = false;
    for (std::string_view k : known) listed = listed || key.str() == k;
    if (listed) continue;
    std::string expected;
    for (std::string_view k : known) expected += (expected.empty() ? "" : ", ") + std::string(k);
    const std::string_view noun = words == UnknownKeyWords::Field ? "field"
                                  : node.is_table()               ? "section"
                                                                  : "key";
    fail(key.str(), TomlProblem::BadValue,
         fmt::format("unknown {} (expected one of: {})", noun, expected));
    return;
  }
}

void TomlReader::failExpected(std::string_view key, std::string_view expected,
                              std::string_view found) {
  fail(key, TomlProblem::BadValue, fmt::format("expected {}, found {}", expected, found));
}

std::string TomlReader::numberText(const toml::node& node) {
  if (node.is_integer()) return std::to_string(node.as_integer()->get());
  return shortestText(node.as_floating_point()->get());
}

void TomlReader::optionalWholeNumber(std::string_view key, std::int64_t min, std::int64_t max,
                                     std::int64_t& out, std::string_view why) {
  const toml::node* node = ok() ? table_->get(key) : nullptr;
  if (node == nullptr) return;
  std::string expected = fmt::format("a whole number from {} to {}", min, max);
  if (!why.empty()) expected += fmt::format(" ({})", why);
  if (!node->is_integer()) return failExpected(key, expected, describeTomlNode(*node));
  const std::int64_t value = node->as_integer()->get();
  if (value < min || value > max) return failExpected(key, expected, std::to_string(value));
  out = value;
}

void TomlReader::optionalNumber(std::string_view key, double min, double max, double& out) {
  const toml::node* node = ok() ? table_->get(key) : nullptr;
  if (node == nullptr) return;
  const std::string expected =
      fmt::format("a number from {} to {}", shortestText(min), shortestText(max));
  if (!node->is_number()) return failExpected(key, expected, describeTomlNode(*node));
  const double value =
      node->is_integer() ? double(node->as_integer()->get()) : node->as_floating_point()->get();
  if (!std::isfinite(value) || value < min || value > max) {
    return failExpected(key, expected, shortestText(value));
  }
  out = value;
}

void TomlReader::optionalBoolean(std::string_view key, bool& out) {
  const toml::node* node = ok() ? table_->get(key) : nullptr;
  if (node == nullptr) return;
  if (!node->is_boolean()) return failExpected(key, "true or false", describeTomlNode(*node));
  out = node->as_boolean()->get();
}

void TomlReader::optionalText(std::string_view key, std::string& out) {
  const toml::node* node = ok() ? table_->get(key) : nullptr;
  if (node == nullptr) return;
  if (!node->is_string()) return failExpected(key, "a string", describeTomlNode(*node));
  out = node->as_string()->get();
}

void TomlReader::optionalChoice(std::string_view key, const std::vector<std::string_view>& names,
                                std::size_t& out) {
  const toml::node* node = ok() ? table_->get(key) : nullptr;
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
  failExpected(key, list, describeTomlNode(*node));
}

const toml::node* TomlReader::required(std::string_view key, std::string_view expected) {
  if (!ok()) return nullptr;
  const toml::node* node = table_->get(key);
  if (node == nullptr)
    fail(key, TomlProblem::MissingField, "missing (expected " + std::string(expected) + ")");
  return node;
}

std::string TomlReader::string(std::string_view key) {
  const toml::node* node = required(key, "a string");
  if (node == nullptr) return {};
  if (!node->is_string()) {
    fail(key, TomlProblem::BadValue, "expected a string, found " + describeTomlNode(*node));
    return {};
  }
  return node->as_string()->get();
}

std::string TomlReader::dateText(std::string_view key) {
  const toml::node* node = required(key, "an ISO 8601 date such as \"2026-01-31T12:00:00Z\"");
  if (node == nullptr) return {};
  if (node->is_string()) return node->as_string()->get();
  if (node->is_date_time()) {
    std::ostringstream text;
    text << *node->as_date_time();
    return text.str();
  }
  fail(key, TomlProblem::BadValue, "expected a date, found " + describeTomlNode(*node));
  return {};
}

std::int64_t TomlReader::integer(std::string_view key, std::int64_t min, std::int64_t max) {
  const toml::node* node = required(key, "an integer");
  if (node == nullptr) return min;
  if (!node->is_integer()) {
    fail(key, TomlProblem::BadValue, "expected an integer, found " + describeTomlNode(*node));
    return min;
  }
  const std::int64_t value = node->as_integer()->get();
  require(value >= min && value <= max, key,
          "expected an integer from " + std::to_string(min) + " to " + std::to_string(max) +
              ", found " + std::to_string(value));
  return ok() ? value : min;
}

std::optional<double> TomlReader::numberOf(const toml::node& node, std::string_view key,
                                           std::string_view expected) {
  if (!ok()) return std::nullopt;
  double value = 0.0;
  if (node.is_integer()) {
    value = double(node.as_integer()->get());
  } else if (node.is_floating_point()) {
    value = node.as_floating_point()->get();
  } else {
    fail(key, TomlProblem::BadValue,
         "expected " + std::string(expected) + ", found " + describeTomlNode(node));
    return std::nullopt;
  }
  if (!std::isfinite(value)) {
    fail(key, TomlProblem::BadValue, "expected a finite number, found " + shortestText(value));
    return std::nullopt;
  }
  return value;
}

double TomlReader::number(std::string_view key) {
  const toml::node* node = required(key, "a number");
  if (node == nullptr) return 0.0;
  return numberOf(*node, key, "a number").value_or(0.0);
}

bool TomlReader::boolean(std::string_view key, bool fallback) {
  if (!ok() || !has(key)) return fallback;
  const toml::node* node = table_->get(key);
  if (!node->is_boolean()) {
    fail(key, TomlProblem::BadValue, "expected true or false, found " + describeTomlNode(*node));
    return fallback;
  }
  return node->as_boolean()->get();
}

const toml::node* TomlReader::quantityValue(std::string_view key, std::string_view unit,
                                            std::string_view valueShape) {
  const std::string shape = quantityShape(valueShape, unit);
  const toml::node* node = required(key, shape);
  if (node == nullptr) return nullptr;
  const toml::table* quantity = node->as_table();
  if (quantity == nullptr) {
    fail(key, TomlProblem::BadValue, "expected " + shape + ", found " + describeTomlNode(*node));
    return nullptr;
  }
  TomlReader parts(*quantity, field(key) + ".", *status_);
  parts.onlyKeys({"value", "unit"});
  const std::string found = parts.string("unit");
  if (ok() && found != unit)
    fail(key, TomlProblem::WrongUnit, "expected unit " + quoted(unit) + ", found " + quoted(found));
  return ok() ? parts.required("value", valueShape) : nullptr;
}

double TomlReader::quantity(std::string_view key, std::string_view unit) {
  const toml::node* value = quantityValue(key, unit, "<number>");
  if (value == nullptr) return 0.0;
  return numberOf(*value, key, "a number as its value").value_or(0.0);
}

std::int64_t TomlReader::integerQuantity(std::string_view key, std::string_view unit,
                                         std::int64_t min, std::int64_t max) {
  const toml::node* value = quantityValue(key, unit, "<integer>");
  if (value == nullptr) return min;
  if (!value->is_integer()) {
    fail(key, TomlProblem::BadValue,
         "expected a whole number as its value, found " + describeTomlNode(*value));
    return min;
  }
  const std::int64_t found = value->as_integer()->get();
  require(found >= min && found <= max, key,
          "expected a value from " + std::to_string(min) + " to " + std::to_string(max) +
              ", found " + std::to_string(found));
  return ok() ? found : min;
}

const toml::array* TomlReader::arrayOf(const toml::node& node, std::string_view key,
                                       ArrayShape shape) {
  if (!ok()) return nullptr;
  const std::string expected = countText(shape.count, "value") +
                               (shape.reason.empty() ? "" : " (" + std::string(shape.reason) + ")");
  const toml::array* array = node.as_array();
  if (array == nullptr) {
    fail(key, TomlProblem::BadValue,
         "expected an array of " + expected + ", found " + describeTomlNode(node));
  } else if (array->size() != shape.count) {
    fail(key, TomlProblem::BadValue,
         "expected " + expected + ", found " + std::to_string(array->size()));
  }
  return ok() ? array : nullptr;
}

std::vector<double> TomlReader::quantityArray(std::string_view key, std::string_view unit,
                                              ArrayShape shape) {
  const toml::node* value = quantityValue(key, unit, "[<numbers>]");
  const toml::array* array = value != nullptr ? arrayOf(*value, key, shape) : nullptr;
  if (array == nullptr) return std::vector<double>(shape.count, 0.0);
  std::vector<double> values;
  for (const toml::node& element : *array)
    values.push_back(numberOf(element, key, "numbers in its value").value_or(0.0));
  return values;
}

std::vector<std::int64_t> TomlReader::integerQuantityArray(std::string_view key,
                                                           std::string_view unit,
                                                           ArrayShape shape) {
  const toml::node* value = quantityValue(key, unit, "[<integers>]");
  const toml::array* array = value != nullptr ? arrayOf(*value, key, shape) : nullptr;
  std::vector<std::int64_t> values(shape.count, 0);
  if (array == nullptr) return values;
  for (std::size_t i = 0; i < shape.count && ok(); ++i) {
    const toml::node& element = *array->get(i);
    if (element.is_integer()) {
      values[i] = element.as_integer()->get();
    } else {
      fail(key, TomlProblem::BadValue,
           "expected whole numbers in its value, found " + describeTomlNode(element));
    }
  }
  return values;
}

std::vector<std::vector<double>> TomlReader::quantityRows(std::string_view key,
                                                          std::string_view unit, ArrayShape rows,
                                                          ArrayShape columns) {
  std::vector<std::vector<double>> values(rows.count, std::vector<double>(columns.count, 0.0));
  const toml::node* value = quantityValue(key, unit, "[[<numbers>], ...]");
  const toml::array* outer = value != nullptr ? arrayOf(*value, key, rows) : nullptr;
  for (std::size_t r = 0; outer != nullptr && r < rows.count && ok(); ++r) {
    const std::string rowKey = std::string(key) + "[" + std::to_string(r) + "]";
    const toml::array* row = arrayOf(*outer->get(r), rowKey, columns);
    for (std::size_t c = 0; row != nullptr && c < columns.count && ok(); ++c)
      values[r][c] = numberOf(*row->get(c), rowKey, "numbers").value_or(0.0);
  }
  return values;
}

bool TomlReader::givenInRadians(std::string_view key) const {
  const toml::node* node = table_->get(key);
  const toml::table* parts = node != nullptr ? node->as_table() : nullptr;
  const toml::node* unit = parts != nullptr ? parts->get("unit") : nullptr;
  return unit != nullptr && unit->is_string() && unit->as_string()->get() == "rad";
}

double TomlReader::angleDeg(std::string_view key) {
  if (givenInRadians(key)) return quantity(key, "rad") * (180.0 / std::numbers::pi);
  return quantity(key, "deg");
}

double TomlReader::angleRad(std::string_view key) {
  if (givenInRadians(key)) return quantity(key, "rad");
  return quantity(key, "deg") * (std::numbers::pi / 180.0);
}

TomlReader TomlReader::section(std::string_view key) {
  if (std::optional<TomlReader> found = optionalSection(key)) return *found;
  fail(key, TomlProblem::MissingField, "missing section (expected a [" + field(key) + "] table)");
  return TomlReader(emptyTable(), field(key) + ".", *status_);
}

std::optional<TomlReader> TomlReader::optionalSection(std::string_view key) {
  const toml::node* node = ok() ? table_->get(key) : nullptr;
  if (node == nullptr) return std::nullopt;
  if (!node->is_table()) {
    fail(key, TomlProblem::BadValue, "expected a table, found " + describeTomlNode(*node));
    return std::nullopt;
  }
  return TomlReader(*node->as_table(), field(key) + ".", *status_);
}

const toml::array* TomlReader::tableArray(std::string_view key) {
  const toml::node* node = required(key, "[[" + std::string(key) + "]] tables");
  if (node == nullptr) return nullptr;
  const toml::array* array = node->as_array();
  if (array == nullptr || !array->is_array_of_tables()) {
    fail(key, TomlProblem::BadValue,
         "expected [[" + std::string(key) + "]] tables, found " + describeTomlNode(*node));
    return nullptr;
  }
  return array;
}

}  // namespace vem::util
