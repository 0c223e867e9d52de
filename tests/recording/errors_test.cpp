// Errors are values with one clear sentence: files that are not recordings, unknown versions,
// invalid frames, and a full disk, after which the part written stays readable.
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "recording/record_format.h"
#include "recording/recording_reader.h"
#include "recording/recording_writer.h"
#include "recording_fixtures.h"

namespace vem::testing {
namespace {

using Errors = RecordingFiles;
using recording::RecordingError;

TEST_F(Errors, UnknownFormatVersionIsRefusedWithAClearMessage) {
  recording::RecordingHeader header = smallHeader();
  header.formatVersion = 7;
  const auto record = recording::encodeHeaderRecord(header);
  const fs::path path = dir_ / "future.vem";
  writeBytes(path, reinterpret_cast<const char*>(record.data()), record.size());
  auto reader = recording::RecordingReader::open(path);
  ASSERT_FALSE(reader);
  EXPECT_EQ(reader.error().cause, RecordingError::UnknownVersion);
  EXPECT_EQ(reader.error().message,
            path.string() +
                ": VEM format version 7 is not supported (expected version 1; a newer "
                "vemcast may read it)");
}

TEST_F(Errors, OtherFilesAreNotVemRecordings) {
  const fs::path text = dir_ / "notes.vem";
  writeBytes(text, "hello, world\n", 13);
  auto reader = recording::RecordingReader::open(text);
  ASSERT_FALSE(reader);
  EXPECT_EQ(reader.error().cause, RecordingError::NotVem);
  EXPECT_EQ(reader.error().message,
            text.string() +
                ": not a VEM recording (expected the record magic 8a 56 45 4d at its "
                "start)");
  const fs::path empty = dir_ / "empty.vem";
  writeBytes(empty, "", 0);
  auto none = recording::RecordingReader::open(empty);
  ASSERT_FALSE(none);
  EXPECT_EQ(none.error().message,
            empty.string() + ": the file is empty (expected a VEM recording)");
  auto missing = recording::RecordingReader::open(dir_ / "nothere.vem");
  ASSERT_FALSE(missing);
  EXPECT_EQ(missing.error().cause, RecordingError::NotFound);
  auto folder = recording::RecordingReader::open(dir_);
  ASSERT_FALSE(folder);
  EXPECT_EQ(folder.error().cause, RecordingError::Unreadable);
}

TEST_F(Errors, DamagedHeaderIsRefusedNotMisread) {
  const fs::path path = dir_ / "a.vem";
  writeSmallRecording(path, 3);
  std::vector<char> bytes = readBytes(path);
  bytes[40] = char(bytes[40] ^ 1);  // inside the header record's payload
  writeBytes(path, bytes.data(), bytes.size());
  auto reader = recording::RecordingReader::open(path);
  ASSERT_FALSE(reader);
  EXPECT_EQ(reader.error().cause, RecordingError::BadHeader);
}

TEST_F(Errors, HeaderAnnouncingHugeFramesIsRefusedBeforeAnyAllocation) {
  recording::RecordingHeader header = smallHeader(3, 16);
  header.sensorWidthPx = 65535;
  header.sensorHeightPx = 65535;
  const auto record = recording::encodeHeaderRecord(header);
  const fs::path path = dir_ / "huge.vem";
  writeBytes(path, reinterpret_cast<const char*>(record.data()), record.size());
  auto reader = recording::RecordingReader::open(path);
  ASSERT_FALSE(reader);
  EXPECT_EQ(reader.error().cause, RecordingError::BadHeader);
  EXPECT_NE(reader.error().message.find("bytes (expected at most"), std::string::npos)
      << reader.error().message;
}

TEST_F(Errors, WriterRefusesFramesThatDoNotFitTheHeaderAndNonIncreasingSeq) {
  const recording::RecordingHeader header = smallHeader();
  auto writer = recording::RecordingWriter::create(dir_ / "a.vem", header);
  ASSERT_TRUE(writer);
  vem::RawFrame wrong = vem::RawFrame::blank(32, 48, header.pixelFormat);
  auto bad = writer->append(0, 0, wrong);
  ASSERT_FALSE(bad);
  EXPECT_EQ(bad.error().cause, RecordingError::InvalidFrame);
  EXPECT_NE(bad.error().message.find("32 x 48 Mono12 (expected the header's 64 x 48 Mono12)"),
            std::string::npos)
      << bad.error().message;
  ASSERT_TRUE(writer->append(5, 0, smallFrame(header, 0)));
  auto repeated = writer->append(5, 1, smallFrame(header, 1));
  ASSERT_FALSE(repeated);
  EXPECT_NE(repeated.error().message.find("sequence number 5 does not follow 5"),
            std::string::npos);
  ASSERT_TRUE(writer->close());
  auto closed = writer->append(6, 2, smallFrame(header, 2));
  ASSERT_FALSE(closed);
  EXPECT_EQ(closed.error().cause, RecordingError::Closed);
}

TEST_F(Errors, WriterRefusesToOverwriteAnExistingFile) {
  const fs::path path = dir_ / "a.vem";
  writeSmallRecording(path, 2);
  const std::vector<char> before = readBytes(path);
  auto writer = recording::RecordingWriter::create(path, smallHeader());
  ASSERT_FALSE(writer);
  EXPECT_EQ(writer.error().message, path.string() +
                                        ": a file is already there (refusing to "
                                        "overwrite it)");
  EXPECT_EQ(readBytes(path), before);
}

// A header that cannot be written used to be reported with "the 0 frames before it stay
// readable", though no recording was made (and none is left).
TEST_F(Errors, HeaderWriteFailureSaysNoRecordingWasMade) {
  auto writer =
      recording::RecordingWriter::create("/dev/full", smallHeader(), {.replaceExisting = true});
  ASSERT_FALSE(writer);
  EXPECT_EQ(writer.error().cause, RecordingError::WriteFailed);
  EXPECT_EQ(writer.error().message,
            "/dev/full: cannot write the header (No space left on device); no recording was made");
}

// The same for a new file on a disk that cannot take its header (RLIMIT_FSIZE below the header's
// size, in a child): the file the writer created is gone again and the sentence says so.
TEST_F(Errors, HeaderThatDoesNotFitLeavesNoFileAndSaysNoRecordingWasMade) {
  const fs::path path = dir_ / "tiny.vem";
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    std::signal(SIGXFSZ, SIG_IGN);
    rlimit unlimited{};
    ::getrlimit(RLIMIT_FSIZE, &unlimited);
    const rlimit limit{64, unlimited.rlim_max};
    ::setrlimit(RLIMIT_FSIZE, &limit);
    auto writer = recording::RecordingWriter::create(path, smallHeader());
    if (writer) ::_exit(10);
    ::setrlimit(RLIMIT_FSIZE, &unlimited);  // room again for the report
    std::ofstream(dir_ / "message.txt") << writer.error().message;
    ::_exit(writer.error().cause == RecordingError::WriteFailed ? 0 : 11);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status));
  ASSERT_EQ(WEXITSTATUS(status), 0) << "10: the header was written; 11: another cause";
  const std::vector<char> message = readBytes(dir_ / "message.txt");
  EXPECT_EQ(std::string(message.begin(), message.end()),
            path.string() + ": cannot write the header (File too large); no recording was made");
  EXPECT_FALSE(fs::exists(path)) << "no file is left behind";
}

