// vem_stream_bench: what streaming costs, against the real vemd (stream_bench.h): the network
// path's latency, the bytes per message, and vemd's processed rate with 1, 10 and 50 clients.
// Writes a markdown section for docs/BENCHMARKS.md (the `bench` target includes it) and prints it.
//
//   vem_stream_bench [--vemd PATH] [--frames N] [--report FILE.md] [--latency-only]
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

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
      "\n**Processed rate with clients**, at `--rate max` and at a camera's 60 frames/s: vemd's own processed frames/s (its "
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
    md +=
        fmt::format("| {} | {} | {:.1f} | {:.1f} | {} | {} | {:.2f} |\n", rate.rate, rate.clients,
                    rate.processedHz,
                    rate.receivedHz, rate.skipped, rate.dropped, rate.cpuMsPerFrame);
  }
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
  app.add_option("--report", reportPath, "Also write the markdown section to this file");
  CLI11_PARSE(app, argc, argv);
  if (frames < 1000) std::cerr << "vem_stream_bench: fewer than 1000 frames make a poor p99\n";
  const std::string md = report(vemdPath, frames, latencyOnly);
  if (md.empty()) return 1;
  return vem::bench::emitMarkdown("vem_stream_bench", md, reportPath) ? 0 : 1;
}
