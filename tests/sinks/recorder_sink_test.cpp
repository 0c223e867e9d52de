// The recorder sink: a .vem that RecordingReader reads back with the very frames and lights, the
// header from the RecordingContext, and a failure that stops the recording once and keeps the file.
#include "vemd/sinks/recorder_sink.h"
#include "sinks/sink_test_frames.h"
#include "vemd/sinks/sink_factory.h"

namespace vem::testing {
namespace {

using vemd::RecorderSink;

class RecorderSinkTest : public SinkFiles {};

TEST_F(RecorderSinkTest, RecordingReadsBackWithIdenticalFramesLightsAndHeader) {
  const fs::path path = dir_ / "run.vem";
  auto sink = RecorderSink::create(path, smallContext());
  ASSERT_TRUE(sink) << sink.error().message;
  for (int i = 0; i < 5; ++i) {
    TestFrame frame(i);
    ASSERT_TRUE(sink->consume(frame.processed));
  }
  ASSERT_TRUE(sink->close());
  EXPECT_EQ(sink->framesWritten(), 5U);

  auto reader = recording::RecordingReader::open(path);
  ASSERT_TRUE(reader) << reader.error().message;
  const recording::RecordingHeader expected = smallHeader();
  EXPECT_EQ(reader->header().cameraModel, expected.cameraModel);
  EXPECT_EQ(reader->header().cameraSerial, expected.cameraSerial);
  EXPECT_EQ(reader->header().sensorWidthPx, expected.sensorWidthPx);
  EXPECT_EQ(reader->header().sensorHeightPx, expected.sensorHeightPx);
  EXPECT_EQ(reader->header().pixelFormat, expected.pixelFormat);
  EXPECT_EQ(reader->header().nominalRateHz, expected.nominalRateHz);
  EXPECT_EQ(reader->header().calibrationToml, expected.calibrationToml);
  EXPECT_EQ(reader->header().writerName, "vemd");
  EXPECT_GT(reader->header().createdUnixNs, 0);
  EXPECT_TRUE(reader->hasIndex()) << "close() writes the index";

  const ReadBack back = readAll(*reader);
  ASSERT_EQ(back.frames.size(), 5U);
  for (int i = 0; i < 5; ++i) {
    const TestFrame frame(i);
    const recording::RecordedFrame& got = back.frames[std::size_t(i)];
    EXPECT_EQ(got.seq, frame.captured.seq);
    EXPECT_EQ(got.captureTsNs, frame.captured.captureTsNs);
    EXPECT_EQ(got.frame.codes, frame.captured.frame.codes);
    EXPECT_TRUE(sameBits(got.frame.exposureUs, frame.captured.frame.exposureUs));
    EXPECT_TRUE(sameBits(got.frame.gain, frame.captured.frame.gain));
    ASSERT_TRUE(got.lights.has_value());
    EXPECT_TRUE(sameLights(*got.lights, frame.processed.lights)) << "frame " << i;
  }
}

// The filtered set stands for an earlier frame; a replay checks each frame's own lights.
TEST_F(RecorderSinkTest, RecordsEachFrameWithItsOwnLightsNotTheFilteredOnes) {
  const fs::path path = dir_ / "run.vem";
  auto sink = RecorderSink::create(path, smallContext());
  ASSERT_TRUE(sink);
  TestFrame frame(3);
  frame.processed.filtered = oddLights(8, 2);
  frame.processed.filteredSeq = kFirstSeq;
  ASSERT_TRUE(sink->consume(frame.processed));
  ASSERT_TRUE(sink->close());
  auto reader = recording::RecordingReader::open(path);
  ASSERT_TRUE(reader);
  const ReadBack back = readAll(*reader);
  ASSERT_EQ(back.frames.size(), 1U);
  ASSERT_TRUE(back.frames[0].lights);
  EXPECT_TRUE(sameLights(*back.frames[0].lights, oddLights(3)));
}

TEST_F(RecorderSinkTest, FrameThatDoesNotFitTheHeaderStopsTheRecordingOnceAndKeepsTheFile) {
  const fs::path path = dir_ / "run.vem";
  auto sink = RecorderSink::create(path, smallContext());
  ASSERT_TRUE(sink);
  for (int i = 0; i < 3; ++i) {
    TestFrame frame(i);
    ASSERT_TRUE(sink->consume(frame.processed));
  }
  TestFrame resized(3);
  resized.captured.frame = vem::RawFrame::blank(32, 48, smallHeader().pixelFormat);
  auto failed = sink->consume(resized.processed);
  ASSERT_FALSE(failed);
  EXPECT_EQ(failed.error().message,
            "recorder: " + path.string() +
                ": cannot record the frame: the frame is 32 x 48 Mono12 (expected the header's "
                "64 x 48 Mono12); recording stopped, the file closed with an index");
  EXPECT_TRUE(sink->stopped());
  for (int i = 4; i < 7; ++i) {
    TestFrame frame(i);
    EXPECT_TRUE(sink->consume(frame.processed)) << "a stopped recorder is a harmless no-op";
  }
  EXPECT_TRUE(sink->close());
  auto reader = recording::RecordingReader::open(path);
  ASSERT_TRUE(reader) << reader.error().message;
  EXPECT_TRUE(reader->hasIndex());
  EXPECT_EQ(readAll(*reader).frames.size(), 3U);
}

TEST_F(RecorderSinkTest, ExistingRecordingIsNeverOverwritten) {
  const fs::path path = dir_ / "run.vem";
  writeBytes(path, "keep", 4);
  vemd::SinkConfig config;
  config.record = path;
  auto sinks = vemd::makeSinks(config, smallContext());
  ASSERT_FALSE(sinks);
  EXPECT_EQ(sinks.error(),
            "recorder: " + path.string() + ": a file is already there (refusing to overwrite it)");
  EXPECT_EQ(readBytes(path), (std::vector<char>{'k', 'e', 'e', 'p'}));
}

TEST_F(RecorderSinkTest, RecordFolderGetsANewTimeStampedFileEachRun) {
  const std::int64_t now = 1'767'225'600'000'000'000;  // 2026-01-01 00:00:00 UTC
  EXPECT_EQ(vemd::recordingPathFor(dir_, now), dir_ / "vemd-20260101T000000Z.vem");
  writeBytes(dir_ / "vemd-20260101T000000Z.vem", "x", 1);
  EXPECT_EQ(vemd::recordingPathFor(dir_, now), dir_ / "vemd-20260101T000000Z-1.vem");
  EXPECT_EQ(vemd::recordingPathFor(dir_ / "a.vem", now), dir_ / "a.vem");

  vemd::SinkConfig config;
  config.record = dir_;
  for (int run = 0; run < 2; ++run) {
    auto sinks = vemd::makeSinks(config, smallContext());
    ASSERT_TRUE(sinks) << sinks.error();
    ASSERT_EQ(sinks->size(), 1U);
    ASSERT_TRUE((*sinks)[0]->close());
  }

  int recordings = 0;
  for (const auto& entry : fs::directory_iterator(dir_)) {
    recordings += entry.path().extension() == ".vem" ? 1 : 0;
  }
  EXPECT_EQ(recordings, 3);  // the planted one and one per run
}

TEST_F(RecorderSinkTest, FolderWithATrailingSlashThatDoesNotExistIsMadeNotTakenForAFile) {
  const std::int64_t now = 1767225600LL * 1'000'000'000LL;  // 2026-01-01T00:00:00Z
  const auto path = vemd::recordingPathFor(dir_ / "runs" / "", now);
  EXPECT_EQ(path, dir_ / "runs" / "vemd-20260101T000000Z.vem");
  EXPECT_TRUE(std::filesystem::is_directory(dir_ / "runs"));
}

TEST_F(RecorderSinkTest, FactoryBuildsTheConfiguredSinksInOrder) {
  vemd::SinkConfig config;
  EXPECT_TRUE(vemd::makeSinks(config, smallContext())->empty());
  config.jsonl = dir_ / "l.jsonl";
  config.record = dir_ / "r.vem";
  config.previewDir = dir_ / "preview";
  auto sinks = vemd::makeSinks(config, smallContext());
  ASSERT_TRUE(sinks) << sinks.error();
  std::vector<std::string> names;
  for (const auto& sink : *sinks) names.push_back(sink->name());
  EXPECT_EQ(names, (std::vector<std::string>{"jsonl", "recorder", "preview"}));
  for (const auto& sink : *sinks) EXPECT_TRUE(sink->close());
}

}  // namespace
}  // namespace vem::testing
