// `vemtool info` and `vemtool recover` as a user meets them: the summary they print, the index
// recover restores, and one clear error line for files that are not recordings.
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "recording/record_format.h"
#include "recording/recording_fixtures.h"
#include "recording/recording_header.h"
#include "recording/recording_index.h"
#include "recording/recording_reader.h"
#include "recording/recording_writer.h"
#include "support/command_run.h"

namespace {

namespace fs = std::filesystem;
using vem::testing::readBytes;
using vem::testing::writeBytes;

using vem::testing::CommandRun;

class VemtoolRecordingCli : public vem::testing::RecordingFiles {
 protected:
  CommandRun run(const std::string& args) const {
    return vem::testing::runCommand(vem::testing::commandLine(VEMTOOL_PATH, args), dir_);
  }
};

TEST_F(VemtoolRecordingCli, InfoJsonReportsHeaderFramesRateAndAValidIndex) {
  const fs::path path = dir_ / "a.vem";
  vem::testing::writeSmallRecording(path, 20);
  const CommandRun r = run("info " + path.string() + " --format json");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.err, "");
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["format_version"], 1);
  EXPECT_EQ(j["camera"]["model"], "simulated HDRC");
  EXPECT_EQ(j["sensor"]["width_px"], 64);
  EXPECT_EQ(j["sensor"]["pixel_format"], "Mono12");
  EXPECT_EQ(j["nominal_rate_hz"], 30.0);
  EXPECT_EQ(j["frames"], 20);
  EXPECT_EQ(j["frames_with_lights"], 10);
  EXPECT_EQ(j["first_seq"], 0);
  EXPECT_EQ(j["last_seq"], 19);
  EXPECT_NEAR(double(j["mean_rate_hz"]), 30.0, 1e-3);
  EXPECT_EQ(j["sequence_gaps"], 0);
  EXPECT_EQ(j["timestamp_gaps"], 0);
  EXPECT_EQ(j["damaged_records"], 0);
  EXPECT_EQ(j["index"], "valid");
  EXPECT_EQ(j["index_entries"], 20);
  EXPECT_EQ(j["file_bytes"], fs::file_size(path));
}

