#include "image/image_header.h"

#include <stdexcept>

namespace xval {

std::string imageHeaderProblem(const ImageHeader& h, const ImageLimits& l) {
  const std::string size = std::to_string(h.width) + "x" + std::to_string(h.height);
  if (h.width <= 0 || h.height <= 0 || h.channels <= 0)
    return "has no pixels (" + size + ", " + std::to_string(h.channels) + " channels)";
  if (h.depth != 1) return "is a volume (depth " + std::to_string(h.depth) + "); expected a 2D image";
  if (l.expect_width > 0 && (h.width != l.expect_width || h.height != l.expect_height))
    return "is " + size + "; expected " + std::to_string(l.expect_width) + "x" + std::to_string(l.expect_height);
  if (h.width > l.max_side || h.height > l.max_side || (long long)h.width * h.height > l.max_pixels)
    return "is " + size + "; the limit is " + std::to_string(l.max_side) + " on a side and " +
           std::to_string(l.max_pixels) + " " + l.unit + " in all";
  if (h.channels > l.max_channels)
    return "has " + std::to_string(h.channels) + " channels; the limit is " + std::to_string(l.max_channels);
  return {};
}

void requireRegularImageFile(const std::filesystem::path& file) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec))
    throw std::runtime_error(file.string() + ": " +
                             (std::filesystem::exists(file, ec) ? "is not a regular file (a FIFO, device or folder)"
                                                                : "does not exist"));
}

}  // namespace xval
