// A word of a command line that xval prints for the user to paste (next
// steps, "Reproduce:" lines, the command that accepts a golden image), as a
// POSIX shell reads it back: left bare when made only of characters no
// shell interprets, else single-quoted with each ' written '\''. A scene,
// folder or renderer file name can then not run anything when pasted.
#pragma once

#include <algorithm>
#include <cctype>
#include <string>
#include <string_view>

namespace xval {

inline std::string shellWord(const std::string& w) {
  if (!w.empty() && std::all_of(w.begin(), w.end(), [](unsigned char c) {
        return std::isalnum(c) || std::string_view("/._-+:=,@").find(char(c)) != std::string_view::npos;
      }))
    return w;
  std::string out = "'";
  for (char c : w) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

}  // namespace xval
