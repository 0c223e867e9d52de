// vem_mqtt_bench: what publishing through an MQTT broker costs and delivers (issue 22), against
// the real vemd and a real Mosquitto on 127.0.0.1 (mqtt_bench.h): the fan-out to 1..500
// subscribers through the broker beside the same number of WebSocket clients of vemd itself, two
// cameras on one broker, the bytes of each payload, and the loopback floor under them. Writes a
// markdown section for docs/BENCHMARKS.md (the `bench` target includes it) and prints it.
//
//   vem_mqtt_bench [--vemd PATH] [--seconds S] [--subscribers 1,10,100,500]
//                  [--two-cameras N] [--broker-nagle] [--report FILE.md]
#include <sys/resource.h>

#include <algorithm>
#include <iostream>
#include <numeric>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "bench/machine_info.h"
#include "bench/markdown_output.h"
#include "bench/mqtt/loopback_floor.h"
#include "bench/mqtt/mqtt_bench.h"

namespace {

using namespace vem::bench;

constexpr double kFrameRateHz = 30.0;
constexpr std::size_t kFloorMessages = 2000;
constexpr std::size_t kSmallMessageBytes = 64;

struct Arguments {
  MqttBenchSetup setup{VEMD_PATH};
  double seconds = 10.0;
  std::vector<std::size_t> subscribers{1, 10, 100, 500};
  std::size_t twoCameraSubscribers = 100;
  std::string reportPath;
};

std::string fail(const std::string& what, const std::string& why) {
  std::cerr << "vem_mqtt_bench: " << what << ": " << why << "\n";
  return {};
}

// Room for the subscribers' sockets here and in the children (the broker inherits it).
void raiseDescriptorLimit() {
  rlimit limit{};
  if (::getrlimit(RLIMIT_NOFILE, &limit) == 0 && limit.rlim_cur < limit.rlim_max) {
    limit.rlim_cur = limit.rlim_max;
    (void)::setrlimit(RLIMIT_NOFILE, &limit);
  }
}

std::string command(const Arguments& a) {
  std::string list;
  for (const std::size_t n : a.subscribers) list += (list.empty() ? "" : ",") + std::to_string(n);
  return fmt::format("vem_mqtt_bench --seconds {} --subscribers {} --two-cameras {}{}", a.seconds,
                     list, a.twoCameraSubscribers, a.setup.brokerNoDelay ? "" : " --broker-nagle");
}

const char* pathName(FanOutPath path) {
  return path == FanOutPath::Mqtt ? "MQTT (broker)" : "WebSocket (vemd)";
}

std::string floorSection(const LoopbackLatency& small, const LoopbackLatency& frame) {
  std::string md = fmt::format(
      "**The floor.** One message at a time over a TCP connection on 127.0.0.1 (TCP_NODELAY) "
      "between two threads, {} messages each, one-way (the sender's write to the receiver holding "
      "the whole message), CLOCK_REALTIME. Through a broker a frame crosses loopback twice.\n\n"
      "| message | bytes | median µs | p99 µs |\n|---|---:|---:|---:|\n",
      small.messages);
  for (const auto& [what, l] :
       {std::pair{"small", small}, std::pair{"one 1024-light frame", frame}}) {
    md += fmt::format("| {} | {} | {:.1f} | {:.1f} |\n", what, l.bytes, l.medianUs, l.p99Us);
  }
  return md + "\n";
}

std::string sizesSection(const std::vector<PayloadSize>& sizes) {
  std::string md =
      "**Bytes per payload** as the broker delivers them (one `ServerMessage`, the same bytes as "
      "on WebSocket; median; the synthetic sky; clustering on, as by default; cube maps' texels "
      "as half floats, zstd level 3, with `[mqtt] cubemap_rate_hz = 5`). Messages/s is what "
      "arrived "
      "(timed from a topic's second message on), and kB/s per subscriber the bytes at that rate "
      "(lights at the camera's 30 frames/s; status about 1/s; hello once, retained).\n\n"
      "| payload | topic | bytes | messages/s | kB/s per subscriber | texel bytes before zstd |\n"
      "|---|---|---:|---:|---:|---:|\n";
  for (const PayloadSize& p : sizes) {
    md += fmt::format("| {} | `vemcast/cam1/{}` | {:.0f} | {} | {} | {} |\n", p.what, p.topic,
                      p.bytes, p.rateHz > 0 ? fmt::format("{:.1f}", p.rateHz) : "",
                      p.rateHz > 0 ? fmt::format("{:.1f}", p.bytes * p.rateHz / 1000.0) : "",
                      p.rawTexelBytes > 0 ? fmt::format("{:.0f}", p.rawTexelBytes) : "");
  }
  return md + "\n";
}

std::string fanOutSection(const std::vector<FanOutResult>& runs, double frameBytes,
                          double seconds) {
  std::string md = fmt::format(
      "**Fan-out: delivery.** One vemd at 30 frames/s, 1024 lights (clustered), with both its "
      "WebSocket server and `[mqtt]` on (so vemd does the same work on both paths), a fresh "
      "Mosquitto and vemd per row. N subscribers to the light frames, either through the broker "
      "(MQTT 5, QoS 0, each its own libmosquitto client and connection) or straight from vemd "
      "(WebSocket, each its own Boost.Beast client and connection); on both paths the bench "
      "drives all of them with 2 threads. Over a {:.0f} s window: light frames per subscriber per "
      "second (mean, and the slowest subscriber's), the latency from `publish_unix_ns` (vemd's "
      "processing done) to receipt, CLOCK_REALTIME, over every frame of every subscriber (each one "
      "decoded), the seq gaps all subscribers saw together, connections lost, and the payload "
      "bytes delivered per second against the floor (frame bytes x 30 Hz x N, {:.0f} bytes a "
      "frame).\n\n"
      "| path | subscribers | frames/s each (slowest) | latency median ms | p99 ms | max ms | seq "
      "gaps | lost | delivered MB/s | floor MB/s |\n"
      "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n",
      seconds, frameBytes);
  for (const FanOutResult& r : runs) {
    md += fmt::format(
        "| {} | {} | {:.1f} ({:.1f}) | {:.2f} | {:.2f} | {:.1f} | {} | {} | {:.1f} | {:.1f} |\n",
        pathName(r.path), r.subscribers, r.delivery.framesPerSubscriberS,
        r.delivery.minFramesPerSubscriberS, r.delivery.latencyMedianMs, r.delivery.latencyP99Ms,
        r.delivery.latencyMaxMs, r.delivery.seqGaps, r.lostConnections, r.delivery.bytesPerS / 1e6,
        frameBytes * kFrameRateHz * double(r.subscribers) / 1e6);
  }
  md +=
      "\n**Fan-out: CPU.** vemd's processed frames/s and drops over the window (its Status on the "
      "broker, the newest before and the first after the window: the capture queue's drops and "
      "the MQTT publisher's `publish_dropped`), and CPU time as percent of one core (200 % is the "
      "whole machine): vemd, the broker and the bench itself (the subscribers) from "
      "/proc/PID/stat (all threads, user + system), and the machine's busy time from /proc/stat "
      "(the kernel's loopback work included) and what of it the three did not use (others: "
      "kernel work not charged to them, and any other program running meanwhile). Times come in "
      "10 ms ticks: over 10 s a figure is good to about 0.1 %. The broker's CPU per light frame "
      "it delivered to a subscriber.\n\n"
      "| path | subscribers | processed frames/s | capture dropped | MQTT dropped | vemd % | vemd "
      "ms/frame | broker % | broker µs/delivery | bench % | machine % (others) |\n"
      "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const FanOutResult& r : runs) {
    md += fmt::format(
        "| {} | {} | {:.1f} | {} | {} | {:.1f} | {:.2f} | {:.1f} | {} | {:.1f} | {:.0f} ({:.0f}) "
        "|\n",
        pathName(r.path), r.subscribers, r.vemd.processedHz, r.vemd.captureDropped,
        r.vemd.publishDropped, r.vemd.cpu.percent, r.vemd.cpu.msPerFrame, r.broker.percent,
        r.brokerUsPerDelivered > 0 ? fmt::format("{:.1f}", r.brokerUsPerDelivered) : "",
        r.benchCpuPercent, r.machineBusyPercent,
        std::max(0.0,
                 r.machineBusyPercent - r.vemd.cpu.percent - r.broker.percent - r.benchCpuPercent));
  }
  // The claim: vemd's CPU does not grow with the subscribers on the MQTT path.
  std::vector<const FanOutResult*> mqtt;
  for (const FanOutResult& r : runs) {
    if (r.path == FanOutPath::Mqtt) mqtt.push_back(&r);
  }
  if (mqtt.size() >= 2) {
    md += fmt::format(
        "\nvemd's CPU per frame through the broker: {:.2f} ms with {} subscriber{}, {:.2f} ms with "
        "{} ({:+.0f} %).\n",
        mqtt.front()->vemd.cpu.msPerFrame, mqtt.front()->subscribers,
        mqtt.front()->subscribers == 1 ? "" : "s", mqtt.back()->vemd.cpu.msPerFrame,
        mqtt.back()->subscribers,
        100.0 * (mqtt.back()->vemd.cpu.msPerFrame / mqtt.front()->vemd.cpu.msPerFrame - 1.0));
  }
  md +=
      "\nBoth TCP hops of the MQTT path have Nagle's algorithm off: vemd's libmosquitto client "
      "sets `MOSQ_OPT_TCP_NODELAY` (util/mosquitto_client.cpp, as the clients do), and the "
      "broker runs with `set_tcp_nodelay true`, as config/mosquitto/vemcast.conf sets it "
      "(Mosquitto's default is false; `--broker-nagle` measures that). Before both, a frame "
      "written while the previous one waited for its ACK waited for the receiver's delayed ACK: "
      "on 2026-12-07 the p99 through the broker was 10 to 15 ms with 1 to 10 subscribers, "
      "against 3 to 6 ms on WebSocket; forcing TCP_NODELAY on one hop alone left it at 13 to 14 "
      "ms.\n";
  return md + "\n";
}

