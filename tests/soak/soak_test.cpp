// The soak test (issue 16, label `soak`): a real vemd replays a recording at 30 Hz in a loop,
// records and streams, while all of these run at once against it on loopback:
// - churning clients (connect, read the hello, close or drop, again);
// - clients that subscribe to cube maps and never read (vemd closes them; they come back);
// - a slow reader (a quarter of the stream's byte rate);
// - clients asking for large cube maps often (with the token: 512 px, 8 levels, 60 Hz) and
//   read-only ones at their budget;
// - a handshake flood (100 half-sent upgrade requests from 127.0.0.2, re-opened as closed);
// - malformed messages (garbage, oversized, text, another protocol major).
// Pass: the processed rate within 5 % of the camera's, no frame dropped, the recording gap-free,
// vemd's RSS and file descriptors flat after warm-up (and back to their count once the attack
// ends), a well-behaved client's frame age bounded, the log under its bound. The figures go to
// stdout and, with VEM_SOAK_REPORT=FILE, into FILE as Markdown (docs/BENCHMARKS.md, "Under
// attack").
//
// VEM_SOAK_SECONDS (default 60) sets the attack's length; every loop is bounded by it and every
// wait by a timeout. The attackers and clients share the machine's two cores with vemd; they stand
// for machines elsewhere on the network, so their threads run at nice 10 (VEM_SOAK_CLIENT_NICE):
// the CPU they take is what is left once vemd's capture and processing threads (nice 0) are
// served, as with vemd's own cube-map worker (nice 10). What vemd's own threads spend on the attack
// still competes with capture at their own priorities; that is what is measured.
#include <sys/resource.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <mutex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/write.hpp>

#include "client/stream_client.h"
#include "recording/recording_reader.h"
#include "stream_e2e/raw_ws_client.h"
#include "stream_e2e/small_camera.h"
#include "stream_e2e/vemd_process.h"

namespace vem::soak {
namespace {

using namespace std::chrono_literals;
namespace fs = std::filesystem;
using e2e::RawConnectOptions;
using e2e::RawWsClient;
using e2e::VemdProcess;

constexpr double kCameraRateHz = 30.0;
constexpr int kLights = 1024;
const std::string kToken = "soak-token-0123456789abcdef-0123";

// Stated bounds (docs/BENCHMARKS.md, "Under attack").
constexpr double kRateTolerance = 0.05;      // of the camera's rate
constexpr double kMaxWellBehavedAgeS = 0.5;  // p99 of a reading client's frame age
constexpr double kLogBytesPerS = 3000.0;     // vemd's log while attacked
// vemd's RSS swings by a cube-map set (tens of MB) as buffers come and go; a leak shows as the
// second half's peak above the first half's (both after warm-up) by more than this.
constexpr double kMaxRssGrowthShare = 0.05;
constexpr long kMaxRssGrowthKb = 16 * 1024;

double soakSeconds() {
  const char* text = std::getenv("VEM_SOAK_SECONDS");
  const double seconds = text != nullptr ? std::atof(text) : 60.0;
  return std::clamp(seconds, 10.0, 24.0 * 3600.0);
}

std::int64_t unixNowNs() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(
             std::chrono::system_clock::now().time_since_epoch())
      .count();
}

// vemd's resident set (kB) and open descriptors, from /proc.
struct ProcessSample {
  double atS = 0.0;
  long rssKb = 0;
  long fds = 0;
};

ProcessSample sampleProcess(pid_t pid, double atS) {
  ProcessSample sample;
  sample.atS = atS;
  std::ifstream status("/proc/" + std::to_string(pid) + "/status");
  for (std::string line; std::getline(status, line);) {
    if (line.starts_with("VmRSS:")) sample.rssKb = std::atol(line.c_str() + 6);
  }
  std::error_code error;
  for (auto it = fs::directory_iterator("/proc/" + std::to_string(pid) + "/fd", error);
       !error && it != fs::directory_iterator(); it.increment(error)) {
    ++sample.fds;
  }
  return sample;
}

double percentile(std::vector<double> values, double p) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  return values[std::min(values.size() - 1, std::size_t(p * double(values.size())))];
}

