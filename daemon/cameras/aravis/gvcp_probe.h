// GVCP probe: asks one GigE Vision camera, by unicast to its address, whether it is there (a
// READREG of the bootstrap Version register, GigE Vision 2.x section 15.3), and finds the local
// address that routes to it. Never broadcasts. Lets the Aravis backend reopen a camera by address
// without Aravis's own open, which waits about 2.5 s for an absent camera and, when that fails,
// falls back to broadcast discovery.
//
// Conventions: IPv4 dotted quads; GVCP on UDP port 3956; waits in milliseconds.
#pragma once

#include <cstdint>
#include <expected>
#include <optional>
#include <string>

namespace vem::cameras {

inline constexpr std::uint16_t kGvcpPort = 3956;

// The address `text` names when it is a dotted IPv4 quad ("192.168.1.20"), else nullopt.
[[nodiscard]] std::optional<std::uint32_t> parseIpv4(const std::string& text);  // host order

// The local IPv4 address the kernel would send from to reach `deviceAddress` (a connected UDP
// socket's name: no packet leaves), as a dotted quad; or a sentence.
[[nodiscard]] std::expected<std::string, std::string> localAddressToward(
    std::uint32_t deviceAddress);

// True when a GVCP acknowledge (any status: a camera another host controls still answers)
// comes back from `deviceAddress` within `waitMs`; else a sentence saying what failed.
[[nodiscard]] std::expected<void, std::string> probeGvcp(std::uint32_t deviceAddress, int waitMs);

}  // namespace vem::cameras
