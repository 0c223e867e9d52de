#include "board_argument.h"

#include <charconv>

#include <fmt/format.h>

namespace vem::calibtool {
namespace {

std::optional<int> wholeNumber(std::string_view text) {
  int value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc{} || end != text.data() + text.size()) return std::nullopt;
  return value;
}

}  // namespace

std::optional<std::pair<int, int>> parseBoardSize(std::string_view text) {
  const std::size_t x = text.find_first_of("xX");
  if (x == std::string_view::npos) return std::nullopt;
  const std::optional<int> cols = wholeNumber(text.substr(0, x));
  const std::optional<int> rows = wholeNumber(text.substr(x + 1));
  if (!cols || !rows || *cols < 2 || *rows < 2) return std::nullopt;
  return std::pair{*cols, *rows};
}

CLI::Validator boardSizeValidator() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        if (parseBoardSize(text)) return {};
        return fmt::format(
            "expected COLSxROWS, the inner corners per row and per column (e.g. 9x6), each at "
            "least 2, not \"{}\"",
            text);
      },
      "COLSxROWS");
}

std::string describeBoard(const calib::Checkerboard& board) {
  return fmt::format("{}x{} inner corners, {:g} mm squares", board.innerCols, board.innerRows,
                     board.squareMm);
}

}  // namespace vem::calibtool