// The number before `key` in vemd's final statistics line.
double finalFigure(const std::string& log, const std::string& key) {
  const std::size_t line = log.rfind("final ");
  if (line == std::string::npos) return -1.0;
  const std::size_t at = log.find(key, line);
  if (at == std::string::npos) return -1.0;
  std::size_t start = at;
  while (start > line && log[start - 1] == ' ') --start;
  std::size_t begin = log.rfind(' ', start - 1) + 1;
  if (log[begin] == '(') ++begin;
  return std::atof(log.substr(begin, start - begin).c_str());
}

class Soak : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("vem_soak_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override {
    if (vemd_ && HasFailure()) std::cerr << "--- vemd's stderr ---\n" << vemd_->stderrText();
    vemd_.reset();
    std::error_code ignored;
    fs::remove_all(dir_, ignored);
  }

  fs::path write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
    fs::permissions(dir_ / name, fs::perms::owner_read | fs::perms::owner_write);
    return dir_ / name;
  }

  fs::path dir_;
  std::unique_ptr<VemdProcess> vemd_;
};

// Everything the attackers count.
struct AttackCounts {
  std::atomic<std::uint64_t> churned{0};
  std::atomic<std::uint64_t> stalledConnections{0};
  std::atomic<std::uint64_t> malformedSent{0};
  std::atomic<std::uint64_t> floodOpened{0};
  std::atomic<std::uint64_t> slowFrames{0};
  std::mutex mutex;
  std::vector<double> slowAgesS;
};

// Attack rates: bounded, so that the attackers (on this machine, sharing its two cores with vemd)
// leave vemd the CPU a remote attacker would. vemd's own cost per connection is what is measured.
// VEM_SOAK_CHURN_PER_S overrides the churn rate (0: as fast as the threads go).
double churnPerSecond() {
  const char* text = std::getenv("VEM_SOAK_CHURN_PER_S");
  return text != nullptr ? std::max(0.0, std::atof(text)) : 40.0;  // per churning thread (3)
}
constexpr double kMalformedPerSecond = 20.0;

// VEM_SOAK_CLIENT_NICE (default 10): the nice value of the test's own threads once vemd runs.
// Set on the main thread before any client or attacker starts, so every thread created after it
// inherits it; 0 makes the test's threads compete with vemd's capture as equals.
int clientNice() {
  const char* text = std::getenv("VEM_SOAK_CLIENT_NICE");
  return text != nullptr ? std::atoi(text) : 10;
}

// Sleeps until the i-th event of a loop running at `perSecond` is due.
void pace(std::chrono::steady_clock::time_point start, int i, double perSecond) {
  if (perSecond <= 0.0) return;
  std::this_thread::sleep_until(start + std::chrono::duration_cast<std::chrono::nanoseconds>(
                                            std::chrono::duration<double>(double(i) / perSecond)));
}

void churn(std::uint16_t port, const std::atomic<bool>& running, AttackCounts& counts, int k) {
  const auto start = std::chrono::steady_clock::now();
  const double perSecond = churnPerSecond();
  for (int i = 0; running.load(); ++i) {
    pace(start, i, perSecond);
    RawWsClient client;
    RawConnectOptions options;
    options.timeout = 5s;
    if (client.connect(port, options) != 0) continue;
    ++counts.churned;
    if ((i + k) % 2 == 0) {
      client.close(2s);
    } else {
      client.drop();
    }
  }
}

void neverRead(std::uint16_t port, const std::atomic<bool>& running, AttackCounts& counts) {
  while (running.load()) {
    RawWsClient client;
    RawConnectOptions options;
    options.receiveBufferBytes = 4096;
    options.timeout = 5s;
    if (client.connect(port, options) != 0) continue;
    ++counts.stalledConnections;
    stream::ClientMessage subscribe;
    subscribe.mutable_subscribe()->set_lights(true);
    subscribe.mutable_subscribe()->set_cubemap_rate_hz(10.0);
    subscribe.mutable_subscribe()->set_cubemap_face_px(256);
    (void)client.send(subscribe, 5s);
    // Never read: vemd closes it once it is max_client_lag_ms behind; then come back.
    for (int i = 0; i < 200 && running.load(); ++i) std::this_thread::sleep_for(50ms);
    client.drop();
  }
}

