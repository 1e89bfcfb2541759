// Images in the formats xval does not decode itself (JPEG, TIFF, HDR, TGA,
// BMP, ...: every format but EXR and PNG, which image/exr_file.h and
// image/png_file.h read): decoded by OpenImageIO inside the module
// xval_oiio (renderer/oiio_module/), loaded on the first such file only.
// OpenImageIO pulls in some 260 shared libraries (OpenCV, FFmpeg, DCMTK,
// OpenVDB, ...), most of a process's start-up when linked
// (docs/performance.md); a run that reads only EXRs and PNGs never loads
// it. Errors name the file, its format (when known) and the module's path.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "image/image_header.h"

namespace xval {

struct OtherFormatImage {
  int width = 0, height = 0, channels = 0;
  std::vector<std::string> names;  // the channels' names (R, G, B, A, Y, ...)
  std::string format;              // OpenImageIO's name of the format ("jpeg", "tiff", ...)
  // 8: stored 8-bit codes in u8; 16: 16-bit codes in u16; 32: any other
  // type, converted to float by OpenImageIO, in f32. Interleaved.
  int bits = 8;
  std::vector<std::uint8_t> u8;
  std::vector<std::uint16_t> u16;
  std::vector<float> f32;
  bool unassociated = false;  // the colour is not multiplied by alpha (read as stored)
};

// Called with the header before any pixel is allocated: throws to refuse.
using OtherFormatCheck = std::function<void(const ImageHeader&)>;

// Decodes subimage 0 of `file`, every channel, as stored (alpha never
// multiplied in), or of `embedded` (encoded bytes; `file` names them in
// messages and OpenImageIO picks the reader from its extension).
OtherFormatImage decodeOtherFormat(const std::filesystem::path& file, const std::vector<std::uint8_t>* embedded,
                                   const OtherFormatCheck& check);
// The header alone.
ImageHeader otherFormatHeader(const std::filesystem::path& file);

// The module's file: xval_oiio.so in the folder of the running executable
// (/proc/self/exe), never a path from the environment or an input.
std::filesystem::path oiioModulePath();
// Tests: the next image that needs the module loads it from `path` (empty:
// the default path again), as if it had not been loaded.
void setOiioModulePathForTesting(const std::filesystem::path& path);
// OpenImageIO's version when the module is loaded, else empty (xval does
// not load it to say so).
std::string loadedOpenImageIoVersion();

}  // namespace xval
