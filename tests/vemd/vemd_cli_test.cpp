// The built `vemd` as a user runs it: a small recording replayed with --frames, the final report,
// a clean stop on SIGTERM that leaves an indexed recording, and bad usage.
#include <netinet/in.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "recording/recording_reader.h"
#include "stream_e2e/vemd_process.h"
#include "support/command_run.h"
#include "vemd_fixtures.h"

namespace vem::testing {
namespace {

class VemdCli : public VemdFiles {
 protected:
  void SetUp() override {
    VemdFiles::SetUp();
    // Streaming on a free port, so that no run depends on 8765 being free.
    std::ofstream(smallConfig()) << "[processing]\nmap_width = 256\nmap_height = 64\n"
                                    "[stream]\nlisten = \"127.0.0.1:0\"\n";
  }
  // Small maps keep the runs fast; flags come after it and override.
  fs::path smallConfig() const { return dir_ / "small.toml"; }
  std::string vemd() const { return commandLine(VEMD_PATH, "--config " + smallConfig().string()); }

  // `args` after --config small.toml, or alone when `withSmallConfig` is false.
  CommandRun run(const std::string& args, bool withSmallConfig = true) const {
    const std::string program = withSmallConfig ? vemd() : std::string(VEMD_PATH);
    return runCommand(program + " " + args, dir_);
  }
};

TEST_F(VemdCli, ReplaysNFramesAndPrintsTheFinalReport) {
  const fs::path path = dir_ / "sky.vem";
  writeSkyRecording(path, 6, false);
  const CommandRun r = run("--source replay:" + path.string() +
                           " --rate max --frames 4 --lights 64 --stats-every 0");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("final "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(": 4 in, 4 processed ("), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("0 dropped"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("stages us mean/max: calibrate "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("stopping: the frame limit was reached"), std::string::npos) << r.err;
}

TEST_F(VemdCli, WritesTheLightsOfEveryFrameToTheJsonlFile) {
  const fs::path path = dir_ / "sky.vem";
  writeSkyRecording(path, 5, false);
  const CommandRun r = run("--source replay:" + path.string() + " --rate max --lights 16 --out " +
                           dir_.string() + " --jsonl lights.jsonl");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const std::string lines = readTextFile(dir_ / "lights.jsonl");
  EXPECT_EQ(std::count(lines.begin(), lines.end(), '\n'), 5) << lines;
}

// SIGTERM stops the daemon cleanly: exit 0, and the recording it was making has its index.
// The README's main job points --out at a folder that does not exist yet.
TEST_F(VemdCli, OutFolderThatDoesNotExistYetIsCreatedWithJsonlAndNumberedPreviews) {
  const fs::path path = dir_ / "sky.vem";
  writeSkyRecording(path, 5, false);
  const fs::path out = dir_ / "new" / "out";
  const CommandRun r =
      run("--source replay:" + path.string() + " --rate max --lights 16 --out " + out.string() +
          " --jsonl lights.jsonl --preview-every 2 --preview-numbered");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const std::string lines = readTextFile(out / "lights.jsonl");
  EXPECT_EQ(std::count(lines.begin(), lines.end(), '\n'), 5) << lines;
  EXPECT_TRUE(fs::exists(out / "preview.png"));
  for (const char* kept :
       {"preview-0000000000.png", "preview-0000000002.png", "preview-0000000004.png"}) {
    EXPECT_TRUE(fs::exists(out / kept)) << kept;
  }
  EXPECT_FALSE(fs::exists(out / "preview-0000000001.png"));
}

TEST_F(VemdCli, OutPathThatIsAFileIsRefusedInOneSentence) {
  const fs::path path = dir_ / "sky.vem";
  writeSkyRecording(path, 2, false);
  std::ofstream(dir_ / "a-file") << "x";
  const CommandRun r = run("--source replay:" + path.string() + " --out " +
                           (dir_ / "a-file").string() + " --jsonl lights.jsonl");
  EXPECT_EQ(r.exitCode, 1) << r.err;
  EXPECT_NE(
      r.err.find("output.dir: cannot use " + (dir_ / "a-file").string() + " as the output folder"),
      std::string::npos)
      << r.err;
}

TEST_F(VemdCli, SigtermStopsCleanlyAndTheRecordingGetsItsIndex) {
  const fs::path path = dir_ / "sky.vem";
  writeSkyRecording(path, 4, false);
  const fs::path recorded = dir_ / "out.vem";
  const fs::path err = dir_ / "stderr";
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    const std::string source = "replay:" + path.string();
    const std::string record = recorded.string();
    (void)std::freopen(err.c_str(), "w", stderr);
    const std::string config = smallConfig().string();
    ::execl(VEMD_PATH, VEMD_PATH, "--config", config.c_str(), "--source", source.c_str(), "--loop",
            "--rate", "100", "--lights", "16", "--record", record.c_str(), "--stats-every", "0",
            static_cast<char*>(nullptr));
    std::_Exit(127);
  }
  // Wait until a few frames are recorded (the file grows), then ask it to stop.
  bool recording = false;
  for (int i = 0; i < 600 && !recording; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    std::error_code error;
    const std::uintmax_t size = fs::file_size(recorded, error);
    recording = !error && size > 200'000;
  }
  ::kill(pid, SIGTERM);
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(recording) << readTextFile(err);
  ASSERT_TRUE(WIFEXITED(status)) << readTextFile(err);
  EXPECT_EQ(WEXITSTATUS(status), 0) << readTextFile(err);
  EXPECT_NE(readTextFile(err).find("stopping: a stop was requested"), std::string::npos)
      << readTextFile(err);
  auto reader = recording::RecordingReader::open(recorded);
  ASSERT_TRUE(reader) << reader.error().message;
  EXPECT_TRUE(reader->hasIndex());
  EXPECT_GE(reader->index().size(), 2u);
}

// The synthetic source through a configuration file (its camera is a small one), paced at its
// own rate: a live clock, so the report has the latency from capture.
TEST_F(VemdCli, SyntheticSceneFromAConfigFileReportsLatencyFromCapture) {
  const fs::path camera = dir_ / "cam.toml";
  ASSERT_TRUE(calib::io::saveCameraFile(smallCamera(), camera));
  const fs::path config = dir_ / "vemd.toml";
  std::ofstream(config) << "[source]\nspec = \"synthetic:sky\"\nrate = 200\nframes = 5\n"
                           "camera = \""
                        << camera.string()
                        << "\"\n[processing]\n"
                           "map_width = 256\nmap_height = 64\nlights = 64\n"
                           "[stream]\nlisten = \"127.0.0.1:0\"\n";
  const CommandRun r = run("--config " + config.string(), false);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("5 in, "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("; from capture to sinks done "), std::string::npos) << r.err;
}

// Catches `vemd --record runs/` never saying which file it created (issue 17): the name is logged
// at start, in every statistics line and in the final one.
TEST_F(VemdCli, RecordingIntoAFolderNamesTheFileAtStartAndInTheStatistics) {
  const fs::path path = dir_ / "sky.vem";
  writeSkyRecording(path, 12, false);
  const fs::path runs = dir_ / "runs";
  fs::create_directories(runs);
  const CommandRun r = run("--source replay:" + path.string() +
                           " --rate 30 --lights 16 --stats-every 0.1 --record " + runs.string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  ASSERT_EQ(std::distance(fs::directory_iterator(runs), fs::directory_iterator()), 1);
  const std::string file = fs::directory_iterator(runs)->path().string();
  EXPECT_NE(r.err.find("info: recording to " + file + "\n"), std::string::npos) << r.err;
  const std::size_t final = r.err.find("info: final ");
  ASSERT_NE(final, std::string::npos) << r.err;
  EXPECT_NE(r.err.find("; recording to " + file + "\n", final), std::string::npos) << r.err;
  const std::size_t stats = r.err.find("info: stats ");
  ASSERT_NE(stats, std::string::npos) << r.err;
  EXPECT_LT(r.err.find("; recording to " + file + "\n", stats), final) << r.err;
}

// A paced replay with a report every 0.1 s: the periodic statistics lines come while it runs.
TEST_F(VemdCli, PrintsAStatisticsLineEveryFewSecondsWhileRunning) {
  const fs::path path = dir_ / "sky.vem";
  writeSkyRecording(path, 12, false);
  const CommandRun r =
      run("--source replay:" + path.string() + " --rate 30 --lights 16 --stats-every 0.1");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("info: stats 0."), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("info: final "), std::string::npos) << r.err;
}

// A datagram socket standing in for systemd's notification socket: run() starts `command` (a
// shell line) with NOTIFY_SOCKET pointing here and reads every message while it runs, as systemd
// does (a full socket queue would block vemd's sd_notify).
class NotifySocket {
 public:
  explicit NotifySocket(const fs::path& path) : path_(path) {
    fd_ = ::socket(AF_UNIX, SOCK_DGRAM | SOCK_NONBLOCK, 0);
    sockaddr_un address{};
    address.sun_family = AF_UNIX;
    if (fd_ < 0 || path.string().size() >= sizeof address.sun_path) return;
    std::copy_n(path.c_str(), path.string().size(), address.sun_path);
    bound_ = ::bind(fd_, reinterpret_cast<const sockaddr*>(&address), sizeof address) == 0;
  }
  ~NotifySocket() {
    if (fd_ >= 0) ::close(fd_);
  }
  [[nodiscard]] bool bound() const { return bound_; }

  // The exit status of `NOTIFY_SOCKET=PATH command`, collecting its messages.
  int run(const std::string& command) {
    const std::string line = "NOTIFY_SOCKET=" + path_.string() + " " + command;
    std::atomic<bool> finished{false};
    int status = -1;
    std::thread daemon([&] {
      status = std::system(line.c_str());
      finished = true;
    });
    char buffer[4096];
    for (;;) {
      const bool last = finished.load();
      for (ssize_t n; (n = ::recv(fd_, buffer, sizeof buffer, 0)) > 0;) {
        messages_.emplace_back(buffer, std::size_t(n));
      }
      if (last) break;
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    daemon.join();
    return status;
  }

  // The index of the first message starting with `prefix`, or -1.
  [[nodiscard]] int position(const std::string& prefix) const {
    for (std::size_t i = 0; i < messages_.size(); ++i) {
      if (messages_[i].rfind(prefix, 0) == 0) return int(i);
    }
    return -1;
  }

 private:
  fs::path path_;
  int fd_ = -1;
  bool bound_ = false;
  std::vector<std::string> messages_;
};

// Under systemd (NOTIFY_SOCKET, WATCHDOG_USEC set), vemd says READY=1 after its first frame,
// pings the watchdog, publishes its report lines as STATUS= and says STOPPING=1.
TEST_F(VemdCli, TellsTheServiceManagerReadyWatchdogStatusAndStopping) {
  NotifySocket systemd(dir_ / "notify");
  ASSERT_TRUE(systemd.bound());
  const fs::path path = dir_ / "sky.vem";
  writeSkyRecording(path, 12, false);
  const int status =
      systemd.run("WATCHDOG_USEC=100000 " + vemd() + " --source replay:" + path.string() +
                  " --rate 60 --lights 16 --stats-every 0.05 2>" + (dir_ / "err").string());
  ASSERT_EQ(status, 0) << readTextFile(dir_ / "err");
  ASSERT_GE(systemd.position("READY=1"), 0);
  EXPECT_GE(systemd.position("WATCHDOG=1"), 0);
  EXPECT_GE(systemd.position("STATUS=stats "), 0);
  ASSERT_GE(systemd.position("STOPPING=1"), 0);
  EXPECT_LT(systemd.position("READY=1"), systemd.position("STOPPING=1"));
}

// Catches a start-up that systemd would kill at TimeoutStartSec while it still makes progress (a
// slower machine, the largest map): vemd asks for more time (EXTEND_TIMEOUT_USEC, 10 s from each
// message) from its start-up steps, before it is ready.
TEST_F(VemdCli, StartUpAsksTheServiceManagerForMoreTimeWhileItMakesProgress) {
  NotifySocket systemd(dir_ / "notify");
  ASSERT_TRUE(systemd.bound());
  const fs::path path = dir_ / "sky.vem";
  writeSkyRecording(path, 2, false);
  const int status =
      systemd.run(vemd() + " --source replay:" + path.string() +
                  " --rate max --lights 16 --stats-every 0 2>" + (dir_ / "err").string());
  ASSERT_EQ(status, 0) << readTextFile(dir_ / "err");
  const int extended = systemd.position("EXTEND_TIMEOUT_USEC=10000000");
  ASSERT_GE(extended, 0);
  EXPECT_LT(extended, systemd.position("READY=1"));
}

// Catches SIGTERM during start-up taking effect only once start-up is over (a 16384 x 16384 map
// went on for 55 s after it): vemd is stopped while it builds the largest polar remap it accepts,
// between two rows, and exits as cleanly as from the loop (0), without running a frame. The
// 60 s bound only guards against a hang.
TEST_F(VemdCli, SigtermWhileBuildingThePolarRemapStopsStartUpCleanly) {
  const fs::path config = dir_ / "largest-map.toml";
  std::ofstream(config) << "[processing]\nmap_width = 4096\nmap_height = 2048\n"
                           "[stream]\nenabled = false\n";
  auto vemd =
      e2e::VemdProcess::spawn(VEMD_PATH, {"--config", config.string(), "--source", "synthetic:sky",
                                          "--rate", "max", "--frames", "1", "--stats-every", "0"});
  ASSERT_TRUE(vemd) << vemd.error();
  ASSERT_TRUE((*vemd)->waitForStderr("starting: building the 4096 x 2048 polar remap",
                                     std::chrono::seconds(60)))
      << (*vemd)->stderrText();
  (*vemd)->signal(SIGTERM);
  const std::optional<int> status = (*vemd)->waitForExit(std::chrono::seconds(60));
  ASSERT_TRUE(status) << "still running 60 s after SIGTERM:\n" << (*vemd)->stderrText();
  const std::string err = (*vemd)->stderrText();
  EXPECT_EQ(*status, 0) << err;
  EXPECT_NE(err.find("stopping during start-up: a stop was requested while building the polar "
                     "remap"),
            std::string::npos)
      << err;
  EXPECT_EQ(err.find("running:"), std::string::npos) << err;
}

// Catches vemd accepting a token no one should use (issue 16: a one-character token was
// accepted): a token file holding 5 bytes stops it before its start-up, exit 1, one sentence that
// names the key and the file, not the token.
TEST_F(VemdCli, TokenFileWithAShortTokenRefusesToStartInOneSentence) {
  const fs::path token = dir_ / "token";
  std::ofstream(token) << "s3crt\n";
  fs::permissions(token, fs::perms::owner_read | fs::perms::owner_write);
  const fs::path config = dir_ / "vemd.toml";
  std::ofstream(config) << "[stream]\ntoken_file = \"" << token.string() << "\"\n";
  const CommandRun r =
      run("--config " + config.string() + " --source synthetic:sky --frames 1", false);
  EXPECT_EQ(r.exitCode, 1) << r.err;
  EXPECT_NE(r.err.find("error: stream.token_file: " + token.string() +
                       ": expected a token of 16 to 1024 visible ASCII characters without white "
                       "space (`openssl rand -hex 32` makes one), found a token of 5 bytes\n"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(r.err.find("s3crt"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("starting:"), std::string::npos) << r.err;
}

// Catches a white-space token being accepted (issue 16: on 0.0.0.0 vemd started and every client
// got 401, since HTTP trims it): refused in the configuration, exit 2, on any listener.
TEST_F(VemdCli, WhiteSpaceOnlyTokenRefusesToStart) {
  const fs::path config = dir_ / "vemd.toml";
  std::ofstream(config) << "[stream]\nlisten = \"127.0.0.1:0\"\ntoken = \"   \"\n";
  const CommandRun r =
      run("--config " + config.string() + " --source synthetic:sky --frames 1", false);
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_EQ(r.err, config.string() +
                       ": stream.token: expected a token of 16 to 1024 visible ASCII characters "
                       "without white space (`openssl rand -hex 32` makes one), found white space "
                       "at byte 1 of 3\n");
}

// Catches help that shows CLI11's internals ("->", "ENUM", "{false}") or leaves out the exit
// statuses, and exit statuses off the tools' conventions (util/cli_conventions.h): 0 for --help,
// 2 for an unknown flag (one error line naming the help), 1 for a failure at run time.
TEST_F(VemdCli, HelpIsPlainTextAndExitStatusesFollowTheConventions) {
  const CommandRun help = run("--help", false);
  EXPECT_EQ(help.exitCode, 0) << help.err;
  for (const char* internal : {"->", "ENUM", "{false}", "{true}"}) {
    EXPECT_EQ(help.out.find(internal), std::string::npos) << internal << " in\n" << help.out;
  }
  EXPECT_NE(help.out.find("Exit status: 0 success, 1 failure at run time, 2 usage error"),
            std::string::npos)
      << help.out;
  EXPECT_NE(help.out.find("--lights N (default: 1024)"), std::string::npos) << help.out;
  EXPECT_NE(help.out.find("holds a\nbad key is a usage error (exit 2)"), std::string::npos)
      << help.out;

  const CommandRun badFlag = run("--no-such-flag", false);
  EXPECT_EQ(badFlag.exitCode, 2) << badFlag.err;
  EXPECT_NE(badFlag.err.find("vemd: error: "), std::string::npos) << badFlag.err;
  EXPECT_NE(badFlag.err.find("(see 'vemd --help')\n"), std::string::npos) << badFlag.err;

  const CommandRun missingReplay =
      run("--stream-listen '' --source replay:" + (dir_ / "missing.vem").string());
  EXPECT_EQ(missingReplay.exitCode, 1) << missingReplay.err;
  EXPECT_NE(missingReplay.err.find("missing.vem: no such file"), std::string::npos)
      << missingReplay.err;

  const CommandRun missingConfig = run("--config " + (dir_ / "missing.toml").string(), false);
  EXPECT_EQ(missingConfig.exitCode, 2) << missingConfig.err;
}

// A TCP socket listening on a free loopback port, taken for as long as it lives.
class TakenPort {
 public:
  TakenPort() {
    fd_ = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t length = sizeof address;
    if (fd_ < 0 || ::bind(fd_, reinterpret_cast<const sockaddr*>(&address), length) != 0 ||
        ::listen(fd_, 1) != 0 ||
        ::getsockname(fd_, reinterpret_cast<sockaddr*>(&address), &length) != 0) {
      return;
    }
    port_ = ntohs(address.sin_port);
  }
  ~TakenPort() {
    if (fd_ >= 0) ::close(fd_);
  }
  [[nodiscard]] int port() const { return port_; }  // 0: not taken

 private:
  int fd_ = -1;
  int port_ = 0;
};

// Catches vemd exiting 0 with "0 sink(s)" when the stream port is taken (issue 17): a daemon
// whose configured outputs cannot open looked healthy and served no one. It stops, exit 1, one
// sentence naming the address and the key that would let it run; with --allow-missing-outputs it
// runs the frames asked for and warns.
TEST_F(VemdCli, StreamPortTakenStopsVemdUnlessMissingOutputsAreAllowed) {
  const TakenPort taken;
  ASSERT_NE(taken.port(), 0);
  const std::string address = "127.0.0.1:" + std::to_string(taken.port());
  const std::string args =
      "--source synthetic:sky --rate max --frames 2 --lights 16 "
      "--stats-every 0 --stream-listen " +
      address;
  const CommandRun refused = run(args);
  EXPECT_EQ(refused.exitCode, 1) << refused.err;
  EXPECT_NE(refused.err.find("error: stream.listen: cannot listen on " + address + " ("),
            std::string::npos)
      << refused.err;
  EXPECT_NE(refused.err.find("vemd does not run without a configured output unless allowed to "
                             "(--allow-missing-outputs, or output.allow_missing = true)\n"),
            std::string::npos)
      << refused.err;
  EXPECT_EQ(refused.err.find("running:"), std::string::npos) << refused.err;

  const CommandRun allowed = run(args + " --allow-missing-outputs");
  EXPECT_EQ(allowed.exitCode, 0) << allowed.err;
  EXPECT_NE(allowed.err.find("warning: stream.listen: cannot listen on " + address),
            std::string::npos)
      << allowed.err;
  EXPECT_NE(allowed.err.find("vemd runs without this output (output.allow_missing)"),
            std::string::npos)
      << allowed.err;
  EXPECT_NE(allowed.err.find("2 in, 2 processed"), std::string::npos) << allowed.err;
}

// The same for a file output: a JSON-lines file in a folder that does not exist.
TEST_F(VemdCli, JsonlFileThatCannotOpenStopsVemdUnlessMissingOutputsAreAllowed) {
  const fs::path path = dir_ / "sky.vem";
  writeSkyRecording(path, 2, false);
  const std::string args = "--source replay:" + path.string() +
                           " --rate max --lights 16 --stats-every 0 --jsonl " +
                           (dir_ / "no-such-folder" / "lights.jsonl").string();
  const CommandRun refused = run(args);
  EXPECT_EQ(refused.exitCode, 1) << refused.err;
  EXPECT_NE(refused.err.find("no-such-folder/lights.jsonl"), std::string::npos) << refused.err;
  EXPECT_NE(refused.err.find("(--allow-missing-outputs, or output.allow_missing = true)"),
            std::string::npos)
      << refused.err;
  const CommandRun allowed = run(args + " --allow-missing-outputs");
  EXPECT_EQ(allowed.exitCode, 0) << allowed.err;
  EXPECT_NE(allowed.err.find("vemd runs without this output"), std::string::npos) << allowed.err;
}

// Catches libcamera's coloured log lines ("\x1b[1;33m WARN \x1b[1;37mIPAManager ...") leaking into
// piped output of `vemd --list-devices`: neither stdout nor stderr holds an ESC byte. Run in a
// network namespace with loopback alone (Aravis's discovery broadcasts), skipped where none can
// be made.
TEST_F(VemdCli, ListDevicesPipedHasNoAnsiEscapesFromLibcamera) {
  const std::string netns =
      "sh " + (fs::path(VEM_SOURCE_DIR) / "tests" / "support" / "run_in_netns.sh").string();
  const CommandRun r = runCommand("env -u LIBCAMERA_LOG_NO_COLOR -u LIBCAMERA_LOG_LEVELS " + netns +
                                      " " + VEMD_PATH + " --list-devices",
                                  dir_);
  if (r.exitCode == 77) GTEST_SKIP() << r.err;
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("libcamera:"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find('\x1b'), std::string::npos) << r.out;
  EXPECT_EQ(r.err.find('\x1b'), std::string::npos) << r.err;
}

// --log-format json: every line vemd logs is one JSON object (time, level, logger, message), also
// the error naming a file whose name holds a quote; --quiet leaves warnings and errors only.
TEST_F(VemdCli, JsonLogFormatGivesOneJsonObjectPerLineAndQuietKeepsErrors) {
  const fs::path missing = dir_ / "say \"no\".vem";
  const std::string args =
      "--stream-listen '' --source 'replay:" + missing.string() + "' --log-format json";
  const CommandRun r = run(args);
  EXPECT_EQ(r.exitCode, 1) << r.err;
  std::istringstream lines(r.err);
  std::vector<nlohmann::json> logged;
  for (std::string line; std::getline(lines, line);) {
    ASSERT_TRUE(nlohmann::json::accept(line)) << line;
    logged.push_back(nlohmann::json::parse(line));
  }
  ASSERT_GE(logged.size(), 2u) << r.err;
  EXPECT_EQ(logged.front().at("level"), "info");
  EXPECT_EQ(logged.back().at("level"), "error");
  EXPECT_EQ(logged.back().at("logger"), "vemd");
  EXPECT_EQ(logged.back().at("message"), missing.string() + ": no such file");

  const CommandRun quiet = run(args + " --quiet");
  EXPECT_EQ(quiet.exitCode, 1) << quiet.err;
  EXPECT_EQ(std::count(quiet.err.begin(), quiet.err.end(), '\n'), 1) << quiet.err;
  EXPECT_NE(quiet.err.find("\"level\":\"error\""), std::string::npos) << quiet.err;
}

TEST_F(VemdCli, MissingSourceExitsWithOneSentence) {
  const CommandRun r = run("--frames 1");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("no source given: expected --source"), std::string::npos) << r.err;
}

TEST_F(VemdCli, BadFlagExitsWithUsageStatus) {
  const CommandRun r = run("--lights 0");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("--lights: expected a whole number from 1 to 65536, found 0"),
            std::string::npos)
      << r.err;
}

// `vemd --source replay:F.vem` on a recording with a valid header and no intact frame exited 0
// as if it had replayed it. It fails at start with one sentence naming the file.
TEST_F(VemdCli, ReplayOfARecordingWithNoIntactFrameExitsNonZeroNamingTheFile) {
  const fs::path empty = dir_ / "empty.vem";
  writeSkyRecording(empty, 0, false);
  const fs::path damaged = dir_ / "damaged.vem";
  writeSkyRecording(damaged, 2, false);
  {
    std::vector<std::uint64_t> offsets;
    auto reader = recording::RecordingReader::open(damaged);
    ASSERT_TRUE(reader && reader->hasIndex());
    for (const recording::IndexEntry& entry : reader->index()) offsets.push_back(entry.offset);
    std::fstream file(damaged, std::ios::in | std::ios::out | std::ios::binary);
    for (const std::uint64_t offset : offsets) {
      file.seekp(std::streamoff(offset + 12));  // the CRC field: the record no longer checks
      file.write("\xff\xff\xff\xff", 4);
    }
    ASSERT_TRUE(file.good());
  }
  for (const fs::path& path : {empty, damaged}) {
    const CommandRun r = run("--source replay:" + path.string() + " --rate max --stats-every 0");
    EXPECT_EQ(r.exitCode, 1) << path << "\n" << r.err;
    EXPECT_NE(r.err.find("error: " + path.string() +
                         ": the recording holds no intact frame (damaged records: "),
              std::string::npos)
        << r.err;
    EXPECT_EQ(r.err.find("final "), std::string::npos) << "no run was started: " << r.err;
  }
}

TEST_F(VemdCli, RecordingFromAnotherCameraIsRefusedAtStart) {
  // A recording whose calibration is for another sensor size cannot be calibrated.
  recording::RecordingHeader header = smallRecordingHeader();
  calib::CameraCalibration other = cameraTruth(640, 512, 1);
  header.calibrationToml = calib::io::formatCameraFile(other);
  const fs::path path = dir_ / "other.vem";
  {
    auto writer = recording::RecordingWriter::create(path, header);
    ASSERT_TRUE(writer);
    ASSERT_TRUE(writer->append(0, 0, cachedSkyFrame(0)));
    ASSERT_TRUE(writer->close());
  }
  const CommandRun r = run("--source replay:" + path.string());
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("the frames are 320 x 256 Mono12 but the calibration is for a 640 x 512 "
                       "Mono12 camera"),
            std::string::npos)
      << r.err;
}

}  // namespace
}  // namespace vem::testing
