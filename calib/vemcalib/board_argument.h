// The checkerboard named on vemcalib's command line: --board COLSxROWS counts inner corners (as
// OpenCV's patternSize, e.g. 9x6 for a board of 10 x 7 squares) and --square gives a square's side
// in millimetres (calib/core/checkerboard.h); and the options that the commands reading or
// simulating views of a board share, registered once here with one help text each.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

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

// The board of COLSxROWS `size` (already checked by boardSizeValidator) with `squareMm` squares.
[[nodiscard]] calib::Checkerboard boardOf(const std::string& size, double squareMm);

// --board and --square.
struct BoardOptions {
  std::string size;  // COLSxROWS
  double squareMm = 0.0;
};

// A COLSxROWS option (--board, --floor-board), checked by boardSizeValidator.
CLI::Option* addBoardSizeOption(CLI::App* cmd, const std::string& name, std::string& size,
                                const std::string& description);

// --board and --square, both required.
void addBoardOptions(CLI::App* cmd, BoardOptions& o);

// --max-rms: the largest RMS reprojection error accepted, pixels (its default is `maxRmsPx`'s).
CLI::Option* addMaxRmsOption(CLI::App* cmd, double& maxRmsPx);

// --bits: bits per code in 16-bit images (8, 10, 12 or 16), with the command's own description.
CLI::Option* addBitsOption(CLI::App* cmd, std::optional<int>& bits, const std::string& description);

// What a command that fits a model to several images of a checkerboard reads (`fisheye`, `plate
// intrinsics`); the limits' defaults are the fit's.
struct BoardViewOptions {
  BoardViewOptions(double defaultMaxRmsPx, int defaultMinViews)
      : maxRmsPx(defaultMaxRmsPx), minViews(defaultMinViews) {}

  std::vector<std::string> images;
  BoardOptions board;
  double maxRmsPx;
  int minViews;
  std::optional<int> bits;  // else the --out file's, else the images' depth
  bool skipMissing = false;
};

// --image FILE ..., --board and --square, all required: what the command's help lists first.
void addBoardViewOptions(CLI::App* cmd, BoardViewOptions& o);

// --max-rms, --min-views, --bits and --skip-missing: what its help lists after its own options.
void addBoardViewLimitOptions(CLI::App* cmd, BoardViewOptions& o);

// --views (described by `viewsDescription`), --seed and --noise of the commands that simulate
// views of a board (`simulate boards`, `simulate plate`); the defaults are the values given.
void addSimulatedViewOptions(CLI::App* cmd, const std::string& viewsDescription, int& views,
                             std::uint64_t& seed, double& noiseCode);

}  // namespace vem::calibtool
