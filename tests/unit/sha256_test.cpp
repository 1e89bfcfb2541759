// files/sha256.h against the standard's test vectors (FIPS 180-2, appendix
// B: "abc" and the 448-bit message), a file hashed whole and in pieces, and
// the size bound that refuses a file larger than expected.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "files/sha256.h"

namespace xval {
namespace {

namespace fs = std::filesystem;

TEST(Sha256, StandardTestVectors) {
  EXPECT_EQ(sha256Text("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(sha256Text("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  EXPECT_EQ(sha256Text(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
}

TEST(Sha256, AFileHashesAsItsBytesWholeOrInPiecesAndTheBoundRefusesMore) {
  const fs::path file = fs::temp_directory_path() / ("xval_sha256_" + std::to_string(getpid()));
  std::string bytes;
  for (int k = 0; k < 200000; ++k) bytes += char('a' + k % 26);  // more than one 64 KiB read
  std::ofstream(file, std::ios::binary) << bytes;
  EXPECT_EQ(sha256File(file), sha256Text(bytes));
  EXPECT_EQ(sha256File(file, bytes.size()), sha256Text(bytes));
  EXPECT_EQ(sha256Pieces([&](const auto& update) {
              update(bytes.data(), 1000);
              update(bytes.data() + 1000, bytes.size() - 1000);
            }),
            sha256Text(bytes));
  EXPECT_THROW(sha256File(file, bytes.size() - 1), std::runtime_error);
  fs::remove(file);
  EXPECT_THROW(sha256File(file), std::runtime_error);
}

}  // namespace
}  // namespace xval
