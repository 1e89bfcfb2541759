// Frames of one prepared scene, without diagnostics, in a loop: what `xval
// bench` times as the reference frame, alone in its process, so that a
// profiler's samples are those of the frame (docs/performance.md "Where the
// time goes"). Prints the median wall and CPU time per frame (CPU over all
// threads) after one warm-up. A benchmark, not a test: it asserts nothing.
//
//   build/tests/bench/xval_frame_bench SCENE [--frames N] [--threads T] [--spp S] [--precision float|double]
//   perf record -F 4000 -g build/tests/bench/xval_frame_bench reference/scenes/table2_knot_yiq.json --frames 300 --threads 1
#include <time.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <string>
#include <vector>

#include "render/renderer.h"
#include "scene_file/scene_loader.h"

namespace {

double processCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

// A whole number >= 1 from argument `name`'s value; exits with the usage otherwise.
int positive(const char* name, const char* text) {
  char* end = nullptr;
  const long v = std::strtol(text, &end, 10);
  if (end == text || *end != '\0' || v < 1 || v > 100000) {
    std::fprintf(stderr, "xval_frame_bench: %s must be a whole number in 1..100000, not '%s'\n", name, text);
    std::exit(2);
  }
  return int(v);
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  using namespace xval;
  const char* usage =
      "usage: xval_frame_bench SCENE [--frames N] [--threads T] [--spp S] [--precision float|double]\n";
  if (argc < 2) {
    std::fputs(usage, stderr);
    return 2;
  }
  int frames = 20, threads = 0, spp = 0;
  Precision precision = Precision::Float;
  for (int i = 2; i < argc; i += 2) {
    if (i + 1 >= argc) {
      std::fprintf(stderr, "xval_frame_bench: %s needs a value\n%s", argv[i], usage);
      return 2;
    }
    const std::string opt = argv[i], value = argv[i + 1];
    if (opt == "--frames") frames = positive("--frames", argv[i + 1]);
    else if (opt == "--threads") threads = positive("--threads", argv[i + 1]);
    else if (opt == "--spp") spp = positive("--spp", argv[i + 1]);
    else if (opt == "--precision" && (value == "float" || value == "double"))
      precision = value == "float" ? Precision::Float : Precision::Double;
    else {
      std::fprintf(stderr, "xval_frame_bench: unknown option or value '%s %s'\n%s", argv[i], argv[i + 1], usage);
      return 2;
    }
  }
  try {
    const Scene scene = loadScene(argv[1]);
    RenderOptions o = defaultOptions(scene);
    o.precision = precision;
    o.threads = threads;
    o.diagnostics = false;
    if (spp) o.spp = spp;
    const PreparedScene prepared(scene, precision, o.cull_back_faces);
    Image img(scene.camera.width, scene.camera.height, false);
    std::vector<double> wall, cpu;
    for (int f = 0; f <= frames; ++f) {  // frame 0: the warm-up
      const auto t0 = std::chrono::steady_clock::now();
      const double c0 = processCpuSeconds();
      prepared.render(o, img);
      if (f == 0) continue;
      wall.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
      cpu.push_back(1e3 * (processCpuSeconds() - c0));
    }
    std::printf("%s: %d frames, %s, %d spp, %s threads: wall median %.3f ms (min %.3f), CPU median %.3f ms\n",
                argv[1], frames, precision == Precision::Float ? "float" : "double", o.spp,
                threads ? std::to_string(threads).c_str() : "all", median(wall),
                *std::min_element(wall.begin(), wall.end()), median(cpu));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "xval_frame_bench: %s: %s\n", argv[1], e.what());
    return 2;
  }
  return 0;
}
