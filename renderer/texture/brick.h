// The built-in procedural brick texture: 512x512, 8-bit sRGB-coded values
// (stored as is, never linearised), tileable under wrap addressing.
//
// Layout: 8 courses of 64 px, each brick 128 px long with 6 px of mortar;
// odd courses are offset by half a brick. Each brick has its own tint and
// every texel a small deterministic grain (an integer hash, no RNG state),
// so the image is the same on every machine.
#pragma once

#include "texture/texture.h"

namespace xval {

inline constexpr int kBrickTextureSize = 512;

Texture makeBrickTexture();

}  // namespace xval
