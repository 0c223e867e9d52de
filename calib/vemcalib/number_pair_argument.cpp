#include "number_pair_argument.h"

#include <charconv>
#include <cmath>

#include <fmt/format.h>

namespace vem::calibtool {
namespace {

std::optional<double> number(std::string_view text) {
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc{} || end != text.data() + text.size() || !std::isfinite(value))
    return std::nullopt;
  return value;
}

}  // namespace

std::optional<std::pair<double, double>> parseNumberPair(std::string_view text) {
  const std::size_t comma = text.find(',');
  if (comma == std::string_view::npos) return std::nullopt;
  const std::optional<double> a = number(text.substr(0, comma));
  const std::optional<double> b = number(text.substr(comma + 1));
  if (!a || !b) return std::nullopt;
  return std::pair{*a, *b};
}

CLI::Validator numberPairValidator(std::string names) {
  return CLI::Validator(
      [names](std::string& text) -> std::string {
        if (parseNumberPair(text)) return {};
        return fmt::format("expected two numbers {} separated by a comma, not \"{}\"", names, text);
      },
      names);
}

}  // namespace vem::calibtool
