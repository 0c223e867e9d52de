// printable: text that came from outside vemd (a client's close reason, a recording name, a file
// name read from a scene or a recording, a peer's HTTP header) made safe to put into a log line or
// a one-sentence message. A forged line cannot start inside it and a terminal cannot be steered by
// it:
// - printable ASCII and well-formed UTF-8 stay as they are;
// - backslash becomes "\\", newline "\n", carriage return "\r", tab "\t";
// - every other control byte, and every byte of malformed UTF-8, becomes "\xNN";
// - C1 controls (U+0080..U+009F), the bidirectional overrides and isolates (U+202A..U+202E,
//   U+2066..U+2069) and the line and paragraph separators (U+2028, U+2029) become "\u{XXXX}";
// - beyond `maxBytes` bytes of input, the rest is dropped and "... (N more bytes)" says so.
// Pure, no allocation beyond the result; the fuzz targets compile it (no <expected>).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace vem::util {

inline constexpr std::size_t kDefaultPrintableBytes = 256;

[[nodiscard]] std::string printable(std::string_view text,
                                    std::size_t maxBytes = kDefaultPrintableBytes);

// True when printable(text) would return `text` unchanged (and it is within maxBytes).
[[nodiscard]] bool isPrintable(std::string_view text,
                               std::size_t maxBytes = kDefaultPrintableBytes);

}  // namespace vem::util
