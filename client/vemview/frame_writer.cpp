#include "client/vemview/frame_writer.h"

#include <fmt/format.h>

#include "client/render/image_files.h"

namespace vem::view {

std::vector<std::uint8_t> frameSrgb8(const render::LinearImage& image, bool displayReferred,
                                     const render::ToneParams& tone) {
  return displayReferred ? render::displaySrgb8(image) : render::toneMappedSrgb8(image, tone);
}

std::expected<FrameWriter, std::string> FrameWriter::open(const std::filesystem::path& folder,
                                                          bool png, bool exr) {
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  if (error || !std::filesystem::is_directory(folder)) {
    return std::unexpected(fmt::format("--out {}: cannot use it as the output folder ({})",
                                       folder.string(),
                                       error ? error.message() : "it is not a folder"));
  }
  std::ofstream timing(folder / "timing.jsonl", std::ios::trunc);
  if (!timing) {
    return std::unexpected(
        fmt::format("--out {}: cannot create timing.jsonl there", folder.string()));
  }
  return FrameWriter(folder, png, exr, std::move(timing));
}

std::expected<void, std::string> FrameWriter::write(const FrameRecord& record,
                                                    const render::LinearImage& image,
                                                    const render::ToneParams& tone) {
  const std::string stem = fmt::format("frame-{:06}", record.frame);
  if (png_ && record.drawn) {
    const auto srgb = frameSrgb8(image, record.displayReferred, tone);
    const auto path = folder_ / (stem + ".png");
    if (auto saved = render::saveSrgbPng(srgb, image.widthPx, image.heightPx, path); !saved) {
      return std::unexpected(saved.error());
    }
    lastPng_ = path;
  }
  if (exr_ && record.drawn) {
    if (auto saved = render::saveLinearExr(image, folder_ / (stem + ".exr")); !saved) {
      return std::unexpected(saved.error());
    }
  }
  nlohmann::ordered_json line = {{"frame", record.frame},
                                 {"input_seq", record.inputSeq},
                                 {"drawn", record.drawn},
                                 {"world_luminance", tone.worldLuminance},
                                 {"key", tone.key}};
  for (const auto& [key, value] : record.timing.items()) {
    line[key] = value;
  }
  timing_ << line.dump() << '\n' << std::flush;
  if (!timing_) {
    return std::unexpected(fmt::format("{}: cannot write the timing log (disk full?)",
                                       (folder_ / "timing.jsonl").string()));
  }
  return {};
}

}  // namespace vem::view
