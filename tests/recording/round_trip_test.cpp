// Record then replay: frames, metadata and stored lights come back bit for bit.
#include <gtest/gtest.h>

#include "recording/recording_reader.h"
#include "recording/recording_writer.h"
#include "recording_fixtures.h"

namespace vem::testing {
namespace {

using RoundTrip = RecordingFiles;

TEST_F(RoundTrip, FramesMetadataAndLightsComeBackBitIdentical) {
  for (const auto& [channels, bits] : {std::pair{1, 12}, std::pair{3, 16}, std::pair{1, 8}}) {
    SCOPED_TRACE(bits);
    const fs::path path = dir_ / ("rt" + std::to_string(channels) + std::to_string(bits) + ".vem");
    const recording::RecordingHeader header = smallHeader(channels, bits);
    writeSmallRecording(path, 6, header);
    auto reader = recording::RecordingReader::open(path);
    ASSERT_TRUE(reader) << reader.error().message;
    EXPECT_EQ(reader->header(), header);
    const ReadBack back = readAll(*reader);
    ASSERT_EQ(back.frames.size(), 6U);
    for (int i = 0; i < 6; ++i) {
      const recording::RecordedFrame& got = back.frames[std::size_t(i)];
      const vem::RawFrame want = smallFrame(header, i);
      EXPECT_EQ(got.seq, std::uint64_t(i));
      EXPECT_EQ(got.captureTsNs, i * kPeriodNs);
      EXPECT_EQ(got.frame.width, want.width);
      EXPECT_EQ(got.frame.height, want.height);
      EXPECT_EQ(got.frame.format, want.format);
      EXPECT_TRUE(sameBits(got.frame.exposureUs, want.exposureUs));
      EXPECT_TRUE(sameBits(got.frame.gain, want.gain));
      EXPECT_EQ(got.frame.codes, want.codes) << "frame " << i;
      ASSERT_EQ(got.lights.has_value(), i % 2 == 0);
      if (got.lights) {
        EXPECT_TRUE(sameLights(*got.lights, awkwardLights(i))) << "frame " << i;
      }
    }
    EXPECT_EQ(back.damage, recording::DamageStats{});
  }
}

TEST_F(RoundTrip, ReusedFrameBufferDoesNotKeepLightsOfAnEarlierFrame) {
  const fs::path path = dir_ / "reuse.vem";
  writeSmallRecording(path, 3);
  auto reader = recording::RecordingReader::open(path);
  ASSERT_TRUE(reader) << reader.error().message;
  recording::RecordedFrame frame;
  for (int i = 0; i < 3; ++i) {
    auto got = reader->next(frame);
    ASSERT_TRUE(got && *got);
    EXPECT_EQ(frame.lights.has_value(), i % 2 == 0) << "frame " << i;
    EXPECT_EQ(frame.frame.codes, smallFrame(smallHeader(), i).codes);
  }
  auto end = reader->next(frame);
  ASSERT_TRUE(end);
  EXPECT_FALSE(*end);
}

TEST_F(RoundTrip, EmptyRecordingHasHeaderAndNoFrames) {
  const fs::path path = dir_ / "empty.vem";
  writeSmallRecording(path, 0);
  auto reader = recording::RecordingReader::open(path);
  ASSERT_TRUE(reader) << reader.error().message;
  EXPECT_TRUE(reader->hasIndex());
  EXPECT_TRUE(readAll(*reader).frames.empty());
}

TEST_F(RoundTrip, CompressionIsLosslessForFullRangeNoise) {
  // Every code value from 0 to 65535 and incompressible noise: nothing may be clipped or rounded.
  recording::RecordingHeader header = smallHeader(1, 16);
  header.sensorWidthPx = 256;
  header.sensorHeightPx = 256;
  vem::RawFrame frame = vem::RawFrame::blank(256, 256, header.pixelFormat);
  std::uint32_t state = 12345;
  for (std::size_t i = 0; i < frame.codes.size(); ++i) {
    state = state * 1664525u + 1013904223u;
    frame.codes[i] = i < 65536 ? std::uint16_t(i) : std::uint16_t(state >> 16);
  }
  const fs::path path = dir_ / "noise.vem";
  {
    auto writer = recording::RecordingWriter::create(path, header);
    ASSERT_TRUE(writer) << writer.error().message;
    ASSERT_TRUE(writer->append(7, 1, frame));
    ASSERT_TRUE(writer->close());
  }
  auto reader = recording::RecordingReader::open(path);
  ASSERT_TRUE(reader) << reader.error().message;
  const ReadBack back = readAll(*reader);
  ASSERT_EQ(back.frames.size(), 1U);
  EXPECT_EQ(back.frames[0].frame.codes, frame.codes);
}

}  // namespace
}  // namespace vem::testing
