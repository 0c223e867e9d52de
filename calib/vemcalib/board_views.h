// Views of a checkerboard read from image files, as the commands that fit a model to them read and
// report them (`fisheye`, `plate intrinsics`, `plate pose`): the images loaded (one size and
// format), the board found in each (calib/core/board_detection.h), each view's RMS reprojection
// error printed beside its image, and a fit's refusal naming the image at fault.
#pragma once

#include <expected>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "calib/core/camera_calibration.h"
#include "calib/core/checkerboard.h"
#include "frames/raw_frame.h"

namespace vem::calibtool {

// Images of a checkerboard with the corners the detector found in each.
struct BoardImages {
  std::vector<RawFrame> frames;
  std::vector<std::vector<glm::dvec2>> corners;
  std::vector<std::string> names;
};

// Every image (`bits`-bit codes when given), in order; refused in one sentence unless all share
// the first one's size and format.
[[nodiscard]] std::expected<std::vector<RawFrame>, std::string> loadBoardImages(
    const std::vector<std::string>& images, std::optional<int> bits);

// The board found in each of `frames` (named `names`), those that show it moved into the result;
// an image without it is refused, or left out with a warning when skipMissing.
[[nodiscard]] std::expected<BoardImages, std::string> findBoards(
    std::vector<RawFrame> frames, const std::vector<std::string>& names,
    const calib::Checkerboard& board, bool skipMissing);

// loadBoardImages, then findBoards.
[[nodiscard]] std::expected<BoardImages, std::string> findBoardsInImages(
    const std::vector<std::string>& images, const calib::Checkerboard& board,
    std::optional<int> bits, bool skipMissing);

// Prints each view's RMS reprojection error beside its image, then the whole fit's: "fit: 12
// views, 648 corners: rms reprojection 0.210 px (limit 1 px)".
void printViewFit(std::span<const double> viewRmsPx, const BoardImages& views,
                  const calib::GeometricQuality& quality, double maxRmsPx);

// A fit's refusal as one sentence, naming the image of `view` when there is one (view >= 0):
// "<image>: <message> (nothing was written)".
[[nodiscard]] std::string viewRefusal(int view, const std::string& message,
                                      const BoardImages& views);

}  // namespace vem::calibtool
