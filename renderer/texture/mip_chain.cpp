#include "texture/mip_chain.h"

namespace xval {

MipChain mipChain(const Texture& t) {
  MipChain c;
  c.levels.push_back(t);
  while (c.levels.back().width > 1 || c.levels.back().height > 1) {
    const Texture& s = c.levels.back();
    Texture n;
    n.width = std::max(1, s.width / 2);
    n.height = std::max(1, s.height / 2);
    n.rgb.resize(size_t(n.width) * n.height * 3);
    for (int j = 0; j < n.height; ++j)
      for (int i = 0; i < n.width; ++i) {
        const int x0 = 2 * i, x1 = std::min(2 * i + 1, s.width - 1);
        const int y0 = 2 * j, y1 = std::min(2 * j + 1, s.height - 1);
        const glm::dvec3 sum = glm::dvec3(s.texel(x0, y0)) + glm::dvec3(s.texel(x1, y0)) +
                               glm::dvec3(s.texel(x0, y1)) + glm::dvec3(s.texel(x1, y1));
        for (int q = 0; q < 3; ++q) n.rgb[(size_t(j) * n.width + i) * 3 + q] = float(sum[q] / 4.0);
      }
    c.levels.push_back(std::move(n));
  }
  return c;
}

}  // namespace xval
