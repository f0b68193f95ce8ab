#include "util/shown_text.h"

#include <cstdio>
#include <vector>

namespace ncube {

namespace {

// One shown unit: the bytes of one character as printed (escaped or not), and whether it is a
// space (a word's end).
struct Unit {
  std::string text;
  bool space;
};

std::string hex_escape(const char* form, unsigned value) {
  char buffer[16];
  std::snprintf(buffer, sizeof buffer, form, value);
  return buffer;
}

// The length of the valid UTF-8 sequence starting at `at`, or 0 when it is not one (a stray
// continuation byte, an overlong form, a surrogate, a value past U+10FFFF, a cut sequence).
std::size_t utf8_length(std::string_view text, std::size_t at, unsigned& code) {
  const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
  const unsigned lead = byte(at);
  std::size_t length = 0;
  if (lead >= 0xC2 && lead <= 0xDF) length = 2, code = lead & 0x1F;
  else if (lead >= 0xE0 && lead <= 0xEF) length = 3, code = lead & 0x0F;
  else if (lead >= 0xF0 && lead <= 0xF4) length = 4, code = lead & 0x07;
  else return 0;
  if (at + length > text.size()) return 0;
  for (std::size_t i = 1; i < length; ++i) {
    if ((byte(at + i) & 0xC0) != 0x80) return 0;
    code = (code << 6) | (byte(at + i) & 0x3F);
  }
  static const unsigned kSmallest[5] = {0, 0, 0x80, 0x800, 0x10000};
  if (code < kSmallest[length] || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF)) return 0;
  return length;
}

std::vector<Unit> units_of(std::string_view text) {
  std::vector<Unit> units;
  for (std::size_t at = 0; at < text.size();) {
    const unsigned char c = static_cast<unsigned char>(text[at]);
    if (c < 0x80) {
      std::string shown;
      switch (c) {
        case '\n': shown = "\\n"; break;
        case '\r': shown = "\\r"; break;
        case '\t': shown = "\\t"; break;
        case 0x1B: shown = "\\e"; break;
        default: shown = c < 0x20 || c == 0x7F ? hex_escape("\\x%02x", c) : std::string(1, char(c));
      }
      units.push_back({shown, c == ' '});
      ++at;
      continue;
    }
    unsigned code = 0;
    const std::size_t length = utf8_length(text, at, code);
    if (length == 0) {
      units.push_back({hex_escape("\\x%02x", c), false});
      ++at;
    } else {
      // C1 controls (U+0080 to U+009F: U+009B is a one-character escape sequence for some
      // terminals) are escaped like C0's.
      units.push_back({code <= 0x9F ? hex_escape("\\u%04x", code) : std::string(text.substr(at, length)),
                       false});
      at += length;
    }
  }
  return units;
}

// units[first, last) appended to `out`, cut to `keep` units around "[... N characters ...]"
// (one unit) when longer.
void append_cut(std::vector<Unit>& out, const std::vector<Unit>& units, std::size_t first,
                std::size_t last, std::size_t keep) {
  const std::size_t count = last - first;
  if (count <= keep) {
    out.insert(out.end(), units.begin() + first, units.begin() + last);
    return;
  }
  const std::size_t tail = keep / 4, head = keep - tail;
  out.insert(out.end(), units.begin() + first, units.begin() + first + head);
  out.push_back({"[... " + std::to_string(count - head - tail) + " characters ...]", false});
  out.insert(out.end(), units.begin() + (last - tail), units.begin() + last);
}

}  // namespace

std::string shown_text(std::string_view text) {
  const std::vector<Unit> units = units_of(text);
  // Each word cut first, then the whole.
  std::vector<Unit> words_cut;
  for (std::size_t at = 0; at < units.size();) {
    std::size_t end = at;
    while (end < units.size() && !units[end].space) ++end;
    append_cut(words_cut, units, at, end, kMaxShownWord);
    if (end < units.size()) words_cut.push_back(units[end++]);
    at = end;
  }
  std::vector<Unit> whole;
  append_cut(whole, words_cut, 0, words_cut.size(), kMaxShownMessage);
  std::string out;
  for (const Unit& unit : whole) out += unit.text;
  return out;
}

}  // namespace ncube
