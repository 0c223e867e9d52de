// vem_stream_bench: what streaming costs, against the real vemd (stream_bench.h): the network
// path's latency, the bytes per message, and vemd's processed rate with 1, 10 and 50 clients.
// Writes a markdown section for docs/BENCHMARKS.md (the `bench` target includes it) and prints it.
//
//   vem_stream_bench [--vemd PATH] [--frames N] [--report FILE.md] [--latency-only]
#include <iostream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "bench/markdown_output.h"
#include "bench/stream/stream_bench.h"

namespace {

constexpr double kLatencyRateHz = 100.0;
constexpr double kRateWindowS = 5.0;

std::string fail(const std::string& what, const std::string& why) {
  std::cerr << "vem_stream_bench: " << what << ": " << why << "\n";
  return {};
}

std::string latencyTable(const vem::bench::LatencyResult& latency) {
  std::string md =
      "| frames | median ms | p99 ms | max ms | seqs skipped |\n|---:|---:|---:|---:|---:|\n";
  md += fmt::format("| {} | {:.3f} | {:.3f} | {:.3f} | {} |\n\n", latency.frames, latency.medianMs,
                    latency.p99Ms, latency.maxMs, latency.skipped);
  return md;
}

constexpr double kCubemapLoadRateHz = 30.0;
constexpr double kCubemapLoadWindowS = 20.0;

std::string cubemapLoadTable(const std::vector<vem::bench::CubemapLoadResult>& loads) {
  std::string md = fmt::format(
      "**Cube maps asked for, while recording** (issue 16, item 1): vemd at a camera's {:.0f} "
      "frames/s with `--record`, 10 raw clients subscribed to light frames and cube maps (every "
      "other one with the polar preview), reading and discarding every message. Processed "
      "frames/s and drops over {:.0f} s from vemd's Status (and the drops of the whole run, "
      "connecting included, from its final statistics); the recording's frames and seq gaps over "
      "the whole run; the cube maps all 10 clients received per second. Before issue 16 "
      "(cube maps built on the processing thread, once per size asked), 512 px / 8 levels / 60 Hz "
      "cut vemd from 30 to 1.2-2 processed frames/s and the recording made meanwhile held 712 "
      "frames over seq 0..1308 (the issue's measurement); the floor is the camera's rate with 0 "
      "drops and 0 gaps.\n\n",
      kCubemapLoadRateHz, kCubemapLoadWindowS);
  md +=
      "| clients ask for | token | refused | processed frames/s | dropped (whole run) | recorded "
      "frames | "
      "recording gaps | cube maps/s received | vemd CPU ms/frame |\n"
      "|---|---|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const vem::bench::CubemapLoadResult& r : loads) {
    md += fmt::format(
        "| {} px, {} levels, {:.0f} Hz | {} | {} | {:.1f} | {} ({}) | {} | {} | "
        "{:.1f} | {:.2f} |\n",
        r.load.facePx, r.load.levels, r.load.rateHz, r.load.token ? "yes" : "no", r.refused,
        r.processedHz, r.dropped, r.droppedInRun, r.recorded, r.recordingGaps, r.cubemapsPerS,
        r.cpuMsPerFrame);
  }
  return md;
}

std::string cubemapLoadReport(const std::string& vemdPath) {
  using namespace vem::bench;
  std::vector<CubemapLoadResult> loads;
  for (const CubemapLoad& load :
       {CubemapLoad{10, 512, 8, 60.0, true}, CubemapLoad{10, 256, 8, 10.0, false},
        CubemapLoad{10, 512, 8, 60.0, false}}) {
    const auto measured =
        rateWithCubemapLoad(vemdPath, kCubemapLoadRateHz, load, kCubemapLoadWindowS);
    if (!measured) return fail("cube-map load", measured.error());
    loads.push_back(*measured);
  }
  return cubemapLoadTable(loads);
}

