// TomlReader: reads the tables of a TOML file (toml++) into typed values, checking each value's
// type, range and unit, and refusing keys it does not know. The first problem becomes the one
// sentence the user sees: "FILE: section.key: expected ..., found ...". Used by the calibration
// files (calib/io) and by vemd's configuration (daemon/vemd).
//
// Conventions: a quantity is an inline table { value = ..., unit = "..." } whose unit must be the
// one the field names ("deg" fields also take "rad", converted). Numbers may be written as integers
// or floats and must be finite.
//
// Two kinds of field: a required one returns its value (a default after a failure, recorded as
// MissingField when absent); an `optional*` one leaves its target as it was when the key is absent,
// so the target's default stands.
//
// All readers of one file share one TomlStatus and stop at its first failure: later reads return
// a default (or leave their target alone) and record nothing, so a parser reads straight through
// and checks once.
#pragma once

#include <cstddef>
#include <cstdint>
#include <expected>
#include <initializer_list>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <toml++/toml.h>

#include "util/toml_failure.h"

namespace vem::util {

struct TomlStatus {
  std::string source;  // the file's name as given, first in every message
  std::optional<TomlFailure> failure;
  [[nodiscard]] bool ok() const { return !failure.has_value(); }
};

// The document, or "<source>: line L, column C: not valid TOML (<why>)" (BadSyntax).
[[nodiscard]] std::expected<toml::table, TomlFailure> parseToml(const std::string& text,
                                                                const std::string& source);

// "a table", "an array", "the string \"x\"", "the integer 3", "the number 0.5", "true", ... for
// "found ..." in messages.
[[nodiscard]] std::string describeTomlNode(const toml::node& node);

// The shortest text that reads back as exactly `value` ("95", "0.1", "1e-07").
[[nodiscard]] std::string shortestText(double value);

// How many values a per-channel or fixed-size array must hold, and why ("one per channel of
// RGB12").
struct ArrayShape {
  std::size_t count = 1;
  std::string_view reason;
};

// How an unknown key is named in the message: "unknown field", or "unknown key" / "unknown
// section" after what it holds.
enum class UnknownKeyWords { Field, KeyOrSection };

class TomlReader {
 public:
  // `prefix` is written before every key in messages: "camera.", "patch \"p3\": " or "" (top).
  TomlReader(const toml::table& table, std::string prefix, TomlStatus& status);

  [[nodiscard]] bool ok() const { return status_->ok(); }
  [[nodiscard]] bool has(std::string_view key) const { return table_->contains(key); }
  [[nodiscard]] std::string field(std::string_view key) const { return prefix_ + std::string(key); }

  // Refuses any key not listed: "<field>: unknown field (expected one of: a, b)".
  void onlyKeys(std::span<const std::string_view> known,
                UnknownKeyWords words = UnknownKeyWords::Field);
  void onlyKeys(std::initializer_list<std::string_view> known,
                UnknownKeyWords words = UnknownKeyWords::Field) {
    onlyKeys(std::span(known.begin(), known.size()), words);
  }

  // ---- required fields ----
  [[nodiscard]] std::string string(std::string_view key);
  // A string, or a TOML date-time turned into its ISO 8601 text.
  [[nodiscard]] std::string dateText(std::string_view key);
  [[nodiscard]] std::int64_t integer(std::string_view key, std::int64_t min, std::int64_t max);
  [[nodiscard]] double number(std::string_view key);
  [[nodiscard]] bool boolean(std::string_view key, bool fallback);  // optional: fallback if absent

  [[nodiscard]] double quantity(std::string_view key, std::string_view unit);
  [[nodiscard]] std::int64_t integerQuantity(std::string_view key, std::string_view unit,
                                             std::int64_t min, std::int64_t max);
  [[nodiscard]] std::vector<double> quantityArray(std::string_view key, std::string_view unit,
                                                  ArrayShape shape);
  [[nodiscard]] std::vector<std::int64_t> integerQuantityArray(std::string_view key,
                                                               std::string_view unit,
                                                               ArrayShape shape);
  // { value = [[...], ...], unit = ... }: `rows` arrays of `columns` numbers each.
  [[nodiscard]] std::vector<std::vector<double>> quantityRows(std::string_view key,
                                                              std::string_view unit,
                                                              ArrayShape rows, ArrayShape columns);
  // An angle in "deg" or "rad", returned in degrees or in radians (a value given in the unit
  // asked for comes back unchanged).
  [[nodiscard]] double angleDeg(std::string_view key);
  [[nodiscard]] double angleRad(std::string_view key);

  // A required sub-table (after a failure: a reader of an empty table), or an optional one.
  [[nodiscard]] TomlReader section(std::string_view key);
  [[nodiscard]] std::optional<TomlReader> optionalSection(std::string_view key);
  // The array of tables [[key]] (required); the caller reads each table with its own TomlReader
  // on the same TomlStatus.
  [[nodiscard]] const toml::array* tableArray(std::string_view key);

  // ---- optional fields: `out` keeps its value when the key is absent ----
  // `why`, when given, says what the range protects, after it in the message: "expected a whole
  // number from 4 to 4096 (start-up time and memory grow with map_width x map_height), found
  // 16384".
  void optionalWholeNumber(std::string_view key, std::int64_t min, std::int64_t max,
                           std::int64_t& out, std::string_view why = {});
  template <typename Int>
  void optionalWholeNumber(std::string_view key, std::int64_t min, std::int64_t max, Int& out,
                           std::string_view why = {}) {
    std::int64_t value = std::int64_t(out);
    optionalWholeNumber(key, min, max, value, why);
    out = Int(value);
  }
  void optionalNumber(std::string_view key, double min, double max, double& out);
  void optionalBoolean(std::string_view key, bool& out);
  void optionalText(std::string_view key, std::string& out);
  // One of `names` (their index into `out`), e.g. {"havran", "standard"}.
  void optionalChoice(std::string_view key, const std::vector<std::string_view>& names,
                      std::size_t& out);
  // A string (or a number, as its text) that `parse` accepts; `expected` describes what it
  // accepts.
  template <typename T, typename Parse>
  void optionalParsed(std::string_view key, std::string_view expected, Parse parse, T& out) {
    const toml::node* node = ok() ? table_->get(key) : nullptr;
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
    failExpected(key, expected, describeTomlNode(*node));
  }

  // ---- failures ----
  // Records "<source>: <field>: <what>" as the failure (unless there is one already).
  void fail(std::string_view key, TomlProblem cause, std::string_view what);
  // Records a BadValue failure when `condition` is false.
  void require(bool condition, std::string_view key, std::string_view what);
  // Records "<source>: <field>: expected <expected>, found <found>" (BadValue).
  void failExpected(std::string_view key, std::string_view expected, std::string_view found);

 private:
  [[nodiscard]] bool givenInRadians(std::string_view key) const;
  [[nodiscard]] const toml::node* required(std::string_view key, std::string_view expected);
  [[nodiscard]] const toml::node* quantityValue(std::string_view key, std::string_view unit,
                                                std::string_view valueShape);
  [[nodiscard]] std::optional<double> numberOf(const toml::node& node, std::string_view key,
                                               std::string_view expected);
  [[nodiscard]] const toml::array* arrayOf(const toml::node& node, std::string_view key,
                                           ArrayShape shape);
  [[nodiscard]] static std::string numberText(const toml::node& node);

  const toml::table* table_;
  std::string prefix_;
  TomlStatus* status_;
};

}  // namespace vem::util