TEST_F(Errors, WriterNeverRewritesEarlierBytes) {
  const recording::RecordingHeader header = smallHeader();
  const fs::path path = dir_ / "a.vem";
  auto writer = recording::RecordingWriter::create(path, header);
  ASSERT_TRUE(writer);
  std::vector<char> before = readBytes(path);
  for (int i = 0; i < 4; ++i) {
    ASSERT_TRUE(writer->append(std::uint64_t(i), i, smallFrame(header, i)));
    const std::vector<char> after = readBytes(path);
    ASSERT_GT(after.size(), before.size());
    ASSERT_TRUE(std::equal(before.begin(), before.end(), after.begin())) << "frame " << i;
    before = after;
  }
  ASSERT_TRUE(writer->close());
  const std::vector<char> closed = readBytes(path);
  EXPECT_TRUE(std::equal(before.begin(), before.end(), closed.begin()));
}

// The file size limit (RLIMIT_FSIZE) makes write() fail part-way through a record, like a full
// disk; run in a child so the limit does not touch the test process.
TEST_F(Errors, WriteErrorMidRecordingReturnsAValueAndTheFramesWrittenStayReadable) {
  const fs::path path = dir_ / "limited.vem";
  const recording::RecordingHeader header = smallHeader();
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    std::signal(SIGXFSZ, SIG_IGN);
    const rlimit limit{20000, 20000};
    ::setrlimit(RLIMIT_FSIZE, &limit);
    auto writer = recording::RecordingWriter::create(path, header);
    if (!writer) ::_exit(200);
    int written = 0;
    for (int i = 0; i < 100; ++i) {
      auto done = writer->append(std::uint64_t(i), i * kPeriodNs, smallFrame(header, i));
      if (!done) {
        const bool clear =
            done.error().cause == RecordingError::WriteFailed &&
            done.error().message.find("File too large") != std::string::npos &&
            done.error().message.find("the " + std::to_string(written) +
                                      " frames before it stay readable") != std::string::npos;
        (void)writer->close();  // fails too (no room for the index): must not crash
        ::_exit(clear ? written : 201);
      }
      ++written;
    }
    ::_exit(202);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status));
  const int written = WEXITSTATUS(status);
  ASSERT_LT(written, 200) << "the child saw no clear error value (" << written << ")";
  ASSERT_GT(written, 0);
  auto reader = recording::RecordingReader::open(path);
  ASSERT_TRUE(reader) << reader.error().message;
  const ReadBack back = readAll(*reader);
  ASSERT_EQ(back.frames.size(), std::size_t(written));
  for (int i = 0; i < written; ++i) {
    EXPECT_EQ(back.frames[std::size_t(i)].frame.codes, smallFrame(header, i).codes);
  }
  EXPECT_EQ(back.damage.damagedRecords, 0U);
  EXPECT_EQ(back.damage.truncatedTailBytes, 0U) << "the partial record was cut off again";
  EXPECT_LE(readBytes(path).size(), 20000U);
}

// File names went into the messages raw: a newline in one forged a second line in vemd's log.
TEST_F(Errors, FailureMessagesEscapeAFileNameWithANewlineAndABadByte) {
  const fs::path missing = dir_ / "no\nsuch\xff.vem";
  auto reader = recording::RecordingReader::open(missing);
  ASSERT_FALSE(reader);
  EXPECT_EQ(reader.error().message, dir_.string() + "/no\\nsuch\\xff.vem: no such file");

  const fs::path nowhere = dir_ / "gone\r" / "a.vem";
  auto writer = recording::RecordingWriter::create(nowhere, smallHeader());
  ASSERT_FALSE(writer);
  EXPECT_EQ(
      writer.error().message,
      dir_.string() + "/gone\\r/a.vem: cannot create the recording (No such file or directory)");
}

}  // namespace
}  // namespace vem::testing