std::string twoCamerasSection(const TwoCamerasResult& r) {
  std::string md = fmt::format(
      "**Two cameras, one broker.** Two vemd (camera ids cam1 and cam2, each as above) publishing "
      "to one Mosquitto; {} MQTT subscribers, half following each camera's light frames, over "
      "{:.0f} s. Broker CPU {:.1f} % of a core ({:.1f} µs per delivery), the bench {:.1f} %, the "
      "machine {:.0f} % busy of 200 %; {} connections lost.\n\n"
      "| camera | subscribers | frames/s each (slowest) | latency median ms | p99 ms | seq gaps | "
      "processed frames/s | capture dropped | MQTT dropped | vemd % | vemd ms/frame |\n"
      "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n",
      r.subscribers, r.windowS, r.brokerCpuPercent, r.brokerUsPerDelivered, r.benchCpuPercent,
      r.machineBusyPercent, r.lostConnections);
  for (const CameraDelivery& c : r.cameras) {
    md += fmt::format(
        "| {} | {} | {:.1f} ({:.1f}) | {:.2f} | {:.2f} | {} | {:.1f} | {} | {} | {:.1f} | {:.2f} "
        "|\n",
        c.vemd.cameraId, c.delivery.subscribers, c.delivery.framesPerSubscriberS,
        c.delivery.minFramesPerSubscriberS, c.delivery.latencyMedianMs, c.delivery.latencyP99Ms,
        c.delivery.seqGaps, c.vemd.processedHz, c.vemd.captureDropped, c.vemd.publishDropped,
        c.vemd.cpu.percent, c.vemd.cpu.msPerFrame);
  }
  return md + "\n";
}

