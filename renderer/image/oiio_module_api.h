// What the module xval_oiio (OpenImageIO's decoders, loaded on first use
// by image/other_formats.cpp) exports: one C function returning this table.
// The module is built with xval by the same CMake project and compiler, so
// the table passes C++ types; kOiioModuleAbi guards against a stale module
// from another build.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "image/other_formats.h"

namespace xval {

inline constexpr int kOiioModuleAbi = 1;
inline constexpr const char* kOiioModuleEntry = "xval_oiio_module";

struct OiioModuleApi {
  int abi;
  const char* (*version)();
  // As other_formats.h's functions; `what` names the image in errors
  // (std::runtime_error).
  ImageHeader (*header)(const std::filesystem::path& file);
  OtherFormatImage (*decode)(const std::filesystem::path& file, const std::vector<std::uint8_t>* embedded,
                             const std::string& what, const OtherFormatCheck& check);
};

}  // namespace xval

extern "C" const xval::OiioModuleApi* xval_oiio_module();