void malformed(std::uint16_t port, const std::atomic<bool>& running, AttackCounts& counts) {
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; running.load(); ++i) {
    pace(start, i, kMalformedPerSecond);
    RawWsClient client;
    RawConnectOptions options;
    options.timeout = 5s;
    if (client.connect(port, options) != 0) continue;
    stream::ClientMessage message;
    switch (i % 3) {
      case 0: message.set_protocol_major(7); break;  // another major: close 1002
      case 1: message.mutable_control()->set_set_light_count(0); break;  // refused (no token)
      default:
        message.mutable_subscribe()->set_cubemap_face_px(100000);  // out of range
        break;
    }
    (void)client.send(message, 2s);
    ++counts.malformedSent;
    (void)client.readBytes(500ms);
    client.drop();
  }
}

void flood(std::uint16_t port, const std::atomic<bool>& running, AttackCounts& counts) {
  boost::asio::io_context ioc;
  std::vector<std::unique_ptr<boost::asio::ip::tcp::socket>> sockets;
  while (running.load()) {
    std::erase_if(sockets, [](auto& s) {
      char byte;
      return ::recv(s->native_handle(), &byte, 1, MSG_DONTWAIT) == 0;
    });
    while (sockets.size() < 100 && running.load()) {
      auto socket = std::make_unique<boost::asio::ip::tcp::socket>(ioc);
      boost::system::error_code ec;
      socket->open(boost::asio::ip::tcp::v4(), ec);
      socket->bind({boost::asio::ip::make_address("127.0.0.2"), 0}, ec);
      socket->connect({boost::asio::ip::make_address("127.0.0.1"), port}, ec);
      if (ec) break;
      boost::asio::write(*socket, boost::asio::buffer(std::string("GET / HTTP/1.1\r\n")), ec);
      sockets.push_back(std::move(socket));
      ++counts.floodOpened;
    }
    std::this_thread::sleep_for(20ms);
  }
}

void slowReader(std::uint16_t port, const std::atomic<bool>& running, AttackCounts& counts) {
  RawWsClient reader;
  RawConnectOptions options;
  options.timeout = 10s;
  if (reader.connect(port, options) != 0) return;
  const auto start = std::chrono::steady_clock::now();
  double bytes = 0.0;
  const double bytesPerS = 30'000.0 * kCameraRateHz / 4.0;  // a quarter of ~30 kB frames at 30 Hz
  while (running.load()) {
    auto raw = reader.readBytes(10s);
    if (!raw) return;
    bytes += double(raw->size());
    stream::ServerMessage message;
    if (message.ParseFromString(*raw) && message.has_lights()) {
      ++counts.slowFrames;
      std::lock_guard lock(counts.mutex);
      counts.slowAgesS.push_back(double(unixNowNs() - message.lights().publish_unix_ns()) * 1e-9);
    }
    std::this_thread::sleep_until(start + std::chrono::duration_cast<std::chrono::nanoseconds>(
                                              std::chrono::duration<double>(bytes / bytesPerS)));
  }
  reader.close(2s);
}

