// OpenEXR files through OpenEXR's own library (no OpenImageIO: its 260
// shared libraries cost every xval process most of its start-up;
// docs/performance.md). Scanline files are written; scanline and tiled
// files (Blender writes tiled ones) are read, every channel as 32-bit float
// whatever its stored type (half is widened exactly).
#pragma once

#include <cstddef>
#include <filesystem>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "image/image_header.h"

namespace xval {

// One channel's values in memory: pixel (x, y) of the image (0-based, from
// the top left of the data window) at base[y * row_stride + x * pixel_stride]
// (strides in floats).
struct ExrChannel {
  std::string name;
  const float* base = nullptr;
  size_t pixel_stride = 1, row_stride = 0;
  bool half = false;  // stored as 16-bit half (rounded to nearest) instead of float
};

// Writes a scanline EXR of width x height with `channels` (OpenEXR keeps
// them sorted by name in the file), compressed with `compression` (one of
// "none", "rle", "zips", "zip", "piz", "pxr24", "b44", "b44a", "dwaa",
// "dwab"), and each string attribute. Throws std::runtime_error naming the
// file.
void writeExrFile(const std::filesystem::path& file, int width, int height, const std::vector<ExrChannel>& channels,
                  const char* compression, const std::vector<std::pair<std::string, std::string>>& attributes);

// One channel to read: pixel (x, y) of the data window goes to
// base[y * row_stride + x * pixel_stride] (floats).
struct ExrTarget {
  std::string name;
  float* base = nullptr;
  size_t pixel_stride = 1, row_stride = 0;
};

// An EXR file opened for reading: its header is read on construction.
class ExrInput {
 public:
  // Throws std::runtime_error naming the file if it is not an EXR OpenEXR
  // can open.
  explicit ExrInput(const std::filesystem::path& file);
  ~ExrInput();
  ExrInput(const ExrInput&) = delete;
  ExrInput& operator=(const ExrInput&) = delete;

  ImageHeader header() const;
  // The channels' names as the file lists them (sorted by name).
  const std::vector<std::string>& channels() const { return names_; }
  bool has(const std::string& name) const;
  // Reads every row of each target's channel (each must be in the file) as
  // float. Throws std::runtime_error naming the file if the pixels cannot
  // be read whole.
  void read(const std::vector<ExrTarget>& targets);

 private:
  struct File;
  std::filesystem::path file_;
  std::unique_ptr<File> in_;
  std::vector<std::string> names_;
};

// True when the file starts with OpenEXR's magic number.
bool isExrSignature(const unsigned char* bytes, size_t size);

// The version of OpenEXR xval reads and writes EXRs with.
const char* openexrVersion();

}  // namespace xval
