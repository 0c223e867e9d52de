// The checkerboard named on vemcalib's command line: --board COLSxROWS counts inner corners (as
// OpenCV's patternSize, e.g. 9x6 for a board of 10 x 7 squares) and --square gives a square's side
// in millimetres (calib/core/checkerboard.h).
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include <CLI/CLI.hpp>

#include "calib/core/checkerboard.h"

namespace vem::calibtool {

// A simulated board's white reads 70 % of the way from the black level to saturation (on every
// channel); its black is kBoardPrintContrast times darker, as matte black and white print
// (`simulate boards`, `simulate plate`).
inline constexpr double kBoardWhiteCodeFraction = 0.7;
inline constexpr double kBoardPrintContrast = 16.0;

// "9x6" (or "9X6") -> 9 inner columns, 6 inner rows; nullopt unless both are whole numbers >= 2.
[[nodiscard]] std::optional<std::pair<int, int>> parseBoardSize(std::string_view text);

// A CLI11 check for --board: one sentence when the text is not COLSxROWS.
[[nodiscard]] CLI::Validator boardSizeValidator();

// "9x6 inner corners, 60 mm squares"
[[nodiscard]] std::string describeBoard(const calib::Checkerboard& board);

}  // namespace vem::calibtool