std::string report(const Arguments& a) {
  const auto sizes = payloadSizes(a.setup);
  if (!sizes) return fail("payload sizes", sizes.error());
  double frameBytes = 0.0;
  for (const PayloadSize& p : *sizes) {
    if (p.what.starts_with("light frame, 1024 ")) frameBytes = p.bytes;
  }
  const auto small = loopbackLatency(kSmallMessageBytes, kFloorMessages);
  if (!small) return fail("loopback", small.error());
  const auto frame = loopbackLatency(std::size_t(frameBytes), kFloorMessages);
  if (!frame) return fail("loopback", frame.error());

  std::vector<FanOutResult> runs;
  for (const FanOutPath path : {FanOutPath::Mqtt, FanOutPath::WebSocket}) {
    for (const std::size_t n : a.subscribers) {
      std::cerr << fmt::format("vem_mqtt_bench: {} subscribers over {}\n", n, pathName(path));
      auto run = fanOut(a.setup, path, n, a.seconds);
      if (!run) return fail(fmt::format("{} subscribers over {}", n, pathName(path)), run.error());
      runs.push_back(*run);
    }
  }
  std::string cameras;
  if (a.twoCameraSubscribers > 0) {
    std::cerr << "vem_mqtt_bench: two cameras\n";
    const auto two = twoCameras(a.setup, a.twoCameraSubscribers, a.seconds);
    if (!two) return fail("two cameras", two.error());
    cameras = twoCamerasSection(*two);
  }

  std::string md = "## MQTT fan-out (vem_mqtt_bench, issue 22)\n\n";
  md += fmt::format(
      "`{}` (tests/bench/mqtt/): the real vemd (`--source synthetic:sky` through the 320 x 256 "
      "camera of vem_stream_bench, `--rate 30`, default processing: 1024 x 256 map, 1024 lights, "
      "paper9 filter, clustering Q = 72) and a real Mosquitto (Debian's), both children of the "
      "bench, everything on 127.0.0.1. Release build; {}: vemd, the broker and all subscribers "
      "share them, so a figure at 500 subscribers is as much the subscribers' CPU as the "
      "broker's. The named baseline is vemd's own WebSocket stream (the section above); "
      "docs/scaling.md extrapolates from these figures.\n\n",
      command(a), machineDescription());
  md += floorSection(*small, *frame);
  md += sizesSection(*sizes);
  md += fanOutSection(runs, frameBytes, a.seconds);
  md += cameras;
  return md;
}

}  // namespace

