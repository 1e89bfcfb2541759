// SHA-256 (OpenSSL's EVP digest) of files, strings and streamed pieces:
// what golden images, the export cache, job exports, validate's plan and
// set packs use to tell whether bytes changed.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>

namespace xval {

// SHA-256 of a file's bytes / of a string, as 64 lower-case hex digits.
// Throws std::runtime_error naming the file when it cannot be read.
std::string sha256File(const std::filesystem::path& file);
// The same, reading no more than max_bytes + one buffer: throws naming the
// file when it holds more (a sparse or growing file is never read whole).
std::string sha256File(const std::filesystem::path& file, std::uintmax_t max_bytes);
std::string sha256Text(const std::string& text);
// SHA-256 over the pieces `feed` passes to the function it is given (a
// file copied and hashed in one pass).
std::string sha256Pieces(const std::function<void(const std::function<void(const char*, size_t)>&)>& feed);

}  // namespace xval
