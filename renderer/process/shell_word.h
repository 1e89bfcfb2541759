// A word of a command line that xval prints for the user to paste (next
// steps, "Reproduce:" lines, the command that accepts a golden image), as a
// POSIX shell reads it back: left bare when made only of characters no
// shell interprets, else single-quoted with each ' written '\''. A scene,
// folder or renderer file name can then not run anything when pasted.
#pragma once

#include <algorithm>
#include <cctype>
#include <filesystem>
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

// A path as a word of such a command: relative to the working folder when
// it lies below it, else absolute (lexically normal either way). The
// command then runs as printed from the folder xval ran in, and a
// published results.json or report carries no absolute path of the machine
// it was made on. A relative path that would read as an option gets "./".
inline std::string shellPath(const std::filesystem::path& p) {
  std::error_code ec;
  const std::filesystem::path abs = std::filesystem::absolute(p, ec).lexically_normal();
  if (ec) return shellWord(p.string());
  const std::filesystem::path cwd = std::filesystem::current_path(ec);
  const std::filesystem::path rel = ec ? std::filesystem::path() : abs.lexically_relative(cwd);
  if (rel.empty() || *rel.begin() == ".." || rel == ".") return shellWord(abs.string());
  const std::string r = rel.string();
  return shellWord(r[0] == '-' ? "./" + r : r);
}

}  // namespace xval
