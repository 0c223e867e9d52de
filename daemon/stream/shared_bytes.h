// SharedBytes: one serialized message, built once and shared by everyone it goes to.
#pragma once

#include <memory>
#include <string>

namespace vem::stream {

using SharedBytes = std::shared_ptr<const std::string>;

}  // namespace vem::stream
