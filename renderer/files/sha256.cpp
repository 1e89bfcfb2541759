#include "files/sha256.h"

#include <openssl/evp.h>

#include <fstream>
#include <limits>
#include <memory>
#include <stdexcept>
#include <vector>

namespace xval {

namespace fs = std::filesystem;

namespace {

// SHA-256 over whatever `feed` passes to its argument, in pieces.
template <class Feed>
std::string sha256Of(Feed feed) {
  std::unique_ptr<EVP_MD_CTX, decltype(&EVP_MD_CTX_free)> ctx(EVP_MD_CTX_new(), &EVP_MD_CTX_free);
  if (!ctx || EVP_DigestInit_ex(ctx.get(), EVP_sha256(), nullptr) != 1)
    throw std::runtime_error("SHA-256: cannot initialise OpenSSL's digest");
  feed([&](const char* data, size_t n) {
    if (EVP_DigestUpdate(ctx.get(), data, n) != 1) throw std::runtime_error("SHA-256: digest update failed");
  });
  unsigned char md[EVP_MAX_MD_SIZE];
  unsigned int len = 0;
  if (EVP_DigestFinal_ex(ctx.get(), md, &len) != 1) throw std::runtime_error("SHA-256: digest failed");
  static const char* hex = "0123456789abcdef";
  std::string out;
  for (unsigned int i = 0; i < len; ++i) out += {hex[md[i] >> 4], hex[md[i] & 15]};
  return out;
}

}  // namespace

std::string sha256File(const fs::path& file) { return sha256File(file, std::numeric_limits<std::uintmax_t>::max()); }

std::string sha256File(const fs::path& file, std::uintmax_t max_bytes) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::runtime_error(file.string() + ": cannot read (for its SHA-256)");
  return sha256Of([&](auto update) {
    std::vector<char> buf(1 << 16);
    std::uintmax_t read = 0;
    while (in.read(buf.data(), std::streamsize(buf.size())) || in.gcount() > 0) {
      read += std::uintmax_t(in.gcount());
      if (read > max_bytes)
        throw std::runtime_error(file.string() + ": holds more than the " + std::to_string(max_bytes) +
                                 " bytes expected (not hashed further)");
      update(buf.data(), size_t(in.gcount()));
    }
    if (in.bad()) throw std::runtime_error(file.string() + ": read error (for its SHA-256)");
  });
}

std::string sha256Text(const std::string& text) {
  return sha256Of([&](auto update) { update(text.data(), text.size()); });
}

std::string sha256Pieces(const std::function<void(const std::function<void(const char*, size_t)>&)>& feed) {
  return sha256Of([&](auto update) { feed(update); });
}

}  // namespace xval
