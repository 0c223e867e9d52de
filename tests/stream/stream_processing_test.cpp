// The processing-thread side of streaming: the stream sink (light frames, cube maps built only on
// demand), control between frames (StreamControl over a real Pipeline), Pipeline::reconfigure,
// and the recording switch. Real pipeline on the small test camera, real server on port 0.
#include <filesystem>
#include <memory>
#include <optional>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <spdlog/spdlog.h>

#include "core/light_clustering.h"
#include "recording/recording_reader.h"
#include "stream/frame_encoding.h"
#include "stream/recording_switch.h"
#include "stream/stream_control.h"
#include "stream/stream_server.h"
#include "stream/stream_sink.h"
#include "vemd/daemon_setup.h"
#include "vemd/pipeline_setup.h"
#include "vemd/sinks/jsonl_light_sink.h"
#include "vemd/stream_wiring.h"
#include "vemd/vemd_fixtures.h"
#include "ws_test_client.h"

namespace vem::stream {
namespace {

using testing::WsTestClient;
namespace fs = std::filesystem;

using testing::eventually;

constexpr std::int64_t kWaitNs = 60'000'000'000;  // a hang guard, not a speed limit

class StreamProcessing : public ::testing::Test {
 protected:
  void SetUp() override {
    spdlog::set_level(spdlog::level::warn);
    StreamServerOptions options;
    options.port = 0;
    options.token = "secret";
    auto started = StreamServer::start(options);
    ASSERT_TRUE(started.has_value()) << started.error();
    server_ = std::move(*started);
    auto pipeline = vemd::pipelineFromCameraFile(vem::testing::smallCameraToml(), "test camera",
                                                 vem::testing::smallProcessing());
    ASSERT_TRUE(pipeline.has_value()) << pipeline.error();
    pipeline_.emplace(std::move(*pipeline));
    sink_ = std::make_unique<StreamSink>(*server_, StreamSinkOptions{3, 32});
  }

  // Processes frame `seq` and feeds it to the sink.
  void feed(std::uint64_t seq) {
    captured_.frame = vem::testing::cachedSkyFrame(int(seq));
    captured_.seq = seq;
    captured_.captureTsNs = std::int64_t(seq) * vem::testing::kFramePeriodNs;
    captured_.arrivalNs = vem::monotonicNowNs();
    const vem::ProcessedFrame& processed = pipeline_->process(captured_);
    ASSERT_TRUE(sink_->consume(processed).has_value());
  }

  void subscribeCubemaps(WsTestClient& client, double rateHz) {
    ClientMessage subscribe;
    subscribe.mutable_subscribe()->set_lights(true);
    subscribe.mutable_subscribe()->set_cubemap_rate_hz(rateHz);
    subscribe.mutable_subscribe()->set_cubemap_face_px(8);
    ASSERT_TRUE(client.send(subscribe));
    auto reply = client.nextReply();
    ASSERT_TRUE(reply && reply->ok());
  }

