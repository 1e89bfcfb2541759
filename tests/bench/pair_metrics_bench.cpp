// Google Benchmark for what measuring one pair costs at 720x720 (the
// paper's Table 2 size): image/compare.h's comparison, image/perceptual.h's
// metrics and LDR-FLIP (image/flip.h), on two noise images that differ
// everywhere (FLIP's cost does not depend on the content: fixed filters).
//
//   build/tests/bench/xval_pair_metrics_bench
//
// Measured when FLIP was added (Release, 2 cores shared with other builds;
// CPU time): compare 14 ms, perceptual 266 ms, FLIP 232 ms of which 116 ms
// per image (its planes) and 17 ms per pair from the planes. validate keeps
// each render's planes for all its pairs (image/metric_table.h
// MeasuredImage), so FLIP adds about 116 ms per render and 17 ms per pair.
#include <benchmark/benchmark.h>

#include <random>

#include "image/compare.h"
#include "image/flip.h"
#include "image/image.h"
#include "image/perceptual.h"

namespace {

using namespace xval;

Image noise(unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  Image img(720, 720, false);
  for (size_t i = 0; i < img.rgba.size(); i += 4)
    img.rgba[i] = u(rng), img.rgba[i + 1] = u(rng), img.rgba[i + 2] = u(rng), img.rgba[i + 3] = 1.0f;
  return img;
}

const Image& imageA() {
  static const Image a = noise(1);
  return a;
}
const Image& imageB() {
  static const Image b = noise(2);
  return b;
}

void BM_Compare(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(compareImages(imageA(), imageB(), Tolerance{}));
}
void BM_Perceptual(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(perceptualMetrics(imageA(), imageB()));
}
void BM_Flip(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(flipMetrics(imageA(), imageB()));
}
// FLIP's two parts: one image's planes (once per image in validate, which
// keeps them for all the image's pairs) and the map from two images' planes
// (once per pair).
void BM_FlipImage(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(flipImage(imageA()));
}
void BM_FlipPairFromPlanes(benchmark::State& state) {
  static const FlipImage fa = flipImage(imageA()), fb = flipImage(imageB());
  for (auto _ : state) benchmark::DoNotOptimize(flipSummary(flipErrorMap(fa, fb), imageA(), imageB()));
}
BENCHMARK(BM_Compare)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Perceptual)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Flip)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FlipImage)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FlipPairFromPlanes)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
