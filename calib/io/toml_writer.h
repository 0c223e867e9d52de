// Writing the calibration TOML files (internal to vem_calibio): keys in a chosen order, quantities
// as { value = ..., unit = "..." }, numbers in their shortest round-trip form, and a comment beside
// each field for the people who read the file.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace vem::calib::io::detail {

// A TOML float that reads back as exactly `value` (finite): "1.0", "0.1", "1e-07".
[[nodiscard]] std::string tomlNumber(double value);
// A TOML basic string with the quotes, escaped as needed.
[[nodiscard]] std::string tomlString(std::string_view text);

class TomlWriter {
 public:
  void comment(std::string_view text);     // "# text"
  void table(std::string_view name);       // a blank line, then "[name]"
  void arrayTable(std::string_view name);  // a blank line, then "[[name]]"

  void string(std::string_view key, std::string_view value, std::string_view note = {});
  void integer(std::string_view key, std::int64_t value, std::string_view note = {});
  void number(std::string_view key, double value, std::string_view note = {});
  void boolean(std::string_view key, bool value, std::string_view note = {});
  void quantity(std::string_view key, double value, std::string_view unit,
                std::string_view note = {});
  void integerQuantity(std::string_view key, std::int64_t value, std::string_view unit,
                       std::string_view note = {});
  void quantity(std::string_view key, std::span<const double> values, std::string_view unit,
                std::string_view note = {});
  void quantity(std::string_view key, std::span<const std::int64_t> values, std::string_view unit,
                std::string_view note = {});
  // Long rows (tables of thousands of values) are broken over lines, 8 numbers a line.
  void quantityRows(std::string_view key, const std::vector<std::span<const double>>& rows,
                    std::string_view unit, std::string_view note = {});

  [[nodiscard]] const std::string& text() const { return text_; }

 private:
  void line(std::string_view key, std::string_view value, std::string_view note);
  std::string text_;
};

}  // namespace vem::calib::io::detail
