// The stream input of light_input.h: vemd's stream through the client library.
#include <fmt/format.h>

#include "client/stream_client.h"
#include "client/vemview/light_input.h"

namespace vem::view {
namespace {

class StreamLightInput final : public LightInput {
 public:
  StreamLightInput(InputFacts facts, std::unique_ptr<client::StreamClient> client)
      : facts_(std::move(facts)), client_(std::move(client)) {}
  ~StreamLightInput() override { client_->stop(); }
  StreamLightInput(const StreamLightInput&) = delete;
  StreamLightInput& operator=(const StreamLightInput&) = delete;

  const InputFacts& facts() const override { return facts_; }

  std::optional<InputFrame> next(std::chrono::milliseconds wait) override {
    const std::optional<std::uint64_t> after =
        last_ ? std::optional<std::uint64_t>(last_->seq) : std::nullopt;
    if (auto received = client_->waitForLightFrame(after, wait)) {
      InputFrame frame;
      frame.seq = received->frame.seq;
      if (received->frame.captureUnixNs > 0) {
        frame.captureUnixSec = double(received->frame.captureUnixNs) * 1e-9;
      }
      frame.lights = std::make_shared<const LightSet>(std::move(received->frame.lights));
      last_ = frame;
    }
    if (last_) {
      refreshCube();
    }
    return last_;
  }

  std::string failure() const override {
    return client_->state() == client::ConnectionState::Refused
               ? fmt::format("{}: {}", facts_.description, client_->stateReason())
               : std::string();
  }

 private:
  void refreshCube() {
    auto environment = client_->latestEnvironmentFrame();
    if (environment && environment->frame.seq + 1 != cubeVersion_) {
      cube_ = std::make_shared<const CubeMap>(std::move(environment->frame.cube));
      cubeVersion_ = environment->frame.seq + 1;
    }
    last_->cube = cube_;
    last_->cubeVersion = cubeVersion_;
  }

  InputFacts facts_;
  std::unique_ptr<client::StreamClient> client_;
  std::optional<InputFrame> last_;
  std::shared_ptr<const CubeMap> cube_;
  std::uint64_t cubeVersion_ = 0;
};

}  // namespace

std::expected<std::unique_ptr<LightInput>, std::string> openStreamInput(
    const StreamInputOptions& options) {
  client::StreamClientOptions clientOptions;
  clientOptions.url = options.url;
  clientOptions.token = options.token;
  clientOptions.username = options.security.username;
  clientOptions.password = options.security.password;
  clientOptions.caFile = options.security.caFile;
  clientOptions.certFile = options.security.certFile;
  clientOptions.keyFile = options.security.keyFile;
  clientOptions.subscription.lights = true;
  if (options.cubeMap) {
    clientOptions.subscription.cubemapRateHz = options.cubeMapRateHz;
    clientOptions.subscription.cubemapFacePx = options.cubeFacePx;
    clientOptions.subscription.cubemapLevels = 8;
  }
  auto client = client::StreamClient::start(std::move(clientOptions));
  if (!client) {
    return std::unexpected(client.error());
  }
  InputFacts facts;
  facts.description = fmt::format("stream {}{}", options.url,
                                  options.cubeMap ? " (lights and cube maps)" : " (lights only)");
  facts.layout = MapLayout::Hemisphere;
  facts.live = true;
  return std::make_unique<StreamLightInput>(std::move(facts), std::move(*client));
}

}  // namespace vem::view
