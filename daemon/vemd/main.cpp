// vemd: the capture daemon. Parses the configuration, builds source, pipeline and sinks, runs the
// loop until the source ends, --frames is reached, or SIGINT/SIGTERM; streams to render clients
// ([stream], vemd/stream_wiring.h); docs/vemd.md.
// SIGINT/SIGTERM are caught from before start-up: start-up checks the flag between its steps and
// the rows of the polar remap (daemon_setup.h), the loop at least every 50 ms.
// Exit status (util/cli_conventions.h): 0 after a clean stop (also one asked for during start-up),
// 1 when start-up failed or a sink failed, 2 for bad usage (a flag, or the configuration file).
#include <csignal>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include <spdlog/spdlog.h>

#include "stream/stream_setup.h"
#include "util/log_setup.h"
#include "util/printable.h"
#include "vemd/daemon_loop.h"
#include "vemd/daemon_setup.h"
#include "vemd/device_list.h"
#include "vemd/service_observer.h"
#include "vemd/stream_wiring.h"
#include "vemd/vemd_config.h"

namespace {

std::atomic<bool> gStopRequested{false};
static_assert(std::atomic<bool>::is_always_lock_free, "set from a signal handler");

extern "C" void requestStop(int) { gStopRequested.store(true); }

// SIGINT and SIGTERM ask the loop to stop; a second one (SA_RESETHAND) ends the process at once.
void installStopHandlers() {
  struct sigaction action {};
  action.sa_handler = requestStop;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESETHAND;
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

}  // namespace

int main(int argc, char** argv) {
  using namespace vem::vemd;
  auto config = parseCommandLine(std::vector<std::string>(argv, argv + argc));
  if (!config) {
    std::cout << config.error().out;
    std::cerr << config.error().err;
    return config.error().exitCode;
  }
  // The configuration checked both names.
  vem::cli::setUpLogging(
      "vemd", {*vem::cli::parseLogLevel(config->log.level),
               *vem::cli::parseLogFormat(config->log.format), vem::cli::underJournald()});
  if (config->listDevices) {
    std::cout << deviceListText();
    return 0;
  }
  installStopHandlers();
  ServiceObserver observer(ServiceNotifier::fromEnvironment());
  if (config->stream.enabled && !config->stream.listen.empty()) {
    // A token file that cannot be used stops vemd now, not after the long start-up steps.
    if (auto token = vem::stream::streamToken(config->stream); !token) {
      spdlog::error("{}", token.error());
      return 1;
    }
  }
  Streaming streaming;  // outlives the daemon's sinks, which borrow the server
  auto daemon = buildDaemon(
      *config,
      [&](const vem::SourceDescription& source,
          std::vector<std::unique_ptr<vem::Sink>>& sinks) -> std::expected<void, std::string> {
        auto started = startStreaming(*config, source, sinks);
        if (!started) return std::unexpected(started.error());
        streaming = std::move(*started);
        return {};
      },
      [&] {
        observer.startupProgress();
        return gStopRequested.load();
      });
  if (!daemon) {
    if (daemon.error().cause == StartupFailure::Cause::Stopped) {
      observer.stopping();
      spdlog::info("stopping during start-up: {}", daemon.error().message);
      return 0;
    }
    spdlog::error("{}", daemon.error().message);
    return 1;
  }
  spdlog::info("running: {} into {} x {} polar maps, {} lights, filter {}, {} sink(s)",
               vem::util::printable(daemon->source->describe().spec), config->processing.mapWidth,
               config->processing.mapHeight, config->processing.lightCount,
               vem::presetName(config->processing.filter), daemon->sinks.size());
  const LoopResult result =
      runDaemonLoop(*daemon->source, *daemon->pipeline, daemon->sinks, daemon->loop, gStopRequested,
                    &observer, streaming.control.get());
  return result.sinkFailures > 0 ? 1 : 0;
}
