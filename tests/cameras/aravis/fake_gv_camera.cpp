#include "fake_gv_camera.h"

#include <arv.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <sstream>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "cameras/aravis/aravis_pixel_formats.h"
#include "pixel_packing.h"

namespace vem::testing {

std::string writeFakeGenicam(const std::vector<std::string>& pixelFormats) {
  std::ifstream in(std::string(VEM_ARAVIS_TEST_DIR) + "/fake_camera.xml.in");
  std::stringstream text;
  text << in.rdbuf();
  std::string entries;
  for (const auto& name : pixelFormats) {
    std::uint32_t code = 0x01080009u;  // BayerRG8: offered but not read by the backend
    if (const auto* native = cameras::nativeFormatByName(name)) code = native->code;
    entries += fmt::format(
        "    <EnumEntry Name=\"{}\" NameSpace=\"Standard\"><Value>{}</Value></EnumEntry>\n", name,
        code);
  }
  std::string xml = text.str();
  const std::string placeholder = "@PIXEL_FORMAT_ENTRIES@";
  xml.replace(xml.find(placeholder), placeholder.size(), entries);
  const std::string path = ::testing::TempDir() + "vem_fake_camera_" +
                           fmt::format("{}", fmt::join(pixelFormats, "_")) + ".xml";
  std::ofstream(path) << xml;
  return path;
}

std::unique_ptr<FakeGvCamera> FakeGvCamera::start(const std::string& serial,
                                                  const std::string& genicamPath) {
  std::unique_ptr<FakeGvCamera> fake(new FakeGvCamera);
  fake->camera_ = arv_gv_fake_camera_new_full("lo", serial.c_str(),
                                              genicamPath.empty() ? nullptr : genicamPath.c_str());
  if (fake->camera_ == nullptr || !arv_gv_fake_camera_is_running(fake->camera_)) {
    ADD_FAILURE() << "the fake GigE Vision camera did not start on lo";
    return nullptr;
  }
  arv_fake_camera_set_fill_pattern(arv_gv_fake_camera_get_fake_camera(fake->camera_),
                                   reinterpret_cast<ArvFakeCameraFillPattern>(&FakeGvCamera::fill),
                                   fake.get());
  return fake;
}

FakeGvCamera::~FakeGvCamera() {
  if (camera_ != nullptr) g_object_unref(camera_);
}

void FakeGvCamera::serve(std::vector<vem::RawFrame> frames) {
  std::lock_guard lock(mutex_);
  frames_ = std::move(frames);
}

void FakeGvCamera::fill(void* buffer, void* self, std::uint32_t exposureUs, std::uint32_t gain,
                        std::uint32_t pixelFormat) {
  auto* fake = static_cast<FakeGvCamera*>(self);
  auto* arvBuffer = static_cast<ArvBuffer*>(buffer);
  fake->exposure_.store(exposureUs);
  fake->gain_.store(gain);
  const auto* native = cameras::nativeFormatByCode(pixelFormat);
  std::lock_guard lock(fake->mutex_);
  if (fake->frames_.empty() || native == nullptr) return;
  const std::uint64_t n = fake->drawn_.fetch_add(1);
  const vem::RawFrame& frame = fake->frames_[n % fake->frames_.size()];
  if (arv_buffer_get_image_width(arvBuffer) != frame.width ||
      arv_buffer_get_image_height(arvBuffer) != frame.height) {
    return;  // the test set another size than its frames': they arrive blank
  }
  const std::vector<std::uint8_t> bytes = packPixels(native->genicamName, frame.codes);
  size_t size = 0;
  // The fake camera hands its own buffer to fill; Aravis's own patterns write it the same way.
  auto* data = static_cast<std::uint8_t*>(const_cast<void*>(arv_buffer_get_data(arvBuffer, &size)));
  std::memcpy(data, bytes.data(),
              std::min(bytes.size(), cameras::payloadBytes(*native, frame.width, frame.height)));
}

}  // namespace vem::testing
