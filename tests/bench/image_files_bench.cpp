// Google Benchmark for the files a validate run writes and reads per case
// (docs/performance.md, "What xval's own files cost"): the Table 2 knot
// (reference/scenes/table2_knot_phong.json, 720x720) rendered once with
// every diagnostic channel (the reference renderer's EXR: 17 float
// channels), its difference from the float path's render (a difference
// EXR: 4 float channels, small values, as between two renderers), and that
// difference's heat map (8-bit RGB). Each is written with the settings
// named in the benchmark: the process's CPU time per write (with the
// read-back every xval write makes; OpenEXR compresses on threads of its
// own, so the process's, not the thread's), the file size as a counter;
// and the render's EXR read.
//
//   build/tests/bench/xval_image_files_bench [--benchmark_repetitions=3]
//
// Run from the repository's root (it reads the scene by that path).
#include <benchmark/benchmark.h>

#include <OpenImageIO/imageio.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

#include "image/compare.h"
#include "image/heat_map.h"
#include "image/image.h"
#include "render/renderer.h"
#include "scene_file/scene_loader.h"

namespace {

using namespace xval;
namespace fs = std::filesystem;
namespace OIIO = OIIO_NAMESPACE;

struct Inputs {
  Image render, diff, heat;
  fs::path dir;
  Inputs() {
    // Its tolerances name renderers, which this program (no registry)
    // cannot check: they are left out; they do not change the render.
    const std::string file = "reference/scenes/table2_knot_phong.json";
    nlohmann::ordered_json j = nlohmann::ordered_json::parse(readJsonFile(file, "scene file"));
    j.erase("tolerances");
    const Scene s = parseScene(j.dump(), file);
    RenderOptions o = defaultOptions(s);
    o.precision = Precision::Double;
    render = renderScene(s, o);
    o.precision = Precision::Float;
    diff = differenceImage(render, renderScene(s, o));
    heat = heatMap(diff);
    dir = fs::temp_directory_path() / ("xval_image_files_bench_" + std::to_string(::getpid()));
    fs::create_directories(dir);
  }
  ~Inputs() { fs::remove_all(dir); }
};
Inputs& inputs() {
  static Inputs in;
  return in;
}

void exrWrite(benchmark::State& state, const Image& img, const char* codec, const char* name) {
  const fs::path f = inputs().dir / name;
  for (auto _ : state) writeImage(img, f, codec);
  state.counters["bytes"] = double(fs::file_size(f));
}
void exrRead(benchmark::State& state, const Image& img, const char* codec, const char* name) {
  const fs::path f = inputs().dir / name;
  writeImage(img, f, codec);
  for (auto _ : state) benchmark::DoNotOptimize(readImage(f));
}

// The heat map as an 8-bit RGB PNG at a zlib level and row filter (0: libpng's
// default, every filter tried on each row), read back as xval does.
void pngWrite(benchmark::State& state, int level, int filter) {
  const Image& h = inputs().heat;
  std::vector<unsigned char> px(size_t(h.width) * h.height * 3);
  for (size_t i = 0; i < px.size() / 3; ++i)
    for (int c = 0; c < 3; ++c) px[i * 3 + c] = (unsigned char)(h.rgba[i * 4 + c] * 255.0f + 0.5f);
  const fs::path f = inputs().dir / "heat.png";
  for (auto _ : state) {
    auto out = OIIO::ImageOutput::create(f.string());
    OIIO::ImageSpec spec(h.width, h.height, 3, OIIO::TypeDesc::UINT8);
    spec.attribute("png:compressionLevel", level);
    if (filter) spec.attribute("png:filter", filter);
    out->open(f.string(), spec);
    out->write_image(OIIO::TypeDesc::UINT8, px.data());
    out->close();
    requireDecodable(f, h.width, h.height);
  }
  state.counters["bytes"] = double(fs::file_size(f));
}

void BM_RenderExrWrite_zip6(benchmark::State& s) { exrWrite(s, inputs().render, "zip", "r.exr"); }
void BM_RenderExrWrite_zip1(benchmark::State& s) { exrWrite(s, inputs().render, "zip:1", "r.exr"); }
void BM_RenderExrWrite_none(benchmark::State& s) { exrWrite(s, inputs().render, "none", "r.exr"); }
void BM_RenderExrWrite_rle(benchmark::State& s) { exrWrite(s, inputs().render, kRenderExrCompression, "r.exr"); }
void BM_RenderExrWrite_piz(benchmark::State& s) { exrWrite(s, inputs().render, "piz", "r.exr"); }
void BM_RenderExrRead_none(benchmark::State& s) { exrRead(s, inputs().render, "none", "r.exr"); }
void BM_RenderExrRead_zip6(benchmark::State& s) { exrRead(s, inputs().render, "zip", "r.exr"); }
void BM_RenderExrRead_zip1(benchmark::State& s) { exrRead(s, inputs().render, "zip:1", "r.exr"); }
void BM_RenderExrRead_rle(benchmark::State& s) { exrRead(s, inputs().render, kRenderExrCompression, "r.exr"); }
void BM_DiffExrWrite_zip6(benchmark::State& s) { exrWrite(s, inputs().diff, "zip", "d.exr"); }
void BM_DiffExrWrite_piz(benchmark::State& s) { exrWrite(s, inputs().diff, kDifferenceExrCompression, "d.exr"); }
void BM_HeatPngWrite_level6_allFilters(benchmark::State& s) { pngWrite(s, 6, 0); }
void BM_HeatPngWrite_level1_allFilters(benchmark::State& s) { pngWrite(s, 1, 0); }
void BM_HeatPngWrite_level1_noFilter(benchmark::State& s) { pngWrite(s, kPngZlibLevel, kPngFilter); }

}  // namespace

BENCHMARK(BM_RenderExrWrite_zip6)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime();
BENCHMARK(BM_RenderExrWrite_zip1)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime();
BENCHMARK(BM_RenderExrWrite_none)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime();
BENCHMARK(BM_RenderExrWrite_rle)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime();
BENCHMARK(BM_RenderExrWrite_piz)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime();
BENCHMARK(BM_RenderExrRead_none)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime();
BENCHMARK(BM_RenderExrRead_zip6)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime();
BENCHMARK(BM_RenderExrRead_zip1)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime();
BENCHMARK(BM_RenderExrRead_rle)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime();
BENCHMARK(BM_DiffExrWrite_zip6)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime();
BENCHMARK(BM_DiffExrWrite_piz)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime();
BENCHMARK(BM_HeatPngWrite_level6_allFilters)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime();
BENCHMARK(BM_HeatPngWrite_level1_allFilters)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime();
BENCHMARK(BM_HeatPngWrite_level1_noFilter)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime();
BENCHMARK_MAIN();