  std::unique_ptr<StreamServer> server_;
  std::optional<vemd::Pipeline> pipeline_;
  std::unique_ptr<StreamSink> sink_;
  vem::CapturedFrame captured_;
};

TEST_F(StreamProcessing, LightFramesCarryThePublishedLights) {
  WsTestClient client;
  ASSERT_EQ(client.connect(server_->boundPort()), 0);
  feed(3);
  for (;;) {
    auto message = client.read();
    ASSERT_TRUE(message);
    if (!message->has_lights()) continue;
    EXPECT_EQ(message->lights().seq(), 3u);
    EXPECT_EQ(message->lights().ids_size(), int(sink_->lightsInLastFrame()));
    EXPECT_GT(message->lights().ids_size(), 0);
    break;
  }
}

TEST_F(StreamProcessing, CubemapsAreBuiltOnlyWhileSomeoneSubscribes) {
  WsTestClient lightsOnly;
  ASSERT_EQ(lightsOnly.connect(server_->boundPort()), 0);
  for (std::uint64_t seq = 0; seq < 5; ++seq) feed(seq);
  ASSERT_TRUE(sink_->waitForCubemaps(kWaitNs));
  EXPECT_EQ(sink_->cubemapCounters().framesOffered, 0u);
  EXPECT_EQ(sink_->cubemapCounters().cubesBuilt, 0u);

  WsTestClient subscriber;
  ASSERT_EQ(subscriber.connect(server_->boundPort()), 0);
  subscribeCubemaps(subscriber, 60.0);
  feed(5);
  ASSERT_TRUE(sink_->waitForCubemaps(kWaitNs));
  EXPECT_EQ(sink_->cubemapCounters().cubesBuilt, 1u);
  bool gotEnvironment = false;
  while (!gotEnvironment) {
    auto message = subscriber.read();
    ASSERT_TRUE(message);
    if (message->has_environment()) {
      gotEnvironment = true;
      EXPECT_EQ(message->environment().face_px(), 8u);
      EXPECT_EQ(message->environment().seq(), 5u);
    }
  }

  subscriber.close();
  ASSERT_TRUE(eventually([&] { return !server_->cubemapDemand().any(); }));
  const std::uint64_t offered = sink_->cubemapCounters().framesOffered;
  for (std::uint64_t seq = 6; seq < 12; ++seq) feed(seq);
  EXPECT_EQ(sink_->cubemapCounters().framesOffered, offered);
}

TEST_F(StreamProcessing, CubemapsFollowTheRateAskedNotTheFrameRate) {
  WsTestClient subscriber;
  ASSERT_EQ(subscriber.connect(server_->boundPort()), 0);
  subscribeCubemaps(subscriber, 0.001);  // one every 1000 s: the first is due at once
  for (std::uint64_t seq = 0; seq < 10; ++seq) feed(seq);
  ASSERT_TRUE(sink_->waitForCubemaps(kWaitNs));
  EXPECT_EQ(sink_->cubemapCounters().framesOffered, 1u);
  EXPECT_EQ(sink_->cubemapCounters().cubesBuilt, 1u);
}

// Issue 16, item 1: each client's size was built once per client, on the processing thread.
TEST_F(StreamProcessing, EachFaceSizeIsBuiltOncePerFrameWhoeverAsksForIt) {
  std::vector<WsTestClient> clients(4);
  for (auto& c : clients) ASSERT_EQ(c.connect(server_->boundPort(), "/", "secret"), 0);
  const auto subscribe = [](WsTestClient& client, int levels, bool preview) {
    ClientMessage message;
    message.mutable_subscribe()->set_lights(true);
    message.mutable_subscribe()->set_cubemap_rate_hz(60.0);
    message.mutable_subscribe()->set_cubemap_face_px(32);
    message.mutable_subscribe()->set_cubemap_levels(std::uint32_t(levels));
    message.mutable_subscribe()->set_preview(preview);
    ASSERT_TRUE(client.send(message));
    auto reply = client.nextReply();
    ASSERT_TRUE(reply && reply->ok());
  };
  subscribe(clients[0], 1, false);
  subscribe(clients[1], 1, false);  // the same variant as the first
  subscribe(clients[2], 4, false);
  subscribe(clients[3], 4, true);
  ASSERT_EQ(server_->cubemapDemand().variants.size(), 3u);
  feed(1);
  ASSERT_TRUE(sink_->waitForCubemaps(kWaitNs));
  const CubemapWorkerCounters counters = sink_->cubemapCounters();
  EXPECT_EQ(counters.cubesBuilt, 1u);          // one 32 px cube with 4 levels
  EXPECT_EQ(counters.messagesPublished, 3u);   // one per variant
  for (std::size_t i = 0; i < clients.size(); ++i) {
    for (;;) {
      auto message = clients[i].read();
      ASSERT_TRUE(message);
      if (!message->has_environment()) continue;
      EXPECT_EQ(message->environment().levels(), i < 2 ? 1u : 4u) << "client " << i;
      EXPECT_EQ(message->environment().has_preview(), i == 3) << "client " << i;
      break;
    }
  }
}

// Issue 16, item 1: the builder falls behind a client that asks for big cube maps often; it
// drops the maps it could not take and builds the newest, and the processing thread never waits.
TEST_F(StreamProcessing, TheCubemapWorkerBuildsTheNewestMapWhenItFallsBehind) {
  WsTestClient subscriber;
  ASSERT_EQ(subscriber.connect(server_->boundPort(), "/", "secret"), 0);
  ClientMessage message;
  message.mutable_subscribe()->set_lights(false);
  message.mutable_subscribe()->set_cubemap_rate_hz(60.0);
  message.mutable_subscribe()->set_cubemap_face_px(512);
  message.mutable_subscribe()->set_cubemap_levels(8);
  ASSERT_TRUE(subscriber.send(message));
  auto reply = subscriber.nextReply();
  ASSERT_TRUE(reply && reply->ok());
  // Frames 100 ms of capture time apart, fed as fast as the pipeline goes: every one is due.
  constexpr std::uint64_t kFrames = 12;
  for (std::uint64_t seq = 0; seq < kFrames; ++seq) {
    feed(seq);
    std::this_thread::sleep_for(std::chrono::milliseconds(17));  // a 60 Hz camera
  }
  ASSERT_TRUE(sink_->waitForCubemaps(kWaitNs));
  const CubemapWorkerCounters counters = sink_->cubemapCounters();
  EXPECT_EQ(counters.framesBuilt + counters.framesDropped, counters.framesOffered);
  EXPECT_EQ(counters.cubesBuilt, counters.framesBuilt);
  std::uint64_t lastSeq = 0;
  while (lastSeq != kFrames - 1) {
    auto received = subscriber.read();
    ASSERT_TRUE(received);
    if (received->has_environment()) lastSeq = received->environment().seq();
  }
}

vem::LoopCounters someCounters() {
  vem::LoopCounters counters;
  counters.processed = 10;
  counters.lastProcessedNs = vem::monotonicNowNs();
  return counters;
}

// Sends `control` with the token and runs the processing thread's hook until the reply comes.
ControlReply controlRoundTrip(StreamServer& server, StreamControl& control,
                              vemd::Pipeline& pipeline, WsTestClient& client,
                              const Control& command) {
  ClientMessage message;
  message.set_request_id(77);
  *message.mutable_control() = command;
  const std::uint64_t before = server.counters().controlsReceived;
  EXPECT_TRUE(client.send(message));
  // The server queues the command; the hook drains it between frames.
  EXPECT_TRUE(eventually([&] { return server.counters().controlsReceived > before; }));
  control.betweenFrames(pipeline, someCounters());
  while (auto replied = client.read()) {  // statuses, then the reply
    if (replied->has_reply()) return replied->reply();
  }
  ADD_FAILURE() << "no reply";
  return {};
}

TEST_F(StreamProcessing, ControlChangesThePipelineBetweenFramesAndAnswers) {
  StreamControl control(*server_, *sink_, nullptr, {"test", "id"}, 1'000'000'000'000);
  WsTestClient client;
  ASSERT_EQ(client.connect(server_->boundPort(), "/", "secret"), 0);
  Control lights;
  lights.set_set_light_count(32);
  ControlReply reply = controlRoundTrip(*server_, control, *pipeline_, client, lights);
  EXPECT_TRUE(reply.ok()) << reply.message();
  EXPECT_EQ(reply.request_id(), 77u);
  EXPECT_EQ(pipeline_->options().lightCount, 32u);

  Control filter;
  filter.set_set_filter("minphase9");
  reply = controlRoundTrip(*server_, control, *pipeline_, client, filter);
  EXPECT_TRUE(reply.ok()) << reply.message();
  EXPECT_EQ(pipeline_->options().filter, FilterPreset::MinPhase9);

  Control unknown;
  unknown.set_set_filter("paper10");
  reply = controlRoundTrip(*server_, control, *pipeline_, client, unknown);
  EXPECT_FALSE(reply.ok());
  EXPECT_NE(reply.message().find("paper10"), std::string::npos);

  Control clusterOff;
  clusterOff.set_set_cluster_budget(0);
  reply = controlRoundTrip(*server_, control, *pipeline_, client, clusterOff);
  EXPECT_TRUE(reply.ok());
  EXPECT_FALSE(pipeline_->options().clustering);

  Control record;
  record.mutable_start_recording();
  reply = controlRoundTrip(*server_, control, *pipeline_, client, record);
  EXPECT_FALSE(reply.ok());  // no recording switch here
}

// The clustering radius used to be fixed when vemd started: after a client changed the cluster
// budget, the JSON-lines file and the stream kept sending the old radius with the new clusters.
TEST_F(StreamProcessing, ClusterBudgetSetByControlChangesTheRadiusInTheJsonLinesAndTheStream) {
  StreamControl control(*server_, *sink_, nullptr, {"test", "id"}, 1'000'000'000'000);
  WsTestClient client;
  ASSERT_EQ(client.connect(server_->boundPort(), "/", "secret"), 0);
  for (const std::uint32_t budget : {4U, 48U}) {
    Control cluster;
    cluster.set_set_cluster_budget(budget);
    ASSERT_TRUE(controlRoundTrip(*server_, control, *pipeline_, client, cluster).ok());
    captured_.frame = vem::testing::cachedSkyFrame(int(budget));
    captured_.seq = budget;
    const vem::ProcessedFrame& processed = pipeline_->process(captured_);
    ASSERT_TRUE(processed.clustering.has_value());
    const double expected = clusterRadiusRad(
        {int(budget), pipeline_->options().clusterCorrectionFactor, MapLayout::Hemisphere});
    EXPECT_DOUBLE_EQ(vemd::lightsLineJson(processed, 0).at("radius_rad").get<double>(), expected)
        << "budget " << budget;
    const LightFrame sent = lightFrameMessage(processed, {}).lights();
    ASSERT_TRUE(sent.has_clusters());
    EXPECT_DOUBLE_EQ(sent.clusters().radius_rad(), expected) << "budget " << budget;
  }
}

TEST_F(StreamProcessing, StatusIsPublishedFromTheHook) {
  StreamControl control(*server_, *sink_, nullptr, {"synthetic:sky", "cam #1"});
  WsTestClient client;
  ASSERT_EQ(client.connect(server_->boundPort()), 0);
  control.betweenFrames(*pipeline_, someCounters());
  EXPECT_EQ(control.statusesPublished(), 1u);
  for (;;) {
    auto message = client.read();
    ASSERT_TRUE(message);
    if (!message->has_status()) continue;
    EXPECT_EQ(message->status().source(), "synthetic:sky");
    EXPECT_EQ(message->status().calibration_id(), "cam #1");
    EXPECT_EQ(message->status().frames_processed(), 10u);
    EXPECT_EQ(message->status().light_count(), std::uint32_t(pipeline_->options().lightCount));
    EXPECT_EQ(message->status().filter(), "paper9");
    break;
  }
}

// The state each Status carries, for counters the loop could pass.
SourceState publishedState(StreamServer& server, StreamSink& sink, vemd::Pipeline& pipeline,
                           const vem::LoopCounters& counters) {
  StreamControl control(server, sink, nullptr, {"aravis:cam", "cam #1"});
  WsTestClient client;
  if (client.connect(server.boundPort()) != 0) return SOURCE_STATE_UNSPECIFIED;
  control.betweenFrames(pipeline, counters);
  while (auto message = client.read()) {
    if (message->has_status()) return message->status().state();
  }
  return SOURCE_STATE_UNSPECIFIED;
}

TEST_F(StreamProcessing, StatusTellsClientsTheCameraIsGoneOrTheReplayEnded) {
  vem::LoopCounters counters = someCounters();
  EXPECT_EQ(publishedState(*server_, *sink_, *pipeline_, counters), SOURCE_STATE_OK);
  counters.sourceFailure = vem::SourceErrorCause::NoDevice;
  EXPECT_EQ(publishedState(*server_, *sink_, *pipeline_, counters), SOURCE_STATE_NO_DEVICE);
  counters.sourceFailure = vem::SourceErrorCause::Timeout;
  EXPECT_EQ(publishedState(*server_, *sink_, *pipeline_, counters), SOURCE_STATE_TIMEOUT);
  counters.sourceFailure = vem::SourceErrorCause::BadFrame;
  EXPECT_EQ(publishedState(*server_, *sink_, *pipeline_, counters), SOURCE_STATE_NO_SIGNAL);
  counters.sourceFailure = vem::SourceErrorCause::EndOfStream;
  EXPECT_EQ(publishedState(*server_, *sink_, *pipeline_, counters), SOURCE_STATE_ENDED);
  counters.sourceFailure.reset();
  counters.lastProcessedNs = vem::monotonicNowNs() - 3'000'000'000;  // a source that blocks
  EXPECT_EQ(publishedState(*server_, *sink_, *pipeline_, counters), SOURCE_STATE_TIMEOUT);
}

// A pipeline of the small test camera that has processed sky frames 0 to 11 (its filter is full).
std::optional<vemd::Pipeline> pipelineAfterTwelveFrames() {
  auto pipeline = vemd::pipelineFromCameraFile(vem::testing::smallCameraToml(), "test camera",
                                               vem::testing::smallProcessing());
  if (!pipeline) return std::nullopt;
  vem::CapturedFrame captured;
  for (int i = 0; i < 12; ++i) {
    captured.frame = vem::testing::cachedSkyFrame(i);
    captured.seq = std::uint64_t(i);
    (void)pipeline->process(captured);
  }
  return std::move(*pipeline);
}

TEST(PipelineReconfigure, ChangingTheLightCountKeepsTheFilterRunning) {
  auto pipeline = pipelineAfterTwelveFrames();
  ASSERT_TRUE(pipeline.has_value());
  vem::CapturedFrame captured;
  vem::ProcessingOptions options = pipeline->options();
  options.lightCount = 16;
  ASSERT_TRUE(pipeline->reconfigure(options).has_value());
  captured.frame = vem::testing::cachedSkyFrame(12);
  captured.seq = 12;
  const vem::ProcessedFrame& next = pipeline->process(captured);
  EXPECT_EQ(next.lights.lights.size(), 16u);
  EXPECT_TRUE(next.filtered.has_value());  // the filter kept its history
}

TEST(PipelineReconfigure, ChangingTheFilterStartsItAfresh) {
  auto pipeline = pipelineAfterTwelveFrames();
  ASSERT_TRUE(pipeline.has_value());
  vem::CapturedFrame captured;
  vem::ProcessingOptions options = pipeline->options();
  options.filter = FilterPreset::Equiripple5;
  ASSERT_TRUE(pipeline->reconfigure(options).has_value());
  captured.frame = vem::testing::cachedSkyFrame(12);
  captured.seq = 12;
  const LightSet switched = *pipeline->process(captured).filtered;
  // A pipeline built with the new filter that sees frame 12 first gives the same lights: the
  // history of the old filter is gone.
  auto fresh =
      vemd::pipelineFromCameraFile(vem::testing::smallCameraToml(), "test camera", options);
  ASSERT_TRUE(fresh.has_value());
  const LightSet expected = *fresh->process(captured).filtered;
  ASSERT_EQ(switched.lights.size(), expected.lights.size());
  for (std::size_t i = 0; i < expected.lights.size(); ++i) {
    EXPECT_EQ(switched.lights[i].dir, expected.lights[i].dir) << i;
    EXPECT_EQ(switched.lights[i].rgb, expected.lights[i].rgb) << i;
  }
}

TEST(PipelineReconfigure, OutOfRangeOptionsChangeNothing) {
  auto pipeline = vemd::pipelineFromCameraFile(vem::testing::smallCameraToml(), "test camera",
                                               vem::testing::smallProcessing());
  ASSERT_TRUE(pipeline.has_value());
  vem::ProcessingOptions options = pipeline->options();
  options.lightCount = 0;
  auto done = pipeline->reconfigure(options);
  ASSERT_FALSE(done.has_value());
  EXPECT_NE(done.error().find("light count"), std::string::npos);
  EXPECT_EQ(pipeline->options(), vem::testing::smallProcessing());
}

TEST(RecordingSwitch, StartsStopsAndRefusesASecondStart) {
  const fs::path dir = fs::temp_directory_path() /
                       ("vem-stream-switch-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  vem::SourceDescription source;
  source.cameraModel = "test";
  source.sensorWidthPx = vem::testing::kSensorWidth;
  source.sensorHeightPx = vem::testing::kSensorHeight;
  source.pixelFormat = vem::testing::smallCamera().camera.pixelFormat;
  source.calibrationToml = vem::testing::smallCameraToml();
  RecordingSwitch recorder(dir, vemd::recorderOpener(vemd::recordingContext(source), {}));
  EXPECT_FALSE(recorder.stop().has_value());
  auto started = recorder.start("take1");
  ASSERT_TRUE(started.has_value()) << started.error();
  EXPECT_EQ(*started, dir / "take1.vem");
  EXPECT_FALSE(recorder.start("take2").has_value());
  auto pipeline = vemd::pipelineFromCameraFile(vem::testing::smallCameraToml(), "test camera",
                                               vem::testing::smallProcessing());
  ASSERT_TRUE(pipeline.has_value());
  vem::CapturedFrame captured;
  for (int i = 0; i < 3; ++i) {
    captured.frame = vem::testing::cachedSkyFrame(i);
    captured.seq = std::uint64_t(i);
    ASSERT_TRUE(recorder.consume(pipeline->process(captured)).has_value());
  }
  auto stopped = recorder.stop();
  ASSERT_TRUE(stopped.has_value()) << stopped.error();
  EXPECT_FALSE(recorder.recording());
  auto reader = recording::RecordingReader::open(*stopped);
  ASSERT_TRUE(reader.has_value());
  EXPECT_TRUE(reader->hasIndex());
  EXPECT_EQ(reader->index().size(), 3u);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace vem::stream