int main(int argc, char** argv) {
  Arguments a;
  CLI::App app{"What publishing through an MQTT broker costs, against the real vemd on 127.0.0.1"};
  app.add_option("--vemd", a.setup.vemdPath, "The vemd binary")->check(CLI::ExistingFile);
  app.add_option("--seconds", a.seconds, "The measuring window of each run")
      ->check(CLI::Range(1.0, 120.0));
  app.add_option("--subscribers", a.subscribers, "Subscriber counts of the fan-out runs")
      ->delimiter(',')
      ->check(CLI::Range(std::size_t(1), std::size_t(2000)));
  app.add_option("--two-cameras", a.twoCameraSubscribers,
                 "Subscribers of the two-camera run (0: skip it)")
      ->check(CLI::Range(std::size_t(0), std::size_t(2000)));
  bool brokerNagle = false;
  app.add_flag("--broker-nagle", brokerNagle,
               "Run the broker with Mosquitto's default set_tcp_nodelay false (Nagle's algorithm "
               "on toward subscribers) instead of config/mosquitto/vemcast.conf's true");
  app.add_option("--report", a.reportPath, "Also write the markdown section to this file");
  CLI11_PARSE(app, argc, argv);
  a.setup.brokerNoDelay = !brokerNagle;
  raiseDescriptorLimit();
  const std::string md = report(a);
  if (md.empty()) return 1;
  return emitMarkdown("vem_mqtt_bench", md, a.reportPath) ? 0 : 1;
}
