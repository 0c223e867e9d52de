// PreviewSink: every Nth processed frame, a PNG of the polar map with the published lights
// (published_lights.h) and their clusters marked (preview_image.h), for a person to glance at.
//
// - Frames are counted as consumed: the 1st, the (N+1)th, ... are drawn (N = `every` >= 1).
// - The image goes to `dir`/preview.png, replaced atomically (written to a temporary file in the
//   same folder, then renamed over it), so a viewer never reads half an image. With `numbered`, a
//   copy also goes to `dir`/preview-SSSSSSSSSS.png (the captured frame's seq, ten digits).
// - A frame without a polar map is skipped (not counted as drawn).
// - A failure (folder gone, disk full) is returned once as a SinkFailure; the sink then does
//   nothing (the last good preview.png stays).
#pragma once

#include <cstdint>
#include <expected>
#include <filesystem>
#include <string>
#include <vector>

#include "frames/sink.h"
#include "vemd/sinks/preview_image.h"

namespace vem::vemd {

struct PreviewOptions {
  int every = 30;  // draw one frame in `every`
  bool numbered = false;
  PreviewStyle style;
};

class PreviewSink final : public Sink {
 public:
  // Creates `dir` (and its parents) when missing.
  [[nodiscard]] static std::expected<PreviewSink, SinkFailure> create(
      const std::filesystem::path& dir, PreviewOptions options);

  [[nodiscard]] std::string name() const override { return "preview"; }
  [[nodiscard]] std::expected<void, SinkFailure> consume(const ProcessedFrame& frame) override;
  [[nodiscard]] std::expected<void, SinkFailure> close() override { return {}; }

  [[nodiscard]] std::filesystem::path latestPath() const { return dir_ / "preview.png"; }
  [[nodiscard]] std::filesystem::path numberedPath(std::uint64_t seq) const;
  [[nodiscard]] std::uint64_t imagesWritten() const { return images_; }

 private:
  PreviewSink(std::filesystem::path dir, PreviewOptions options);

  std::filesystem::path dir_;
  PreviewOptions options_;
  std::uint64_t frames_ = 0;
  std::uint64_t images_ = 0;
  bool failed_ = false;
};

}  // namespace vem::vemd
