#include "client/vemview/plate_source.h"

#include <array>
#include <chrono>
#include <filesystem>

#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/videoio.hpp>

#include "client/render/image_files.h"
#include "client/render/tone_mapping.h"
#include "util/printable.h"
#include "util/quiet_std_err.h"

namespace vem::view {
namespace {

// sRGB code to linear, for 8-bit pictures.
const std::array<float, 256>& srgb8Table() {
  static const std::array<float, 256> table = [] {
    std::array<float, 256> t{};
    for (int i = 0; i < 256; ++i) t[std::size_t(i)] = render::srgbDecode(float(i) / 255.0F);
    return t;
  }();
  return table;
}

// An 8- or 16-bit BGR(A) or grey picture as linear light (sRGB decoded); row 0 at the top. Rows
// in parallel on TBB's threads.
render::LinearImage linearFromPicture(const cv::Mat& picture) {
  render::LinearImage out = render::LinearImage::black(picture.cols, picture.rows);
  std::ranges::fill(out.covered, std::uint8_t{1});
  const int channels = picture.channels();
  const bool eightBit = picture.depth() == CV_8U;
  const std::array<float, 256>& table = srgb8Table();
  tbb::parallel_for(
      tbb::blocked_range<int>(0, picture.rows), [&](const tbb::blocked_range<int>& rows) {
        for (int y = rows.begin(); y < rows.end(); ++y) {
          float* to = &out.rgb[3 * std::size_t(y) * std::size_t(picture.cols)];
          for (int x = 0; x < picture.cols; ++x) {
            for (int c = 0; c < 3; ++c) {
              const int from =
                  x * channels + (channels >= 3 ? 2 - c : 0);  // BGR to RGB; grey to all
              to[3 * x + c] =
                  eightBit
                      ? table[picture.ptr<std::uint8_t>(y)[from]]
                      : render::srgbDecode(float(picture.ptr<std::uint16_t>(y)[from]) / 65535.0F);
            }
          }
        }
      });
  return out;
}

bool decodable(const cv::Mat& picture) {
  return !picture.empty() && (picture.depth() == CV_8U || picture.depth() == CV_16U) &&
         (picture.channels() == 1 || picture.channels() == 3 || picture.channels() == 4);
}

class StillPlate final : public PlateSource {
 public:
  StillPlate(std::string description, PlateFrame frame)
      : description_(std::move(description)), frame_(std::move(frame)) {}
  std::string description() const override { return description_; }
  int widthPx() const override { return frame_.linear.widthPx; }
  int heightPx() const override { return frame_.linear.heightPx; }
  std::optional<PlateFrame> next() override { return frame_; }

 private:
  std::string description_;
  PlateFrame frame_;
};

// A video file, an image sequence or a live camera, through cv::VideoCapture.
class CapturePlate final : public PlateSource {
 public:
  CapturePlate(std::string description, cv::VideoCapture capture, bool isLive)
      : description_(std::move(description)),
        capture_(std::move(capture)),
        live_(isLive),
        widthPx_(int(capture_.get(cv::CAP_PROP_FRAME_WIDTH))),
        heightPx_(int(capture_.get(cv::CAP_PROP_FRAME_HEIGHT))) {}
  std::string description() const override { return description_; }
  int widthPx() const override { return widthPx_; }
  int heightPx() const override { return heightPx_; }
  bool live() const override { return live_; }
  bool ended() const override { return ended_; }

  std::optional<PlateFrame> next() override {
    if (ended_) return std::nullopt;
    cv::Mat picture;
    if (!capture_.read(picture) || !decodable(picture)) {
      ended_ = true;  // a video's end, a sequence's last file, a camera that stopped
      return std::nullopt;
    }
    PlateFrame frame;
    frame.linear = linearFromPicture(picture);
    frame.seq = ++seq_;
    frame.captureTimeSec =
        live_ ? std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch())
                    .count()
              : capture_.get(cv::CAP_PROP_POS_MSEC) / 1000.0;
    frame.captureOnSystemClock = live_;
    return frame;
  }

 private:
  std::string description_;
  cv::VideoCapture capture_;
  bool live_;
  int widthPx_;
  int heightPx_;
  bool ended_ = false;
  std::uint64_t seq_ = 0;
};

std::expected<std::unique_ptr<PlateSource>, std::string> openStill(const std::string& source) {
  const std::filesystem::path path(source);
  if (path.extension() == ".exr") {
    auto image = render::loadLinearExr(path);
    if (!image) return std::unexpected(image.error());
    std::ranges::fill(image->covered, std::uint8_t{1});
    PlateFrame frame{std::move(*image), false, 0.0, false, 1};
    return stillPlate(fmt::format("image {} ({} x {}, linear)", util::printable(source),
                                  frame.linear.widthPx, frame.linear.heightPx),
                      std::move(frame));
  }
  cv::Mat picture;
  {
    const util::QuietStdErr quiet;
    picture = cv::imread(source, cv::IMREAD_UNCHANGED);
  }
  if (!decodable(picture)) {
    return std::unexpected(fmt::format(
        "--plate {}: not a picture vemview can read (expected an 8- or 16-bit PNG or JPEG, or "
        "an OpenEXR file)",
        util::printable(source)));
  }
  PlateFrame frame{linearFromPicture(picture), true, 0.0, false, 1};
  return stillPlate(
      fmt::format("image {} ({} x {}, sRGB)", util::printable(source), picture.cols, picture.rows),
      std::move(frame));
}

}  // namespace

std::unique_ptr<PlateSource> stillPlate(std::string description, PlateFrame frame) {
  return std::make_unique<StillPlate>(std::move(description), std::move(frame));
}

std::expected<std::unique_ptr<PlateSource>, std::string> openPlateSource(
    const std::string& source) {
  constexpr std::string_view kV4l2 = "v4l2:";
  const bool isLive = source.starts_with(kV4l2);
  const bool isSequence = source.find('%') != std::string::npos;
  const std::string path = isLive ? source.substr(kV4l2.size()) : source;
  if (!isLive && !isSequence) {
    if (!std::filesystem::is_regular_file(path)) {
      return std::unexpected(
          fmt::format("--plate {}: no such file (expected an image, an image sequence such as "
                      "frames/%04d.png, a video file, v4l2:/dev/videoN or sim)",
                      util::printable(source)));
    }
    const std::string ext = std::filesystem::path(path).extension().string();
    if (ext == ".png" || ext == ".jpg" || ext == ".jpeg" || ext == ".exr" || ext == ".PNG" ||
        ext == ".JPG") {
      return openStill(path);
    }
  }
  cv::VideoCapture capture;
  {
    const util::QuietStdErr quiet;
    capture.open(path, isLive ? cv::CAP_V4L2 : (isSequence ? cv::CAP_IMAGES : cv::CAP_FFMPEG));
  }
  if (!capture.isOpened()) {
    return std::unexpected(fmt::format(
        "--plate {}: OpenCV cannot open it as {}", util::printable(source),
        isLive ? "a V4L2 camera" : (isSequence ? "an image sequence" : "a video file")));
  }
  const int widthPx = int(capture.get(cv::CAP_PROP_FRAME_WIDTH));
  const int heightPx = int(capture.get(cv::CAP_PROP_FRAME_HEIGHT));
  const char* kind = isLive ? "live camera" : (isSequence ? "image sequence" : "video");
  return std::make_unique<CapturePlate>(
      fmt::format("{} {} ({} x {})", kind, util::printable(source), widthPx, heightPx),
      std::move(capture), isLive);
}

}  // namespace vem::view
