// FrameWriter: vemview's headless output in --out DIR: each drawn frame as frame-NNNNNN.png
// (tone-mapped, 8-bit sRGB) and frame-NNNNNN.exr (linear radiance, 32-bit float), and one JSON line
// per frame in timing.jsonl (times in ms). A frame the plan did not redraw (nothing changed) gets
// its timing line ("drawn": false) and no picture: the last picture stands. Files are
// written atomically; the first failure is returned as one sentence and stops the run.
#pragma once

#include <cstdint>
#include <expected>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "client/render/linear_image.h"
#include "client/render/tone_mapping.h"

namespace vem::view {

struct FrameRecord {
  std::uint64_t frame = 0;
  std::uint64_t inputSeq = 0;
  bool drawn = true;
  bool displayReferred = false;  // frameSrgb8: encode as it is, no tone mapping
  nlohmann::ordered_json timing;  // the renderer's own figures, merged into the line
};

// The 8-bit sRGB picture of a frame, as the PNG and the video hold it: tone-mapped, or, for a
// display-referred frame (a composite into an 8-bit plate), encoded as it is.
[[nodiscard]] std::vector<std::uint8_t> frameSrgb8(const render::LinearImage& image,
                                                   bool displayReferred,
                                                   const render::ToneParams& tone);

class FrameWriter {
 public:
  [[nodiscard]] static std::expected<FrameWriter, std::string> open(
      const std::filesystem::path& folder, bool png, bool exr);
  [[nodiscard]] std::expected<void, std::string> write(const FrameRecord& record,
                                                       const render::LinearImage& image,
                                                       const render::ToneParams& tone);
  [[nodiscard]] const std::filesystem::path& folder() const { return folder_; }
  [[nodiscard]] std::filesystem::path lastPng() const { return lastPng_; }

 private:
  FrameWriter(std::filesystem::path folder, bool png, bool exr, std::ofstream timing)
      : folder_(std::move(folder)), png_(png), exr_(exr), timing_(std::move(timing)) {}
  std::filesystem::path folder_;
  bool png_;
  bool exr_;
  std::ofstream timing_;
  std::filesystem::path lastPng_;
};

}  // namespace vem::view
