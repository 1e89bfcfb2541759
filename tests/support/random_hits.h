// Hits for exercising the SIMD shading kernel (shading/batch_shader.h)
// outside the renderer: random triangles of a mesh, each at a point drawn
// uniformly over the triangle (b1, b2 folded into b1 + b2 <= 1), from a
// fixed seed. Used by its unit tests and its benchmark.
#pragma once

#include <cstdint>
#include <random>
#include <vector>

namespace xval::test {

struct RandomHits {
  std::vector<std::uint32_t> tri;
  std::vector<float> b1, b2;
};

inline RandomHits randomHits(size_t triangle_count, size_t count, unsigned seed) {
  RandomHits h{std::vector<std::uint32_t>(count), std::vector<float>(count), std::vector<float>(count)};
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u01(0.0f, 1.0f);
  for (size_t k = 0; k < count; ++k) {
    h.tri[k] = std::uint32_t(rng() % triangle_count);
    float a = u01(rng), b = u01(rng);
    if (a + b > 1.0f) a = 1.0f - a, b = 1.0f - b;
    h.b1[k] = a, h.b2[k] = b;
  }
  return h;
}

}  // namespace xval::test
