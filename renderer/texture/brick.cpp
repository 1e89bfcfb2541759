#include "texture/brick.h"

#include <algorithm>
#include <cstdint>

namespace xval {

namespace {
// A 32-bit integer hash (finaliser of MurmurHash3's scheme), mapped to [0,1).
double hash01(uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352dU;
  x ^= x >> 15;
  x *= 0x846ca68bU;
  x ^= x >> 16;
  return (x >> 8) * (1.0 / 16777216.0);
}
}  // namespace

Texture makeBrickTexture() {
  constexpr int N = kBrickTextureSize, course = 64, brick = 128, mortar = 6;
  Texture t;
  t.width = t.height = N;
  t.rgb8.resize(size_t(N) * N * 3);
  for (int y = 0; y < N; ++y) {
    int row = y / course, yin = y % course;
    int shift = (row % 2) * (brick / 2);
    for (int x = 0; x < N; ++x) {
      int xs = (x + shift) % N;
      int col = xs / brick, xin = xs % brick;
      bool is_mortar = yin < mortar || xin < mortar;
      double grain = hash01(uint32_t(y * N + x) * 2654435761U + 17U) - 0.5;
      double r, g, b;
      if (is_mortar) {
        r = 0.74 + 0.06 * grain;
        g = 0.72 + 0.06 * grain;
        b = 0.68 + 0.06 * grain;
      } else {
        double tint = hash01(uint32_t(row * 131 + col * 7 + 3)) - 0.5;
        r = 0.66 + 0.16 * tint + 0.08 * grain;
        g = 0.30 + 0.08 * tint + 0.05 * grain;
        b = 0.20 + 0.05 * tint + 0.04 * grain;
      }
      unsigned char* p = &t.rgb8[(size_t(y) * N + x) * 3];
      p[0] = (unsigned char)std::clamp(int(r * 255.0 + 0.5), 0, 255);
      p[1] = (unsigned char)std::clamp(int(g * 255.0 + 0.5), 0, 255);
      p[2] = (unsigned char)std::clamp(int(b * 255.0 + 0.5), 0, 255);
    }
  }
  t.rgb.resize(t.rgb8.size());
  for (size_t i = 0; i < t.rgb8.size(); ++i) t.rgb[i] = float(t.rgb8[i]) / 255.0f;
  return t;
}

}  // namespace xval
