// Hand-made vem.stream.ServerMessages for the client's tests: built field by field here, not by
// vemd's encoder, so the tests check the client against the schema rather than against the server.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "proto/vem_stream.pb.h"

namespace vem::client::test {

// A valid light frame: `count` lights with ids 0.., unit dirs, rgb (i + 1, 2i + 1, 0.5).
[[nodiscard]] stream::ServerMessage lightFrameMessage(std::uint64_t seq, int count = 3);
// A valid environment frame: face `facePx`, `levels` levels, texel value i-th = (i % 7) * 0.25.
[[nodiscard]] stream::ServerMessage environmentMessage(std::uint64_t seq, int facePx, int levels);
[[nodiscard]] stream::ServerMessage helloMessage(bool controlAllowed = false);
// Sets protocol_major (default 1) and minor, returns the bytes.
[[nodiscard]] std::string bytesOf(stream::ServerMessage message, std::uint32_t major = 1,
                                  std::uint32_t minor = 0);
// The texel values environmentMessage packs.
[[nodiscard]] std::vector<float> testTexels(int facePx, int levels);

}  // namespace vem::client::test
