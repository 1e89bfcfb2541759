// What an image file's header may claim before any of its pixels is read:
// every reader (textures, images read back from the external renderers and
// by `xval compare` and `xval validate`) checks the header's size against
// its limit first, so a 69-byte PNG that claims 100000 x 100000 pixels
// costs nothing.
#pragma once

#include <filesystem>
#include <string>

namespace xval {

struct ImageHeader {
  int width = 0, height = 0, depth = 1, channels = 0;
};

struct ImageLimits {
  int max_side;
  long long max_pixels;
  const char* unit;          // "pixels" or "texels", for messages
  int max_channels = 64;
  int expect_width = 0, expect_height = 0;  // when > 0: exactly this size
};

// Empty when the header is within the limits, else what is wrong, e.g.
// "is 8000x8000; expected 16x16" or "is 100000x100000; the limit is 16384
// on a side and 16777216 texels in all".
std::string imageHeaderProblem(const ImageHeader& h, const ImageLimits& l);

// Throws std::runtime_error naming the file unless it is a regular file
// (a FIFO would block the reader forever, a device read without end).
void requireRegularImageFile(const std::filesystem::path& file);

}  // namespace xval
