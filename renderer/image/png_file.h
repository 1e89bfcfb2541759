// PNG files through libpng directly (no OpenImageIO: its 260 shared
// libraries cost every xval process most of its start-up;
// docs/performance.md). Decoding keeps the stored values: palette and
// 1-, 2- and 4-bit grey are expanded to 8 bits, transparency (tRNS) to an
// alpha channel; no gamma is applied and alpha is never multiplied in
// (PNG's alpha is unassociated).
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "image/image_header.h"

namespace xval {

struct PngPixels {
  int width = 0, height = 0;
  int channels = 0;  // 1 grey, 2 grey + alpha, 3 RGB, 4 RGBA
  int bits = 8;      // 8: samples in `bytes`; 16: in `words`
  std::vector<std::uint8_t> bytes;
  std::vector<std::uint16_t> words;
};

// Called with the header (after expansion) before any pixel is allocated:
// throws to refuse the image.
using PngHeaderCheck = std::function<void(const ImageHeader&)>;

// Decodes a whole PNG file, or `size` bytes at `data`. `what` names the
// image in errors (std::runtime_error "<what>: ...").
PngPixels readPngFile(const std::filesystem::path& file, const PngHeaderCheck& check);
PngPixels decodePng(const std::uint8_t* data, size_t size, const std::string& what, const PngHeaderCheck& check);
// The header alone (no pixel is decoded).
ImageHeader readPngHeader(const std::filesystem::path& file);

// Encodes width x height pixels of `channels` interleaved samples of `bits`
// (8: uint8_t, 16: uint16_t in memory) as a PNG, compressed at
// kPngZlibLevel with no row filter (image/image.h), with a tEXt chunk per
// key and value. Throws std::runtime_error naming `what`.
std::string encodePng(int width, int height, int channels, int bits, const void* samples,
                      const std::vector<std::pair<std::string, std::string>>& text, const std::string& what);

// The read-back of a PNG xval writes, from memory: `png` (just encoded)
// must decode whole as width x height (else std::runtime_error naming
// `what`). The file then gets exactly these bytes, each write checked
// (files/atomic_write.h), so it decodes as they do: as strong as decoding
// the file, without reading it.
PngPixels requirePngDecodable(const std::string& png, const std::string& what, int width, int height);

bool isPngSignature(const unsigned char* bytes, size_t size);

// The version of libpng xval reads and writes PNGs with.
const char* libpngVersion();

}  // namespace xval
