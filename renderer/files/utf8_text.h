// Text from outside (a tool's log, its error output) as valid UTF-8.
//
// Logs are bytes: a tool may print any, and a log tail may start inside a
// character. Records and results.json are JSON, which holds only UTF-8
// text, so every such text goes through validUtf8 before it is stored:
// each byte that does not start a well-formed UTF-8 sequence (a stray
// continuation byte, a truncated sequence, an overlong form, a surrogate,
// a code point above U+10FFFF, 0xC0, 0xC1, 0xF5..0xFF) becomes U+FFFD,
// the replacement character, and the text around it is kept as it was.
#pragma once

#include <string>
#include <string_view>

namespace xval {

inline constexpr std::string_view kUtf8Replacement = "\xEF\xBF\xBD";  // U+FFFD

// The length of the well-formed UTF-8 sequence at s[i], or 0 if none
// starts there (RFC 3629, its table of well-formed byte sequences).
inline size_t utf8SequenceLength(std::string_view s, size_t i) {
  auto byte = [&s](size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char b = byte(i);
  if (b < 0x80) return 1;
  size_t n = 0;
  unsigned char lo = 0x80, hi = 0xBF;  // the second byte's range
  if (b >= 0xC2 && b <= 0xDF) n = 2;
  else if (b >= 0xE0 && b <= 0xEF) n = 3, lo = b == 0xE0 ? 0xA0 : 0x80, hi = b == 0xED ? 0x9F : 0xBF;
  else if (b >= 0xF0 && b <= 0xF4) n = 4, lo = b == 0xF0 ? 0x90 : 0x80, hi = b == 0xF4 ? 0x8F : 0xBF;
  else return 0;
  if (i + n > s.size()) return 0;
  if (byte(i + 1) < lo || byte(i + 1) > hi) return 0;
  for (size_t k = 2; k < n; ++k)
    if (byte(i + k) < 0x80 || byte(i + k) > 0xBF) return 0;
  return n;
}

// `text` with each byte that starts no well-formed sequence replaced by U+FFFD.
inline std::string validUtf8(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (size_t i = 0; i < text.size();) {
    const size_t n = utf8SequenceLength(text, i);
    if (n == 0) {
      out += kUtf8Replacement;
      ++i;
    } else {
      out.append(text.substr(i, n));
      i += n;
    }
  }
  return out;
}

// Where a text cut at byte `from` of a UTF-8 text may start: past the
// continuation bytes (10xxxxxx) of a character the cut fell inside (at
// most 3 of them), so that no half character is quoted.
inline size_t utf8CharacterStart(std::string_view text, size_t from) {
  size_t i = from;
  while (i < text.size() && i < from + 3 && (static_cast<unsigned char>(text[i]) & 0xC0) == 0x80) ++i;
  return i;
}

}  // namespace xval