TEST_F(VemtoolRecordingCli, InfoTextNamesFramesDamageAndIndex) {
  const fs::path path = dir_ / "a.vem";
  vem::testing::writeSmallRecording(path, 5);
  const CommandRun r = run("info " + path.string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("frames:      5 (seq 0 .. 4), 3 with lights\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("damage:      0 damaged records"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("index:       valid (5 entries)\n"), std::string::npos) << r.out;
}

// Issue 17: info printed "created 1760000000000000000 ns after 1970"; a person reads a date.
TEST_F(VemtoolRecordingCli, InfoShowsTheCreationDateInIso8601UtcNotNanosecondsAfter1970) {
  const fs::path path = dir_ / "a.vem";
  vem::testing::writeSmallRecording(path, 2);  // created 1.76e18 ns after 1970
  const CommandRun text = run("info " + path.string());
  ASSERT_EQ(text.exitCode, 0) << text.err;
  EXPECT_NE(text.out.find(", created 2025-10-09T08:53:20.000Z\n"), std::string::npos) << text.out;
  EXPECT_EQ(text.out.find("ns after 1970"), std::string::npos) << text.out;
  const CommandRun json = run("info " + path.string() + " --format json");
  ASSERT_EQ(json.exitCode, 0) << json.err;
  const auto j = nlohmann::json::parse(json.out);
  EXPECT_EQ(j["created_unix_ns"], 1'760'000'000'000'000'000);
  EXPECT_EQ(j["created_utc"], "2025-10-09T08:53:20.000Z");
}

TEST_F(VemtoolRecordingCli, RecoverRestoresTheIndexThatInfoReportsMissing) {
  const fs::path path = dir_ / "a.vem";
  vem::testing::writeSmallRecording(path, 10);
  std::vector<char> bytes = readBytes(path);
  bytes.resize(bytes.size() - vem::recording::kFooterRecordBytes - 30);  // cut into the index
  writeBytes(path, bytes.data(), bytes.size());

  const CommandRun before = run("info " + path.string() + " --format json");
  ASSERT_EQ(before.exitCode, 0) << before.err;
  const auto b = nlohmann::json::parse(before.out);
  EXPECT_EQ(b["index"], "missing");
  EXPECT_EQ(b["frames"], 10);
  EXPECT_GT(b["truncated_tail_bytes"], 0);

  const CommandRun recover = run("recover " + path.string());
  ASSERT_EQ(recover.exitCode, 0) << recover.err;
  EXPECT_NE(recover.out.find("appended a new index of 10 frames"), std::string::npos)
      << recover.out;

  const CommandRun after = run("info " + path.string() + " --format json");
  ASSERT_EQ(after.exitCode, 0) << after.err;
  const auto a = nlohmann::json::parse(after.out);
  EXPECT_EQ(a["index"], "valid");
  EXPECT_EQ(a["index_entries"], 10);
  EXPECT_EQ(a["frames"], 10);

  const CommandRun again = run("recover " + path.string());
  ASSERT_EQ(again.exitCode, 0);
  EXPECT_NE(again.out.find("already valid"), std::string::npos) << again.out;
}

// 90 frames, one of them out of order: info counted 90, recover indexed 89, info then called
// that index stale, and every further recover appended another index.
TEST_F(VemtoolRecordingCli, RecoverOfAnOutOfOrderFrameSettlesAndAgreesWithInfo) {
  std::vector<vem::testing::HandFrame> frames;
  for (std::uint64_t i = 0; i < 90; ++i) frames.push_back({i, std::int64_t(i) * 33'333'333});
  std::swap(frames[40].seq, frames[41].seq);
  const fs::path path = dir_ / "swapped.vem";
  vem::testing::writeRecordingByHand(path, frames);

  const CommandRun before = run("info " + path.string() + " --format json");
  ASSERT_EQ(before.exitCode, 0) << before.err;
  EXPECT_EQ(nlohmann::json::parse(before.out)["frames"], 90);

  std::vector<std::vector<char>> bytesAfter;
  for (int i = 0; i < 3; ++i) {
    const CommandRun recover = run("recover " + path.string());
    ASSERT_EQ(recover.exitCode, 0) << recover.err;
    const std::string expected =
        i == 0 ? "appended a new index of 90 frames" : "the index is already valid (90 frames)";
    EXPECT_NE(recover.out.find(expected), std::string::npos)
        << "run " << i + 1 << ": " << recover.out;
    bytesAfter.push_back(readBytes(path));
  }
  EXPECT_EQ(bytesAfter[1], bytesAfter[0]) << "the second run changed the file";
  EXPECT_EQ(bytesAfter[2], bytesAfter[0]) << "the third run changed the file";

  const CommandRun after = run("info " + path.string() + " --format json");
  ASSERT_EQ(after.exitCode, 0) << after.err;
  const auto a = nlohmann::json::parse(after.out);
  EXPECT_EQ(a["index"], "valid");
  EXPECT_EQ(a["frames"], 90);
  EXPECT_EQ(a["index_entries"], 90);
}

// seq 0 then 2^64 - 1: info printed "18446744073709551614 frames missing".
TEST_F(VemtoolRecordingCli, InfoNamesASeqWrapInsteadOfAGiganticMissingCount) {
  const std::uint64_t top = std::numeric_limits<std::uint64_t>::max();
  const fs::path path = dir_ / "wrap.vem";
  vem::testing::writeRecordingByHand(path, {{0, 0}, {top, 33'333'333}, {top - 2, 66'666'666}});
  std::uint64_t offset = 0;
  {
    auto reader = vem::recording::RecordingReader::open(path);
    ASSERT_TRUE(reader);
    auto scan = reader->scan();
    ASSERT_TRUE(scan && scan->entries.size() == 3);
    offset = scan->entries[1].offset;
  }
  const CommandRun text = run("info " + path.string());
  ASSERT_EQ(text.exitCode, 0) << text.err;
  EXPECT_EQ(text.out.find("18446744073709551614"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("gaps:        0 in sequence (0 frames missing, 2 out of order)"),
            std::string::npos)
      << text.out;
  EXPECT_NE(text.out.find("order:       first out of order: seq wraps from 0 to "
                          "18446744073709551615 at frame 2 of 3 (byte " +
                          std::to_string(offset) + ")\n"),
            std::string::npos)
      << text.out;

  const CommandRun json = run("info " + path.string() + " --format json");
  ASSERT_EQ(json.exitCode, 0) << json.err;
  const auto j = nlohmann::json::parse(json.out);
  EXPECT_EQ(j["missing_frames"], 0);
  EXPECT_EQ(j["sequence_gaps"], 0);
  EXPECT_EQ(j["sequence_disorders"], 2);
  EXPECT_EQ(j["first_sequence_disorder"]["kind"], "wrap");
  EXPECT_EQ(j["first_sequence_disorder"]["from_seq"], 0);
  EXPECT_EQ(j["first_sequence_disorder"]["to_seq"], top);
  EXPECT_EQ(j["first_sequence_disorder"]["frame"], 2);
  EXPECT_EQ(j["first_sequence_disorder"]["offset"], offset);
}

// A file name with a newline and a byte that is not UTF-8: info and recover printed it raw (a
// forged second line), and `info --format json` threw on the bad byte. Names in the header
// (camera model, writer) were printed raw too.
TEST_F(VemtoolRecordingCli, InfoAndRecoverEscapeNamesFromOutside) {
  vem::recording::RecordingHeader header = vem::testing::smallHeader();
  header.cameraModel = "cam\nvemtool: error: forged\u202e";
  const fs::path path = dir_ / "evil\nvemtool: error: forged\xff.vem";
  vem::testing::writeSmallRecording(path, 3, header);
  const std::string shown = dir_.string() + "/evil\\nvemtool: error: forged\\xff.vem";
  const std::string glob = dir_.string() + "/evil*";  // the shell passes the name unchanged

  const CommandRun text = run("info " + glob);
  ASSERT_EQ(text.exitCode, 0) << text.err;
  EXPECT_TRUE(text.out.starts_with(shown + ": VEM recording, format version 1, ")) << text.out;
  EXPECT_NE(text.out.find("camera:      cam\\nvemtool: error: forged\\u{202e} (serial "),
            std::string::npos)
      << text.out;
  EXPECT_EQ(text.out.find("\nvemtool: error: forged"), std::string::npos) << "a forged line";

  const CommandRun json = run("info " + glob + " --format json");
  ASSERT_EQ(json.exitCode, 0) << json.err;
  EXPECT_EQ(nlohmann::json::parse(json.out)["file"], shown);

  const CommandRun recover = run("recover " + glob);
  ASSERT_EQ(recover.exitCode, 0) << recover.err;
  EXPECT_EQ(recover.out, shown + ": the index is already valid (3 frames); nothing was written\n");

  const fs::path notVem = dir_ / "bad\n\xfe.vem";
  writeBytes(notVem, "just text\n", 10);
  const CommandRun bad = run("info " + dir_.string() + "/bad*");
  EXPECT_EQ(bad.exitCode, 1);
  EXPECT_EQ(bad.err, "vemtool: error: " + dir_.string() +
                         "/bad\\n\\xfe.vem: not a VEM recording (expected the record magic 8a 56 "
                         "45 4d at its start)\n");
}

TEST_F(VemtoolRecordingCli, NotARecordingGivesOneErrorLineAndFails) {
  const fs::path path = dir_ / "notes.vem";
  writeBytes(path, "just text\n", 10);
  for (const char* command : {"info ", "recover "}) {
    const CommandRun r = run(command + path.string());
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(r.err, "vemtool: error: " + path.string() +
                         ": not a VEM recording (expected the record magic 8a 56 45 4d at its "
                         "start)\n");
  }
  EXPECT_EQ(readBytes(path).size(), 10U) << "recover wrote nothing";
}

TEST_F(VemtoolRecordingCli, UnknownVersionAndMissingFileGiveOneClearSentence) {
  vem::recording::RecordingHeader header = vem::testing::smallHeader();
  header.formatVersion = 2;
  const auto record = vem::recording::encodeHeaderRecord(header);
  const fs::path path = dir_ / "v2.vem";
  writeBytes(path, reinterpret_cast<const char*>(record.data()), record.size());
  const CommandRun r = run("info " + path.string());
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_EQ(r.err, "vemtool: error: " + path.string() +
                       ": VEM format version 2 is not supported (expected version 1; a newer "
                       "vemcast may read it)\n");
  const CommandRun missing = run("info " + (dir_ / "nothere.vem").string());
  EXPECT_EQ(missing.exitCode, 1);
  EXPECT_EQ(missing.err, "vemtool: error: " + (dir_ / "nothere.vem").string() + ": no such file\n");
}

}  // namespace