std::string report(const std::string& vemdPath, std::size_t frames, bool latencyOnly) {
  using namespace vem::bench;
  const auto latency = networkLatency(vemdPath, frames, kLatencyRateHz);
  if (!latency) return fail("latency", latency.error());
  if (latencyOnly) return latencyTable(*latency);
  const auto sizes = messageSizes(vemdPath);
  if (!sizes) return fail("message sizes", sizes.error());
  std::vector<RateResult> rates;
  for (const char* vemdRate : {"max", "60"}) {
    for (const std::size_t clients : {1U, 10U, 50U}) {
      const auto rate = rateWithClients(vemdPath, vemdRate, clients, kRateWindowS);
      if (!rate) return fail(fmt::format("{} clients", clients), rate.error());
      rates.push_back(*rate);
    }
  }
  const std::string loads = cubemapLoadReport(vemdPath);
  if (loads.empty()) return {};

  std::string md = "## Streaming (vem_stream_bench)\n\n";
  md += fmt::format(
      "`vem_stream_bench --frames {}` (tests/bench/stream/): the real vemd (`--source "
      "synthetic:sky` through a 320 x 256 RGB camera so that rendering the scene does not bound "
      "the rate; default processing: 1024 x 256 map, 1024 lights, paper9 filter, clustering "
      "Q = 72) on 127.0.0.1, clients in the bench's process. Release build, 2 cores shared by vemd "
      "and the clients (no GPU involved).\n\n",
      frames);
  md += fmt::format(
      "**Network path latency**: `publish_unix_ns` (processing done) to a StreamClient holding the "
      "decoded frame (`receivedUnixNs`), both CLOCK_REALTIME, over {} light frames at `--rate {}` "
      "(target: median below 1 ms).\n\n",
      latency->frames, latency->rateHz);
  md += latencyTable(*latency);
  md +=
      "**Bytes per message** (one serialized ServerMessage, median; cube maps of the synthetic "
      "sky, texels zstd level 3):\n\n| message | bytes | texel bytes before zstd "
      "|\n|---|---:|---:|\n";
  for (const MessageSize& size : *sizes) {
    md += fmt::format("| {} | {:.0f} | {} |\n", size.what, size.bytes,
                      size.rawTexelBytes > 0 ? fmt::format("{:.0f}", size.rawTexelBytes) : "");
  }
  md += fmt::format(
      "\n**Processed rate with clients**, at `--rate max` and at a camera's 60 frames/s: vemd's "
      "own processed frames/s (its "
      "Status, median over {:.0f} s), the light frames one StreamClient received per second, its "
      "seq gaps, frames vemd's capture queue dropped, and vemd's CPU time (all threads) per "
      "processed "
      "frame; the other clients read and discard every message. vemd and the clients share the "
      "two cores, so a lower rate with more clients is the clients' CPU, unless vemd's CPU per "
      "frame grows.\n\n",
      kRateWindowS);
  md +=
      "| vemd --rate | clients | processed frames/s | received frames/s | skipped by that client "
      "| dropped by vemd | vemd CPU ms/frame |\n|---|---:|---:|---:|---:|---:|---:|\n";
  for (const RateResult& rate : rates) {
    md += fmt::format("| {} | {} | {:.1f} | {:.1f} | {} | {} | {:.2f} |\n", rate.rate, rate.clients,
                      rate.processedHz, rate.receivedHz, rate.skipped, rate.dropped,
                      rate.cpuMsPerFrame);
  }
  md += "\n" + loads;
  return md;
}

}  // namespace

int main(int argc, char** argv) {
  std::string vemdPath = VEMD_PATH;
  std::string reportPath;
  std::size_t frames = 1200;
  bool latencyOnly = false;
  CLI::App app{"What streaming costs, against the real vemd on 127.0.0.1"};
  app.add_option("--vemd", vemdPath, "The vemd binary")->check(CLI::ExistingFile);
  app.add_option("--frames", frames, "Light frames in the latency measurement")
      ->check(CLI::Range(std::size_t(10), std::size_t(1000000)));
  app.add_flag("--latency-only", latencyOnly, "Measure the latency alone");
  bool cubemapsOnly = false;
  app.add_flag("--cubemap-load-only", cubemapsOnly,
               "Measure vemd under cube-map load alone (issue 16)");
  app.add_option("--report", reportPath, "Also write the markdown section to this file");
  CLI11_PARSE(app, argc, argv);
  if (frames < 1000) std::cerr << "vem_stream_bench: fewer than 1000 frames make a poor p99\n";
  const std::string md =
      cubemapsOnly ? cubemapLoadReport(vemdPath) : report(vemdPath, frames, latencyOnly);
  if (md.empty()) return 1;
  return vem::bench::emitMarkdown("vem_stream_bench", md, reportPath) ? 0 : 1;
}
