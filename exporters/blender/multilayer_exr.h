// Blender's multilayer EXR, read by channel name: a render's passes are
// named "<view layer>.<pass>.<component>" (e.g. "ViewLayer.DiffDir.R",
// "ViewLayer.Depth.Z"), and the view layer's name is Blender's, so a
// channel is found by the suffix "<pass>.<component>".
//
// One reader for every harness that reads passes (blender_render.cpp's
// DiffDir for blender-native, model_import.cpp's geometry passes), so the
// checks before any allocation are made once: a regular file (no symlink,
// no device), a header that claims the camera's size and a sane channel
// count (image/image_header.h), before the pixels are read.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace xval {

struct MultilayerChannels {
  int width = 0, height = 0;
  int nchannels = 0;          // the channels read: one per requested suffix
  std::vector<float> pixels;  // width x height x nchannels, float, as stored
  std::vector<int> index;     // per requested suffix: its channel in `pixels`

  // The k-th requested channel of pixel p (p = y * width + x).
  float at(size_t p, size_t k) const { return pixels[p * size_t(nchannels) + size_t(index[k])]; }
};

// Reads `file`, which must be width x height, and finds for each suffix
// the first channel whose name ends with it, in the file's order (OpenEXR
// lists channels sorted by name); only those channels are read. Throws ExternalToolError
// (exporters/common/export_common.h) naming the file for a file that is
// not a regular file, cannot be opened or read, has another size, or lacks
// a channel ("no channel *<suffix>").
MultilayerChannels readMultilayerChannels(const std::filesystem::path& file, int width, int height,
                                          const std::vector<std::string>& suffixes);

}  // namespace xval