TEST_F(Soak, VemdHoldsItsRateRecordingAndMemoryWhileEveryAttackRunsAtOnce) {
  const double seconds = soakSeconds();
  const fs::path camera = write("camera.toml", e2e::smallCameraToml());
  const std::string processing =
      "version = 1\n[source]\ncamera = \"" + camera.string() +
      "\"\n[processing]\nmap_width = 1024\nmap_height = 256\nlights = " + std::to_string(kLights) +
      "\n[clustering]\nenabled = true\nbudget = 16\n";
  // The recording vemd replays: 90 frames of the synthetic sky through the small camera.
  const fs::path source = dir_ / "source.vem";
  {
    auto maker = VemdProcess::spawn(
        VEMD_PATH,
        {"--config", write("make.toml", processing + "[stream]\nenabled = false\n").string(),
         "--source", "synthetic:sky", "--rate", "max", "--frames", "90", "--record",
         source.string(), "--stats-every", "0"});
    ASSERT_TRUE(maker.has_value()) << maker.error();
    const auto status = (*maker)->waitForExit(120s);
    ASSERT_TRUE(status && *status == 0) << (*maker)->stderrText();
  }
  const fs::path recording = dir_ / "during-soak.vem";
  const fs::path config =
      write("vemd.toml", processing + "[stream]\ntoken = \"" + kToken +
                             "\"\nmax_client_lag_ms = 3000\nhandshake_timeout_ms = 2000\n");
  auto spawned = VemdProcess::spawn(
      VEMD_PATH, {"--config", config.string(), "--source", "replay:" + source.string(), "--loop",
                  "--rate", fmt::format("{}", kCameraRateHz), "--record", recording.string(),
                  "--stream-listen", "127.0.0.1:0", "--stats-every", "0"});
  ASSERT_TRUE(spawned.has_value()) << spawned.error();
  vemd_ = std::move(*spawned);
  const auto port = vemd_->waitForPort(60s);
  ASSERT_TRUE(port) << "vemd did not start streaming";
  // From here on the test's threads stand for other machines (see the top of the file).
  const int testThreadsNice = clientNice();
  ASSERT_EQ(::setpriority(PRIO_PROCESS, static_cast<id_t>(::gettid()), testThreadsNice), 0)
      << "cannot set the test's threads to nice " << testThreadsNice;

  // The well-behaved client: reads every frame, measures each one's age.
  std::mutex agesMutex;
  std::vector<double> wellBehavedAgesS;
  client::StreamClientOptions wellBehaved;
  wellBehaved.url = fmt::format("ws://127.0.0.1:{}", *port);
  wellBehaved.onLightFrame = [&](const client::Received<client::LightFrame>& received) {
    std::lock_guard lock(agesMutex);
    wellBehavedAgesS.push_back(double(received.receivedUnixNs - received.frame.publishUnixNs) *
                               1e-9);
  };
  auto watcher = client::StreamClient::start(wellBehaved);
  ASSERT_TRUE(watcher.has_value()) << watcher.error();
  ASSERT_TRUE((*watcher)->waitForLightFrame(std::nullopt, 60s)) << "no frame before the attack";

  // Before the attack: vemd's descriptors with one client.
  const auto start = std::chrono::steady_clock::now();
  const auto elapsedS = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  const ProcessSample before = sampleProcess(vemd_->pid(), 0.0);

  std::atomic<bool> running{true};
  AttackCounts counts;
  std::vector<std::thread> attackers;
  for (int k = 0; k < 3; ++k)
    attackers.emplace_back(churn, *port, std::cref(running), std::ref(counts), k);
  for (int k = 0; k < 3; ++k)
    attackers.emplace_back(neverRead, *port, std::cref(running), std::ref(counts));
  attackers.emplace_back(malformed, *port, std::cref(running), std::ref(counts));
  attackers.emplace_back(flood, *port, std::cref(running), std::ref(counts));
  attackers.emplace_back(slowReader, *port, std::cref(running), std::ref(counts));
  std::vector<std::unique_ptr<client::StreamClient>> cubemapClients;
  for (int k = 0; k < 6; ++k) {
    client::StreamClientOptions options;
    options.url = wellBehaved.url;
    const bool token = k < 3;
    if (token) options.token = kToken;
    options.subscription.cubemapRateHz = token ? 60.0 : 10.0;
    options.subscription.cubemapFacePx = token ? 512 : 256;
    options.subscription.cubemapLevels = 8;
    options.subscription.preview = k % 2 == 0;
    auto started = client::StreamClient::start(options);
    ASSERT_TRUE(started.has_value()) << started.error();
    cubemapClients.push_back(std::move(*started));
  }

  std::vector<ProcessSample> samples;
  const double warmUpS = std::min(15.0, seconds / 4.0);
  while (elapsedS() < seconds) {
    std::this_thread::sleep_for(1s);
    samples.push_back(sampleProcess(vemd_->pid(), elapsedS()));
  }
  running = false;
  for (auto& t : attackers) t.join();
  std::uint64_t cubemapsReceived = 0;
  for (auto& c : cubemapClients) {
    cubemapsReceived += c->stats().environmentFrames;
    c->stop();
  }
  cubemapClients.clear();
  // After the attack: back to one client (the flood's and churn's sockets are gone).
  ProcessSample after;
  for (int i = 0; i < 200; ++i) {
    after = sampleProcess(vemd_->pid(), elapsedS());
    if (after.fds <= before.fds) break;
    std::this_thread::sleep_for(50ms);
  }
  (*watcher)->stop();
  vemd_->signal(SIGTERM);
  const auto exit = vemd_->waitForExit(60s);
  ASSERT_TRUE(exit.has_value()) << "vemd did not stop";
  EXPECT_EQ(*exit, 0);
  const std::string log = vemd_->stderrText();

  // The figures.
  const double processedRate = finalFigure(log, "frames/s)");
  const double processed = finalFigure(log, "processed");
  const double dropped = finalFigure(log, "dropped");
  std::vector<std::uint64_t> seqs;
  {
    auto reader = recording::RecordingReader::open(recording);
    ASSERT_TRUE(reader.has_value());
    for (;;) {
      auto frame = reader->next();
      if (!frame || !*frame) break;
      seqs.push_back((*frame)->seq);
    }
  }
  std::uint64_t gaps = 0;
  for (std::size_t i = 1; i < seqs.size(); ++i) gaps += seqs[i] != seqs[i - 1] + 1 ? 1 : 0;
  // Peaks of the two halves after warm-up.
  const double middleS = (warmUpS + seconds) / 2.0;
  long firstHalfPeakKb = 0, secondHalfPeakKb = 0, peakFds = 0;
  for (const ProcessSample& s : samples) {
    if (s.atS < warmUpS) continue;
    long& halfPeakKb = s.atS < middleS ? firstHalfPeakKb : secondHalfPeakKb;
    halfPeakKb = std::max(halfPeakKb, s.rssKb);
    peakFds = std::max(peakFds, s.fds);
  }
  const long endRssKb = samples.back().rssKb;
  double wellP50 = 0, wellP99 = 0, wellMax = 0;
  {
    std::lock_guard lock(agesMutex);
    wellP50 = percentile(wellBehavedAgesS, 0.5);
    wellP99 = percentile(wellBehavedAgesS, 0.99);
    wellMax = percentile(wellBehavedAgesS, 1.0);
  }
  const double slowP99 = percentile(counts.slowAgesS, 0.99);
  const double slowMax = percentile(counts.slowAgesS, 1.0);
  const double logBytesPerS = double(log.size()) / seconds;
  std::string rssQuarters;
  for (int q = 1; q <= 4; ++q) {
    const double atS = seconds * q / 4.0;
    const auto it =
        std::ranges::find_if(samples, [&](const ProcessSample& s) { return s.atS >= atS - 0.5; });
    if (it != samples.end())
      rssQuarters += fmt::format("{}{:.0f} s: {} kB", q > 1 ? ", " : "", it->atS, it->rssKb);
  }

  const std::string intro = fmt::format(
      "## Under attack (vem_soak_tests)\n\n"
      "`VEM_SOAK_SECONDS={:.0f} build/tests/soak/vem_soak_tests` (tests/soak/, label `soak`; "
      ".ci/run runs it alone for 60 s): the real vemd replays a 90-frame recording of the "
      "synthetic sky (320 x 256 RGB camera) in a loop at 30 frames/s into 1024 x 256 maps with "
      "1024 lights clustered toward 16, records every frame and streams, while on 127.0.0.1, all "
      "at once: 3 threads churn connections (close or drop), 3 clients subscribe to cube maps and "
      "never read, a malformed message every 50 ms, 100 half-sent upgrade requests from 127.0.0.2 "
      "re-opened as vemd closes them, a reader at a quarter of the stream's byte rate, 3 clients "
      "with the token asking for 512 px / 8 levels / 60 Hz cube maps and 3 read-only ones at the "
      "256 px / 10 Hz budget, and one well-behaved client measuring each frame's age. The "
      "attackers and clients share the machine's two cores with vemd at nice {} (they stand for "
      "other machines; vemd's capture and processing run at nice 0, its stream io thread at 5, "
      "its cube-map worker at 10). Release build.\n\n",
      seconds, testThreadsNice);
  const std::string comparison = fmt::format(
      "\nAgainst issue 16's measurements of the same attacks before the fixes (camera at 30 Hz; "
      "each attack alone there, all at once here); the floor is the camera's rate, no gap, and a "
      "frame no older than the time to read it:\n\n"
      "| what | before (issue 16) | now (this run) |\n|---|---|---|\n"
      "| processed rate while clients ask for large cube maps | 1.2-2 frames/s of 30 | {:.2f} "
      "frames/s, {:.0f} dropped |\n"
      "| a recording made meanwhile | 712 frames over seq 0..1308, gaps over 1 s | {} frames, {} "
      "gaps |\n"
      "| a slow reader's frame age | 0.14 s growing to 23 s (then closed for idling) | p99 {:.0f} "
      "ms, max {:.0f} ms, not closed |\n"
      "| a real client during a slowloris flood | 2 of 6 `vemtool subscribe` attempts connected, "
      "nothing logged | connected before the flood, kept receiving (p99 age {:.0f} ms); failed "
      "handshakes counted and logged within the budget |\n"
      "| the log while connections churn | 23 MB in 30 s (181k lines) | {:.0f} bytes/s over {} "
      "churned connections |\n",
      processedRate, dropped, seqs.size(), gaps, slowP99 * 1e3, slowMax * 1e3, wellP99 * 1e3,
      logBytesPerS, counts.churned.load());
  const std::string table = fmt::format(
      "| figure | measured | bound |\n|---|---:|---:|\n"
      "| attack length | {:.0f} s | |\n"
      "| churn rate asked (3 threads) | {} | |\n"
      "| processed rate (camera {:.0f} Hz) | {:.2f} frames/s | within {:.0f} % |\n"
      "| frames processed / dropped | {:.0f} / {:.0f} | 0 dropped |\n"
      "| recording: frames, gaps in seq | {}, {} | 0 gaps |\n"
      "| vemd RSS: before; peak of {:.0f}-{:.0f} s; peak of {:.0f}-{:.0f} s; end | {} / {} / {} / "
      "{} kB | second peak within {:.0f} % or {} MB of the first |\n"
      "| vemd descriptors: before, peak under attack, after | {} / {} / {} | after <= before |\n"
      "| well-behaved client's frame age: median, p99, max | {:.1f} / {:.1f} / {:.1f} ms | p99 < "
      "{:.0f} ms |\n"
      "| slow reader (1/4 of the byte rate): frames, age p99, max | {}, {:.0f} / {:.0f} ms | |\n"
      "| vemd's log | {} bytes ({:.0f} B/s) | < {:.0f} B/s |\n"
      "| churned connections | {} | |\n"
      "| never-reading clients (each closed by vemd) | {} | |\n"
      "| malformed messages sent | {} | |\n"
      "| half-sent requests opened by the flood | {} | |\n"
      "| cube maps received by the 6 cube-map clients | {} | |\n"
      "| vemd RSS every quarter of the attack | {} | |\n",
      seconds,
      churnPerSecond() > 0 ? fmt::format("{:.0f} connections/s", 3 * churnPerSecond())
                           : std::string("as fast as they go"),
      kCameraRateHz, processedRate, kRateTolerance * 100, processed, dropped, seqs.size(), gaps,
      warmUpS, middleS, middleS, seconds, before.rssKb, firstHalfPeakKb, secondHalfPeakKb, endRssKb,
      kMaxRssGrowthShare * 100, kMaxRssGrowthKb / 1024, before.fds, peakFds, after.fds,
      wellP50 * 1e3, wellP99 * 1e3, wellMax * 1e3, kMaxWellBehavedAgeS * 1e3,
      counts.slowFrames.load(), slowP99 * 1e3, slowMax * 1e3, log.size(), logBytesPerS,
      kLogBytesPerS, counts.churned.load(), counts.stalledConnections.load(),
      counts.malformedSent.load(), counts.floodOpened.load(), cubemapsReceived, rssQuarters);
  const std::string report = intro + table + comparison;
  std::cout << report;
  if (const char* file = std::getenv("VEM_SOAK_REPORT")) std::ofstream(file) << report;

  EXPECT_NEAR(processedRate, kCameraRateHz, kCameraRateHz * kRateTolerance) << log;
  EXPECT_EQ(dropped, 0.0);
  EXPECT_GT(seqs.size(), std::size_t(seconds * kCameraRateHz * (1.0 - kRateTolerance)));
  EXPECT_EQ(gaps, 0u);
  EXPECT_LE(secondHalfPeakKb - firstHalfPeakKb,
            std::max<long>(long(kMaxRssGrowthShare * double(firstHalfPeakKb)), kMaxRssGrowthKb))
      << "vemd's memory grew under the attack";
  EXPECT_LE(after.fds, before.fds) << "descriptors left open after the attack";
  EXPECT_LT(wellP99, kMaxWellBehavedAgeS);
  EXPECT_LT(logBytesPerS, kLogBytesPerS);
  EXPECT_GT(counts.churned.load(), 100u);
  EXPECT_GT(counts.floodOpened.load(), 100u);
  EXPECT_GT(cubemapsReceived, 0u);
  EXPECT_GT(counts.slowFrames.load(), 10u);
}

}  // namespace
}  // namespace vem::soak
