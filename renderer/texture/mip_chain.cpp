#include "texture/mip_chain.h"

namespace xval {

namespace {

// Where texel i of a level n wide samples the level w wide above it
// (mip_chain.h): columns c0 and c1 with weights 1 - f and f.
struct Taps {
  int c0, c1;
  double f;
};

Taps taps(int i, int w, int n) {
  if (w == 1) return {0, 0, 0.5};  // x = 0: the one column, its weight in halves
  // x = (i + 1/2) w / n - 1/2 = ((2i + 1) w - n) / (2n): integer floor and an
  // exact remainder (for even w, f = 1/2 exactly).
  const long long num = (2LL * i + 1) * w - n, den = 2LL * n;
  const int c0 = int(num / den);
  return {c0, std::min(c0 + 1, w - 1), double(num % den) / double(den)};
}

}  // namespace

MipChain mipChain(const Texture& t) {
  MipChain c;
  c.levels.push_back(t);
  while (c.levels.back().width > 1 || c.levels.back().height > 1) {
    const Texture& s = c.levels.back();
    Texture n;
    n.width = std::max(1, s.width / 2);
    n.height = std::max(1, s.height / 2);
    n.rgb.resize(size_t(n.width) * n.height * 3);
    for (int j = 0; j < n.height; ++j) {
      const Taps ty = taps(j, s.height, n.height);
      for (int i = 0; i < n.width; ++i) {
        const Taps tx = taps(i, s.width, n.width);
        // Summed in this order so that where every weight is 1/4 the result
        // is the 2x2 box's ((a + b) + c + d) / 4, bit for bit.
        const glm::dvec3 sum = (1.0 - tx.f) * (1.0 - ty.f) * glm::dvec3(s.texel(tx.c0, ty.c0)) +
                               tx.f * (1.0 - ty.f) * glm::dvec3(s.texel(tx.c1, ty.c0)) +
                               (1.0 - tx.f) * ty.f * glm::dvec3(s.texel(tx.c0, ty.c1)) +
                               tx.f * ty.f * glm::dvec3(s.texel(tx.c1, ty.c1));
        for (int q = 0; q < 3; ++q) n.rgb[(size_t(j) * n.width + i) * 3 + q] = float(sum[q]);
      }
    }
    c.levels.push_back(std::move(n));
  }
  return c;
}

}  // namespace xval
