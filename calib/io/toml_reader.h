// Reading the calibration TOML files (internal to vem_calibio): typed fields, quantities with
// units, and one sentence naming the file and the field for the first thing that is wrong.
//
// Conventions: a quantity is an inline table { value = ..., unit = "..." } whose unit must be the
// one the field names ("deg" fields also take "rad", converted). Numbers may be written as integers
// or floats and must be finite. Every table is read with onlyKeys(), so a misspelt key or section
// is refused instead of being ignored.
//
// All FieldReaders of one file share one ReadStatus and stop at its first failure: later reads
// return a default and record nothing, so a parser reads straight through and checks once.
#pragma once

#include <cstddef>
#include <cstdint>
#include <expected>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <toml++/toml.h>

#include "calib/io/calib_file_failure.h"

namespace vem::calib::io::detail {

struct ReadStatus {
  std::string source;  // the file's name as given, first in every message
  std::optional<CalibFileFailure> failure;
  [[nodiscard]] bool ok() const { return !failure.has_value(); }
};

// The document, or "<source>: line L, column C: not valid TOML (<why>)".
[[nodiscard]] std::expected<toml::table, CalibFileFailure> parseToml(const std::string& text,
                                                                     const std::string& source);

// How many values a per-channel or fixed-size array must hold, and why ("one per channel of
// RGB12").
struct ArrayShape {
  std::size_t count = 1;
  std::string_view reason;
};

class FieldReader {
 public:
  // `prefix` is written before every key in messages: "camera." or "patch \"p3\": ".
  FieldReader(const toml::table& table, std::string prefix, ReadStatus& status);

  [[nodiscard]] bool ok() const { return status_->ok(); }
  [[nodiscard]] bool has(std::string_view key) const { return table_->contains(key); }
  [[nodiscard]] std::string field(std::string_view key) const { return prefix_ + std::string(key); }

  // Refuses any key not listed.
  void onlyKeys(std::initializer_list<std::string_view> known);

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
  [[nodiscard]] FieldReader section(std::string_view key);
  [[nodiscard]] std::optional<FieldReader> optionalSection(std::string_view key);
  // The array of tables [[key]] (required); the caller reads each table with its own FieldReader
  // on the same ReadStatus.
  [[nodiscard]] const toml::array* tableArray(std::string_view key);

  // Records `what` about `key` as the failure (unless there is one already).
  void fail(std::string_view key, CalibFileError cause, std::string_view what);
  // Records a BadValue failure when `condition` is false.
  void require(bool condition, std::string_view key, std::string_view what);

 private:
  [[nodiscard]] bool givenInRadians(std::string_view key) const;
  [[nodiscard]] const toml::node* required(std::string_view key, std::string_view expected);
  [[nodiscard]] const toml::node* quantityValue(std::string_view key, std::string_view unit,
                                                std::string_view valueShape);
  [[nodiscard]] std::optional<double> numberOf(const toml::node& node, std::string_view key,
                                               std::string_view expected);
  [[nodiscard]] const toml::array* arrayOf(const toml::node& node, std::string_view key,
                                           ArrayShape shape);

  const toml::table* table_;
  std::string prefix_;
  ReadStatus* status_;
};

// "a string", "an integer", "an array"... for "found ..." in messages.
[[nodiscard]] std::string describeNode(const toml::node& node);

// The shortest text that reads back as exactly `value` ("95", "0.1", "1e-07").
[[nodiscard]] std::string shortestText(double value);

}  // namespace vem::calib::io::detail
