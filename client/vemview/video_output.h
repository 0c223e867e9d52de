// VideoOutput: vemview's --video FILE: the drawn frames, as the PNGs show them
// (frame_writer.h's frameSrgb8), into a video through OpenCV's VideoWriter (FFmpeg; MPEG-4 part 2
// in MP4, the codec Debian's OpenCV writes everywhere), at 30 frames per second. Opened at the
// first frame's size; a frame of another size is refused in one sentence.
#pragma once

#include <cstdint>
#include <expected>
#include <memory>
#include <span>
#include <string>

namespace vem::view {

class VideoOutput {
 public:
  explicit VideoOutput(std::string path);
  ~VideoOutput();
  VideoOutput(VideoOutput&&) noexcept;
  VideoOutput& operator=(VideoOutput&&) noexcept;

  // srgb8: widthPx * heightPx * 3 bytes, RGB, row 0 at the top.
  [[nodiscard]] std::expected<void, std::string> write(std::span<const std::uint8_t> srgb8,
                                                       int widthPx, int heightPx);
  [[nodiscard]] std::uint64_t frames() const;
  // Finishes the file (also done by the destructor).
  void close();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace vem::view
