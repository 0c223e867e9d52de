#include "calib/io/toml_writer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <type_traits>

#include "util/toml_reader.h"

namespace vem::calib::io::detail {
namespace {

constexpr std::size_t kNoteColumn = 44;  // where the comments beside fields start
constexpr std::size_t kNumbersPerLine = 8;

template <class T>
std::string arrayText(std::span<const T> values) {
  std::string text = "[";
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i > 0) text += ", ";
    if constexpr (std::is_same_v<T, double>) {
      text += tomlNumber(values[i]);
    } else {
      text += std::to_string(values[i]);
    }
  }
  return text + "]";
}

std::string quantityText(std::string_view value, std::string_view unit) {
  return "{ value = " + std::string(value) + ", unit = " + tomlString(unit) + " }";
}

// One row of a long table, its numbers over several lines.
std::string longRowText(std::span<const double> row) {
  std::string text = "  [";
  for (std::size_t i = 0; i < row.size(); ++i) {
    if (i > 0) text += i % kNumbersPerLine == 0 ? ",\n    " : ", ";
    text += tomlNumber(row[i]);
  }
  return text + "]";
}

}  // namespace

std::string tomlNumber(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  std::string text = util::shortestText(value);
  if (text.find_first_of(".e") == std::string::npos) text += ".0";
  return text;
}

std::string tomlString(std::string_view text) {
  std::string out = "\"";
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (byte < 0x20 || byte == 0x7f) {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\u%04x", unsigned(byte));
      out += escaped;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

void TomlWriter::comment(std::string_view text) {
  text_ += text.empty() ? "#\n" : "# " + std::string(text) + "\n";
}

void TomlWriter::table(std::string_view name) { text_ += "\n[" + std::string(name) + "]\n"; }

void TomlWriter::arrayTable(std::string_view name) { text_ += "\n[[" + std::string(name) + "]]\n"; }

void TomlWriter::line(std::string_view key, std::string_view value, std::string_view note) {
  std::string entry = std::string(key) + " = " + std::string(value);
  if (!note.empty()) {
    entry.resize(std::max(entry.size() + 2, kNoteColumn), ' ');
    entry += "# " + std::string(note);
  }
  text_ += entry + "\n";
}

void TomlWriter::string(std::string_view key, std::string_view value, std::string_view note) {
  line(key, tomlString(value), note);
}

void TomlWriter::integer(std::string_view key, std::int64_t value, std::string_view note) {
  line(key, std::to_string(value), note);
}

void TomlWriter::number(std::string_view key, double value, std::string_view note) {
  line(key, tomlNumber(value), note);
}

void TomlWriter::boolean(std::string_view key, bool value, std::string_view note) {
  line(key, value ? "true" : "false", note);
}

void TomlWriter::quantity(std::string_view key, double value, std::string_view unit,
                          std::string_view note) {
  line(key, quantityText(tomlNumber(value), unit), note);
}

void TomlWriter::integerQuantity(std::string_view key, std::int64_t value, std::string_view unit,
                                 std::string_view note) {
  line(key, quantityText(std::to_string(value), unit), note);
}

void TomlWriter::quantity(std::string_view key, std::span<const double> values,
                          std::string_view unit, std::string_view note) {
  line(key, quantityText(arrayText(values), unit), note);
}

void TomlWriter::quantity(std::string_view key, std::span<const std::int64_t> values,
                          std::string_view unit, std::string_view note) {
  line(key, quantityText(arrayText(values), unit), note);
}

void TomlWriter::quantityRows(std::string_view key,
                              const std::vector<std::span<const double>>& rows,
                              std::string_view unit, std::string_view note) {
  if (!note.empty()) comment(std::string(key) + ": " + std::string(note));
  std::string value = "[\n";
  for (const std::span<const double> row : rows) value += longRowText(row) + ",\n";
  line(key, quantityText(value + "]", unit), {});
}

}  // namespace vem::calib::io::detail
