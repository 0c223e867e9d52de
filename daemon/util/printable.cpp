#include "util/printable.h"

#include <cstdint>
#include <cstdio>

namespace vem::util {

namespace {

// Length of the well-formed UTF-8 sequence at the start of `text` (RFC 3629: no overlong forms,
// no surrogates, nothing above U+10FFFF) and its code point; 0 when it is not one.
std::size_t utf8Sequence(std::string_view text, char32_t& codePoint) {
  const auto byte = [&](std::size_t i) { return std::uint8_t(text[i]); };
  const std::uint8_t lead = byte(0);
  std::size_t length = 0;
  char32_t min = 0;
  if (lead >= 0xC2 && lead <= 0xDF) {
    length = 2, codePoint = lead & 0x1Fu, min = 0x80;
  } else if (lead >= 0xE0 && lead <= 0xEF) {
    length = 3, codePoint = lead & 0x0Fu, min = 0x800;
  } else if (lead >= 0xF0 && lead <= 0xF4) {
    length = 4, codePoint = lead & 0x07u, min = 0x10000;
  } else {
    return 0;
  }
  if (text.size() < length) return 0;
  for (std::size_t i = 1; i < length; ++i) {
    if ((byte(i) & 0xC0u) != 0x80u) return 0;
    codePoint = (codePoint << 6) | (byte(i) & 0x3Fu);
  }
  if (codePoint < min || codePoint > 0x10FFFF || (codePoint >= 0xD800 && codePoint <= 0xDFFF)) {
    return 0;
  }
  return length;
}

bool invisibleControl(char32_t codePoint) {
  return (codePoint >= 0x80 && codePoint <= 0x9F) || (codePoint >= 0x202A && codePoint <= 0x202E) ||
         (codePoint >= 0x2066 && codePoint <= 0x2069) || codePoint == 0x2028 || codePoint == 0x2029;
}

void appendByte(std::string& out, unsigned byte) {
  char text[8];
  std::snprintf(text, sizeof text, "\\x%02x", byte);
  out += text;
}

void appendCodePoint(std::string& out, unsigned codePoint) {
  char text[16];
  std::snprintf(text, sizeof text, "\\u{%04x}", codePoint);
  out += text;
}

}  // namespace

std::string printable(std::string_view text, std::size_t maxBytes) {
  const std::size_t kept = text.size() < maxBytes ? text.size() : maxBytes;
  std::string out;
  out.reserve(kept + 16);
  std::size_t i = 0;
  while (i < kept) {
    const char c = text[i];
    const auto byte = std::uint8_t(c);
    if (byte >= 0x20 && byte < 0x7F) {
      if (c == '\\') out += '\\';
      out += c;
      ++i;
      continue;
    }
    switch (c) {
      case '\n': out += "\\n", ++i; continue;
      case '\r': out += "\\r", ++i; continue;
      case '\t': out += "\\t", ++i; continue;
      default: break;
    }
    char32_t codePoint = 0;
    const std::size_t length = byte >= 0x80 ? utf8Sequence(text.substr(i, kept - i), codePoint) : 0;
    if (length == 0) {
      appendByte(out, byte);
      ++i;
    } else if (invisibleControl(codePoint)) {
      appendCodePoint(out, unsigned(codePoint));
      i += length;
    } else {
      out.append(text.substr(i, length));
      i += length;
    }
  }
  if (text.size() > kept) {
    out += "... (" + std::to_string(text.size() - kept) + " more bytes)";
  }
  return out;
}

bool isPrintable(std::string_view text, std::size_t maxBytes) {
  return text.size() <= maxBytes && printable(text, maxBytes) == text;
}

}  // namespace vem::util
