#include "cameras/v4l2/fake_v4l2_camera.h"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "cameras/v4l2/fake_v4l2_device.h"
#include "frames/frame_source.h"

namespace vem::testing {

namespace {

FakeControl integerControl(std::uint32_t id, const char* name, std::int32_t type, int minimum,
                           int maximum, int step, int defaultValue) {
  FakeControl c;
  c.query.id = id;
  c.query.type = std::uint32_t(type);
  std::strncpy(reinterpret_cast<char*>(c.query.name), name, sizeof c.query.name - 1);
  c.query.minimum = minimum;
  c.query.maximum = maximum;
  c.query.step = step;
  c.query.default_value = defaultValue;
  c.value = defaultValue;
  return c;
}

}  // namespace

std::vector<FakeControl> FakeV4l2Config::defaultControls() {
  return {integerControl(V4L2_CID_EXPOSURE_AUTO, "Auto Exposure", V4L2_CTRL_TYPE_MENU, 0, 3, 1,
                         V4L2_EXPOSURE_APERTURE_PRIORITY),
          integerControl(V4L2_CID_EXPOSURE_ABSOLUTE, "Exposure Time, Absolute",
                         V4L2_CTRL_TYPE_INTEGER, 1, 10000, 1, 156),
          integerControl(V4L2_CID_GAIN, "Gain", V4L2_CTRL_TYPE_INTEGER, 0, 255, 1, 32)};
}

FakeV4l2Camera::FakeV4l2Camera(FakeV4l2Config config) : state_(std::make_shared<FakeV4l2State>()) {
  if (config.formats.empty() || config.formats.front().sizes.empty()) {
    std::fprintf(stderr, "FakeV4l2Camera: needs at least one format with a size\n");
    std::abort();
  }
  FakeV4l2State& s = *state_;
  s.card = config.card;
  s.busInfo = config.busInfo;
  s.driver = config.driver;
  s.deviceCaps = config.deviceCaps;
  s.formats = config.formats;
  s.refusedFourccs = config.refusedFourccs;
  s.rowAlignBytes = std::max<std::size_t>(config.rowAlignBytes, 1);
  s.frameRatesHz = config.frameRatesHz;
  s.maxBuffers = config.maxBuffers;
  for (const FakeControl& c : config.controls) s.controlDefaults[c.query.id] = c;
  s.resetSettings();
}

std::expected<std::unique_ptr<cameras::V4l2Device>, int> FakeV4l2Camera::open() {
  std::lock_guard lock(state_->mutex);
  if (!state_->plugged) return std::unexpected(ENOENT);
  return std::make_unique<FakeV4l2Device>(state_);
}

cameras::V4l2Opener FakeV4l2Camera::opener(std::string expectedPath) {
  return [this, expectedPath](
             const std::string& path) -> std::expected<std::unique_ptr<cameras::V4l2Device>, int> {
    if (!expectedPath.empty() && path != expectedPath) return std::unexpected(ENOENT);
    return open();
  };
}

bool FakeV4l2Camera::pushFrame(const FakeFrame& frame) {
  std::lock_guard lock(state_->mutex);
  return state_->deliver(frame, vem::monotonicNowNs());
}

void FakeV4l2Camera::setGenerator(FakeFrameGenerator generator, std::int64_t periodNs) {
  std::lock_guard lock(state_->mutex);
  state_->generator = std::move(generator);
  state_->periodNs = periodNs;
  state_->nextDueNs = vem::monotonicNowNs() + periodNs;
  state_->ready.signal();
}

void FakeV4l2Camera::unplug() {
  std::lock_guard lock(state_->mutex);
  FakeV4l2State& s = *state_;
  s.plugged = false;
  ++s.generation;
  s.releaseQueue();
  s.graveyard.push_back(std::move(s.buffers));
  s.buffers.clear();
  s.owner = 0;
  s.ready.signal();
}

void FakeV4l2Camera::replug() {
  std::lock_guard lock(state_->mutex);
  state_->plugged = true;
  state_->sequence = 0;
  state_->resetSettings();
}

void FakeV4l2Camera::failNext(unsigned long request, int error, int count) {
  std::lock_guard lock(state_->mutex);
  state_->faults.push_back({request, error, count});
}

v4l2_pix_format FakeV4l2Camera::format() const {
  std::lock_guard lock(state_->mutex);
  return state_->format;
}

int FakeV4l2Camera::control(std::uint32_t id) const {
  std::lock_guard lock(state_->mutex);
  return state_->controls.at(id).value;
}

double FakeV4l2Camera::frameRateHz() const {
  std::lock_guard lock(state_->mutex);
  return state_->frameRateHz;
}

std::vector<std::uint32_t> FakeV4l2Camera::requestedBufferCounts() const {
  std::lock_guard lock(state_->mutex);
  return state_->requestedBufferCounts;
}

std::size_t FakeV4l2Camera::allocatedBuffers() const {
  std::lock_guard lock(state_->mutex);
  return state_->buffers.size();
}

int FakeV4l2Camera::mappedBuffers() const {
  std::lock_guard lock(state_->mutex);
  int mapped = 0;
  for (const FakeBuffer& b : state_->buffers) mapped += b.mappings;
  return mapped;
}

std::size_t FakeV4l2Camera::queuedBuffers() const {
  std::lock_guard lock(state_->mutex);
  return state_->queued.size();
}

bool FakeV4l2Camera::streaming() const {
  std::lock_guard lock(state_->mutex);
  return state_->streaming;
}

std::uint64_t FakeV4l2Camera::droppedFrames() const {
  std::lock_guard lock(state_->mutex);
  return state_->dropped;
}

int FakeV4l2Camera::pendingFaults() const {
  std::lock_guard lock(state_->mutex);
  int n = 0;
  for (const auto& f : state_->faults) n += f.count;
  return n;
}

}  // namespace vem::testing
