// FakeGvCamera: Aravis's own fake GigE Vision camera (ArvGvFakeCamera) serving on 127.0.0.1, with
// a fill callback that draws the frames the test gives it, in turn, packed into whatever pixel
// format the camera is set to (pixel_packing.h). Destroying it makes the camera vanish from the
// network (for the fault tests). Only inside the tests' network namespace (run_in_netns.sh).
//
// The GenICam description: tests/cameras/aravis/fake_camera.xml.in with the PixelFormat entries
// asked for (writeFakeGenicam), or Aravis's built-in one (Mono8, Mono16, RGB8, Bayer; GainRaw).
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "frames/raw_frame.h"

struct _ArvGvFakeCamera;

namespace vem::testing {

// Writes the test description offering `pixelFormats` (GenICam names) to a file; its path.
[[nodiscard]] std::string writeFakeGenicam(const std::vector<std::string>& pixelFormats);

class FakeGvCamera {
 public:
  // genicamPath "" = Aravis's built-in description. Fails the test (and returns nullptr) if the
  // camera does not come up.
  [[nodiscard]] static std::unique_ptr<FakeGvCamera> start(const std::string& serial,
                                                           const std::string& genicamPath);
  ~FakeGvCamera();
  FakeGvCamera(const FakeGvCamera&) = delete;
  FakeGvCamera& operator=(const FakeGvCamera&) = delete;

  void serve(std::vector<vem::RawFrame> frames);
  [[nodiscard]] std::uint64_t framesDrawn() const { return drawn_.load(); }
  // The raw register values the last fill saw: exposure in us, gain register (1/100 dB in the
  // test description).
  [[nodiscard]] std::uint32_t lastExposureRegister() const { return exposure_.load(); }
  [[nodiscard]] std::uint32_t lastGainRegister() const { return gain_.load(); }

 private:
  FakeGvCamera() = default;
  static void fill(void* buffer, void* self, std::uint32_t exposureUs, std::uint32_t gain,
                   std::uint32_t pixelFormat);

  _ArvGvFakeCamera* camera_ = nullptr;
  std::mutex mutex_;
  std::vector<vem::RawFrame> frames_;
  std::atomic<std::uint64_t> drawn_{0};
  std::atomic<std::uint32_t> exposure_{0};
  std::atomic<std::uint32_t> gain_{0};
};

}  // namespace vem::testing
