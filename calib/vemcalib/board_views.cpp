#include "board_views.h"

#include <utility>

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "calib/core/board_detection.h"
#include "calib/io/raw_frame_file.h"
#include "frame_arguments.h"

namespace vem::calibtool {

std::expected<std::vector<RawFrame>, std::string> loadBoardImages(
    const std::vector<std::string>& images, std::optional<int> bits) {
  std::vector<RawFrame> frames;
  for (const std::string& image : images) {
    auto frame = calib::io::loadRawFrame(image, bits);
    if (!frame) return std::unexpected(frame.error().message);
    const RawFrame& first = frames.empty() ? *frame : frames.front();
    if (frame->width != first.width || frame->height != first.height ||
        frame->format != first.format)
      return std::unexpected(
          fmt::format("{}: the image is {} but {} is {} (every --image must share size and format)",
                      image, describeFrame(*frame), images.front(), describeFrame(first)));
    frames.push_back(std::move(*frame));
  }
  return frames;
}

std::expected<BoardImages, std::string> findBoards(std::vector<RawFrame> frames,
                                                   const std::vector<std::string>& names,
                                                   const calib::Checkerboard& board,
                                                   bool skipMissing) {
  BoardImages found;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    std::optional<std::vector<glm::dvec2>> corners = calib::detectCheckerboard(frames[i], board);
    if (!corners) {
      const std::string what = fmt::format("{}: no {}x{} checkerboard was found", names[i],
                                           board.innerCols, board.innerRows);
      if (!skipMissing) return std::unexpected(what + " (--skip-missing leaves such images out)");
      spdlog::warn("{}; skipped (--skip-missing)", what);
      continue;
    }
    spdlog::info("{}: found the board", names[i]);
    found.frames.push_back(std::move(frames[i]));
    found.corners.push_back(std::move(*corners));
    found.names.push_back(names[i]);
  }
  return found;
}

std::expected<BoardImages, std::string> findBoardsInImages(const std::vector<std::string>& images,
                                                           const calib::Checkerboard& board,
                                                           std::optional<int> bits,
                                                           bool skipMissing) {
  auto frames = loadBoardImages(images, bits);
  if (!frames) return std::unexpected(frames.error());
  return findBoards(std::move(*frames), images, board, skipMissing);
}

void printViewFit(std::span<const double> viewRmsPx, const BoardImages& views,
                  const calib::GeometricQuality& quality, double maxRmsPx) {
  fmt::print("view  rms px  image\n");
  for (std::size_t v = 0; v < viewRmsPx.size(); ++v)
    fmt::print("{:>4}  {:>6.3f}  {}\n", v, viewRmsPx[v], views.names[v]);
  fmt::print("fit: {} views, {} corners: rms reprojection {:.3f} px (limit {:g} px)\n",
             quality.views, quality.corners, quality.rmsReprojectionPx, maxRmsPx);
}

std::string viewRefusal(int view, const std::string& message, const BoardImages& views) {
  const std::string sentence = view >= 0 && std::size_t(view) < views.names.size()
                                   ? fmt::format("{}: {}", views.names[std::size_t(view)], message)
                                   : message;
  return sentence + " (nothing was written)";
}

}  // namespace vem::calibtool
