// Text the user gave (a file name, an option, a value) as a message shows it: one helper for
// every message that echoes user input (docs/cli.md, "Exit codes"), so that a name cannot
// move the terminal's cursor, change its colours or fill the screen.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace ncube {

// A word (a run of characters without a space) longer than this is cut in the middle.
constexpr std::size_t kMaxShownWord = 200;
// A whole message longer than this is cut in the middle (with the tool's name and a closing
// remark, a message stays under 2,000 bytes but for the escapes of a cut word).
constexpr std::size_t kMaxShownMessage = 1800;

// `text` with every control character escaped (C0, DEL and C1: "\n", "\t", "\e", "\x7f",
// "\u009b"), every byte that is not part of valid UTF-8 escaped ("\xff"), each word over
// kMaxShownWord characters cut to its beginning and end around "[... N characters ...]", and
// the whole over kMaxShownMessage cut likewise. Printable text, valid UTF-8 included, is kept
// as it is.
std::string shown_text(std::string_view text);

}  // namespace ncube
