// The sizes and values a scene may ask for: every limit the loader checks
// before anything is allocated, and the readers of images and textures
// check again (docs/scene-format.md). Plain constants, below
// every module that reads scene-given files.
#pragma once

#include <cstddef>

namespace xval {

// Largest accepted image side and pixel count (an "absurd resolution" is an
// error, not an attempt to allocate it).
inline constexpr int kMaxImageSide = 16384;
inline constexpr long long kMaxImagePixels = 64ll * 1024 * 1024;
inline constexpr int kMaxSpp = 256;
// The narrowest field of view: the float path's raster projects a scene
// of size 1 to 1 / tan(fov / 2) pixels, and its edge functions multiply two
// of those (1e-300 degrees: 1e302 px, whose products overflow).
inline constexpr double kMinFovDeg = 1e-6;
inline constexpr long long kMaxMeshVertices = 16ll * 1024 * 1024;
// A scene file larger than this is refused before it is read.
inline constexpr long long kMaxSceneFileBytes = 64ll * 1024 * 1024;
// Texture images: the header is checked against these when the scene is
// loaded (and again when the image is read), before any pixel is allocated.
inline constexpr int kMaxTextureSide = 16384;
inline constexpr long long kMaxTexturePixels = 16ll * 1024 * 1024;
// A texel value (code / (2^bits - 1) for integer images, as stored for
// floating-point ones) must be finite and at most this in magnitude
// (checked when the pixels are read; scene_file/precision_limits.h counts on it).
inline constexpr double kMaxTexelValue = 1e6;
// Scene names become folder names (`xval validate` writes DIR/NAME/): at
// most this many bytes, no '/', no NUL, not "." or "..".
inline constexpr size_t kMaxSceneNameBytes = 200;

}  // namespace xval
