#include "board_argument.h"

#include <charconv>

#include <fmt/format.h>

#include "util/cli_value_names.h"

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

calib::Checkerboard boardOf(const std::string& size, double squareMm) {
  const auto [cols, rows] = *parseBoardSize(size);  // validated by CLI11
  return {cols, rows, squareMm};
}

CLI::Option* addBoardSizeOption(CLI::App* cmd, const std::string& name, std::string& size,
                                const std::string& description) {
  return cmd->add_option(name, size, description)
      ->type_name("COLSxROWS")
      ->check(help::quiet(boardSizeValidator()));
}

void addBoardOptions(CLI::App* cmd, BoardOptions& o) {
  addBoardSizeOption(cmd, "--board", o.size,
                     "Inner corners per row and column: COLSxROWS, e.g. 9x6")
      ->required();
  cmd->add_option("--square", o.squareMm, "Side of a square, mm")
      ->required()
      ->check(help::quiet(CLI::PositiveNumber));
}

CLI::Option* addMaxRmsOption(CLI::App* cmd, double& maxRmsPx) {
  return cmd->add_option("--max-rms", maxRmsPx, "Largest RMS reprojection error accepted, pixels")
      ->capture_default_str()
      ->check(help::quiet(CLI::PositiveNumber));
}

CLI::Option* addBitsOption(CLI::App* cmd, std::optional<int>& bits,
                           const std::string& description) {
  return cmd->add_option("--bits", bits, description)->check(CLI::IsMember({8, 10, 12, 16}));
}

void addBoardViewOptions(CLI::App* cmd, BoardViewOptions& o) {
  cmd->add_option("--image", o.images, "Images of the checkerboard: FILE ...")->required();
  addBoardOptions(cmd, o.board);
}

void addBoardViewLimitOptions(CLI::App* cmd, BoardViewOptions& o) {
  addMaxRmsOption(cmd, o.maxRmsPx);
  cmd->add_option("--min-views", o.minViews, "Fewest views with a board accepted")
      ->capture_default_str()
      ->type_name(help::rangeName(1, 1000))
      ->check(help::quiet(CLI::Range(1, 1000)));
  addBitsOption(cmd, o.bits,
                "Bits per code in 16-bit images, e.g. 12 (default: the --out file's, else the "
                "image's depth)");
  cmd->add_flag("--skip-missing", o.skipMissing,
                "Leave out images without the board (with a warning) instead of refusing");
}

void addSimulatedViewOptions(CLI::App* cmd, const std::string& viewsDescription, int& views,
                             std::uint64_t& seed, double& noiseCode) {
  cmd->add_option("--views", views, viewsDescription)
      ->capture_default_str()
      ->type_name(help::rangeName(1, 100))
      ->check(help::quiet(CLI::Range(1, 100)));
  cmd->add_option("--seed", seed, "Random seed (the same seed gives the same views)")
      ->capture_default_str();
  cmd->add_option("--noise", noiseCode, "Read noise, codes (standard deviation)")
      ->capture_default_str()
      ->check(help::quiet(CLI::NonNegativeNumber));
}

}  // namespace vem::calibtool
