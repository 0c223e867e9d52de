#include "mapio/exr_codec.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <exception>

namespace vem::mapio::detail {
namespace {

using Box = Imath::Box2i;
constexpr std::size_t kPixelBytes = 3 * sizeof(float);

std::int64_t boxWidth(const Box& box) { return std::int64_t{box.max.x} - box.min.x + 1; }
std::int64_t boxHeight(const Box& box) { return std::int64_t{box.max.y} - box.min.y + 1; }

// An in-memory Imf::OStream: OpenEXR swallows errors in its destructors, memory has none.
class MemoryOStream final : public Imf::OStream {
 public:
  MemoryOStream() : Imf::OStream("memory") {}
  void write(const char c[], int n) override {
    const std::size_t end = position_ + std::size_t(n);
    if (end > bytes.size()) bytes.resize(end);
    std::memcpy(bytes.data() + position_, c, std::size_t(n));
    position_ = end;
  }
  std::uint64_t tellp() override { return position_; }
  void seekp(std::uint64_t position) override { position_ = position; }

  std::vector<unsigned char> bytes;

 private:
  std::size_t position_ = 0;
};

// Names of the channels that fill R, G, B: {R, G, B}, or {Y} for a grey file.
std::expected<std::vector<const char*>, MapFileFailure> pickChannels(
    const std::filesystem::path& path, const Imf::ChannelList& channels) {
  const auto plain = [&](const char* name) {
    const Imf::Channel* channel = channels.findChannel(name);
    return channel != nullptr && channel->xSampling == 1 && channel->ySampling == 1;
  };
  const bool chroma =
      channels.findChannel("RY") != nullptr || channels.findChannel("BY") != nullptr;
  if (plain("R") && plain("G") && plain("B")) return std::vector{"R", "G", "B"};
  if (plain("Y") && !chroma) return std::vector{"Y"};
  std::string found;
  for (auto it = channels.begin(); it != channels.end(); ++it)
    found += (found.empty() ? "" : ", ") + std::string(it.name());
  return std::unexpected(
      fileFailure(chroma ? MapFileError::UnsupportedFormat : MapFileError::BadContents, path,
                  "the OpenEXR channels are " + (found.empty() ? std::string("none") : found) +
                      " (expected R, G and B, or a lone luminance Y, none subsampled)"));
}

// The display window of the pixels read over the data window.
RgbImage placeInDisplayWindow(std::vector<float> pixels, const Box& data, const Box& display) {
  RgbImage image{int(boxWidth(display)), int(boxHeight(display)), {}};
  if (data == display) {
    image.rgb = std::move(pixels);
    return image;
  }
  image.rgb.assign(std::size_t(image.width) * std::size_t(image.height) * 3, 0.0f);
  const int x0 = std::max(data.min.x, display.min.x), x1 = std::min(data.max.x, display.max.x);
  const int y0 = std::max(data.min.y, display.min.y), y1 = std::min(data.max.y, display.max.y);
  if (x0 > x1) return image;
  for (int y = y0; y <= y1; ++y) {
    const std::int64_t from = (std::int64_t{y} - data.min.y) * boxWidth(data) + (x0 - data.min.x);
    const std::int64_t to = (std::int64_t{y} - display.min.y) * image.width + (x0 - display.min.x);
    std::copy_n(pixels.begin() + 3 * from, 3 * (std::int64_t{x1} - x0 + 1),
                image.rgb.begin() + 3 * to);
  }
  return image;
}

std::expected<RgbImage, MapFileFailure> readOpenFile(const std::filesystem::path& path,
                                                     Imf::InputFile& file) {
  const Box display = file.header().displayWindow();
  const Box data = file.header().dataWindow();
  if (auto ok = checkMapSize(path, "the map", boxWidth(display), boxHeight(display)); !ok)
    return std::unexpected(ok.error());
  if (auto ok = checkMapSize(path, "the OpenEXR data window", boxWidth(data), boxHeight(data)); !ok)
    return std::unexpected(ok.error());
  const auto channels = pickChannels(path, file.header().channels());
  if (!channels) return std::unexpected(channels.error());

  std::vector<float> pixels(std::size_t(boxWidth(data) * boxHeight(data)) * 3);
  Imf::FrameBuffer frame;
  for (std::size_t c = 0; c < channels->size(); ++c)
    frame.insert((*channels)[c], Imf::Slice::Make(Imf::FLOAT, pixels.data() + c, data, kPixelBytes,
                                                  kPixelBytes * std::size_t(boxWidth(data))));
  file.setFrameBuffer(frame);
  file.readPixels(data.min.y, data.max.y);
  if (channels->size() == 1)
    for (std::size_t i = 0; i < pixels.size(); i += 3) pixels[i + 1] = pixels[i + 2] = pixels[i];
  return placeInDisplayWindow(std::move(pixels), data, display);
}

}  // namespace

std::expected<RgbImage, MapFileFailure> readExr(const std::filesystem::path& path,
                                                std::string_view fileStart) {
  if (!fileStart.starts_with("\x76\x2f\x31\x01"))
    return std::unexpected(
        fileFailure(MapFileError::BadContents, path,
                    "not an OpenEXR file (expected the magic number 76 2f 31 01)"));
  try {
    Imf::InputFile file(path.c_str());
    return readOpenFile(path, file);
  } catch (const std::exception& e) {
    return std::unexpected(fileFailure(
        MapFileError::BadContents, path,
        "the OpenEXR data is truncated or corrupted (OpenEXR: " + std::string(e.what()) + ")"));
  } catch (...) {
    return std::unexpected(
        fileFailure(MapFileError::BadContents, path, "the OpenEXR data is truncated or corrupted"));
  }
}

std::expected<std::vector<unsigned char>, std::string> encodeExr(const EnvMap& map) {
  try {
    MemoryOStream stream;
    {
      Imf::Header header(map.width, map.height);
      Imf::FrameBuffer frame;
      const char* names[] = {"R", "G", "B"};
      for (std::size_t c = 0; c < 3; ++c) {
        header.channels().insert(names[c], Imf::Channel(Imf::FLOAT));
        frame.insert(names[c], Imf::Slice::Make(Imf::FLOAT, map.rgb.data() + c, header.dataWindow(),
                                                kPixelBytes, kPixelBytes * std::size_t(map.width)));
      }
      Imf::OutputFile file(stream, header);
      file.setFrameBuffer(frame);
      file.writePixels(map.height);
    }  // the destructor writes the line offset table
    return std::move(stream.bytes);
  } catch (const std::exception& e) {
    return std::unexpected(std::string("OpenEXR: ") + e.what());
  } catch (...) {
    return std::unexpected(std::string("OpenEXR failed"));
  }
}

}  // namespace vem::mapio::detail
