// Model-file loading at scale: per file, the median over N runs of
//   load   loadModelFile (Assimp's read and post-processing, our checks,
//          node transforms, normals) and the rounding to float32
//   bvh f  building the float path's Accel (Embree triangles)
//   bvh d  building the double path's Accel (Embree user geometry)
// (load also as CPU time, user + system: the loader is single-threaded, so
// on a loaded machine this is what it costs; it includes the child process
// Assimp reads in) and the peak resident memory (ru_maxrss): of that child
// ("peak import"), of the run after the load and at the end.
// With --frame instead, the scene path of `xval render`: the file as the one
// mesh object of a 720 x 720 scene (camera on +z, 4.5 from the origin; the
// knot of scripts/make-scale-meshes.py lies within 1.52 of it; Phong
// shading, untextured, one point light) read by loadScene ("scene s": the
// model file's load included), then per path (f = float, the fast path;
// d = double, the reference) PreparedScene ("setup": tessellation, BVH) and
// the median of 3 frames (the float frame also as CPU time, all threads:
// on two idle cores its wall time is about half of it), and the peak
// resident memory at the end.
// Each run is a child process of its own (fork), so that every peak is that
// run's alone. A benchmark, not a test: it prints figures, asserts nothing.
//
//   scripts/make-scale-meshes.py /tmp/knots
//   build/tests/bench/xval_model_load_bench [--repeat N] [--frame] /tmp/knots/*.ply /tmp/knots/*.glb
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <vector>

#include <nlohmann/json.hpp>

#include "geometry/mesh.h"
#include "geometry/model_file.h"
#include "render/accel.h"
#include "render/renderer.h"
#include "scene_file/scene_loader.h"

namespace {

struct Run {
  double load = 0, load_cpu = 0, bvh_float = 0, bvh_double = 0;
  long peak_load_kib = 0, peak_kib = 0, peak_import_kib = 0;
  long long triangles = 0;
  double setup_float = 0, frame_float = 0, setup_double = 0, frame_double = 0;  // --frame
  double frame_float_cpu = 0;  // --frame: CPU time (all threads) of the median-wall float frame
  long peak_frame_kib = 0;
  char error[512] = {0};
};

double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
double cpuSeconds(int who) {
  rusage u{};
  getrusage(who, &u);
  return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) + 1e-6 * double(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}
// User + system time of this process (all threads) and of its reaped
// children (the loader's Assimp child).
double cpuSeconds() { return cpuSeconds(RUSAGE_SELF) + cpuSeconds(RUSAGE_CHILDREN); }
long childMaxrssKiB() {  // the largest reaped child's peak
  rusage u{};
  getrusage(RUSAGE_CHILDREN, &u);
  return u.ru_maxrss;
}
long maxrssKiB() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss;
}

Run measure(const char* file) {
  Run r;
  try {
    double t0 = now();
    const double c0 = cpuSeconds();
    xval::Model m = xval::loadModelFile(file);
    std::vector<xval::TriangleMesh> meshes;
    for (auto& p : m.primitives) {
      xval::roundToFloat(p.mesh);
      meshes.push_back(std::move(p.mesh));
    }
    r.load = now() - t0;
    r.load_cpu = cpuSeconds() - c0;
    r.peak_load_kib = maxrssKiB();
    r.peak_import_kib = childMaxrssKiB();
    for (const auto& t : meshes) r.triangles += (long long)t.triangleCount();
    t0 = now();
    { xval::Accel a(meshes, xval::Precision::Float); }
    r.bvh_float = now() - t0;
    t0 = now();
    { xval::Accel a(meshes, xval::Precision::Double); }
    r.bvh_double = now() - t0;
  } catch (const std::exception& e) {
    std::snprintf(r.error, sizeof r.error, "%s", e.what());
  }
  r.peak_kib = maxrssKiB();
  return r;
}

double median(std::vector<double> v);

// The scene-path measurement of --frame (see the top of the file).
Run measureFrame(const char* file) {
  Run r;
  try {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                      ("xval_scale_bench_" + std::to_string(getpid()));
    std::filesystem::create_directories(dir);
    const std::filesystem::path scene_file = dir / "scene.json";
    {
      std::ofstream o(scene_file);
      o << R"({"format": "xval-scene/1", "name": "scale",
        "camera": {"position": [0, 0, 4.5], "target": [0, 0, 0], "fov_y_deg": 45, "width": 720, "height": 720},
        "objects": [{"shape": "mesh", "path": )"
        << nlohmann::json(std::filesystem::absolute(file).string()).dump() << R"(}],
        "material": {"model": {"type": "classic_phong", "variant": "paper", "shininess": 40}},
        "lights": [{"type": "point", "position": [2, 3, 4]}], "shading": "phong"})";
      if (!o) throw std::runtime_error(scene_file.string() + ": cannot write");
    }
    double t0 = now();
    const xval::Scene scene = xval::loadScene(scene_file);
    r.load = now() - t0;
    std::filesystem::remove_all(dir);
    for (const xval::Precision prec : {xval::Precision::Float, xval::Precision::Double}) {
      t0 = now();
      const xval::PreparedScene prepared(scene, prec);
      const double setup = now() - t0;
      xval::RenderOptions opt = xval::defaultOptions(scene);
      opt.precision = prec;
      xval::Image img(720, 720, false);
      std::vector<double> frames, cpus;
      for (int k = 0; k < 3; ++k) {
        t0 = now();
        const double c0 = cpuSeconds();
        prepared.render(opt, img);
        frames.push_back(now() - t0);
        cpus.push_back(cpuSeconds() - c0);
      }
      if (prec == xval::Precision::Float) r.frame_float_cpu = median(cpus);
      r.triangles = (long long)prepared.triangleCount();
      (prec == xval::Precision::Float ? r.setup_float : r.setup_double) = setup;
      (prec == xval::Precision::Float ? r.frame_float : r.frame_double) = median(frames);
    }
  } catch (const std::exception& e) {
    std::snprintf(r.error, sizeof r.error, "%s", e.what());
  }
  r.peak_frame_kib = maxrssKiB();
  return r;
}

// One run in a child; its Run comes back through a pipe.
bool inChild(const char* file, Run& out, bool frame) {
  int fd[2];
  if (pipe(fd) != 0) return false;
  std::fflush(nullptr);  // the child must not write this process's buffered output again
  const pid_t pid = fork();
  if (pid < 0) return false;
  if (pid == 0) {
    close(fd[0]);
    const Run r = frame ? measureFrame(file) : measure(file);
    const bool ok = write(fd[1], &r, sizeof r) == (ssize_t)sizeof r;
    _exit(ok ? 0 : 1);
  }
  close(fd[1]);
  const bool got = read(fd[0], &out, sizeof out) == (ssize_t)sizeof out;
  close(fd[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  return got && WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace

int main(int argc, char** argv) {
  int repeat = 5;
  bool frame = false;
  std::vector<const char*> files;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--repeat") == 0 && i + 1 < argc) repeat = std::max(1, std::atoi(argv[++i]));
    else if (std::strcmp(argv[i], "--frame") == 0) frame = true;
    else files.push_back(argv[i]);
  }
  if (files.empty()) {
    std::fprintf(stderr, "usage: xval_model_load_bench [--repeat N] [--frame] FILE...\n");
    return 64;
  }
  if (frame)
    std::printf("%-24s %10s %5s %9s %9s %9s %9s %9s %9s %12s\n", "file", "triangles", "runs", "scene s", "setup f",
                "frame f", "f cpu", "setup d", "frame d", "peak");
  else
    std::printf("%-24s %10s %5s %9s %9s %9s %9s %12s %12s %12s\n", "file", "triangles", "runs", "load s", "load cpu",
                "bvh f s", "bvh d s", "peak import", "peak load", "peak all");
  int status = 0;
  for (const char* f : files) {
    std::vector<double> load, cpu, bf, bd, pi, pl, pa, sf, ff, fc, sd, fd, pk;
    Run r;
    for (int k = 0; k < repeat; ++k) {
      if (!inChild(f, r, frame) || r.error[0]) {
        std::printf("%s: %s\n", f, r.error[0] ? r.error : "the measuring child failed");
        status = 1;
        break;
      }
      load.push_back(r.load), cpu.push_back(r.load_cpu), bf.push_back(r.bvh_float), bd.push_back(r.bvh_double);
      pi.push_back(r.peak_import_kib / 1024.0), pl.push_back(r.peak_load_kib / 1024.0), pa.push_back(r.peak_kib / 1024.0);
      sf.push_back(r.setup_float), ff.push_back(r.frame_float), sd.push_back(r.setup_double);
      fd.push_back(r.frame_double), pk.push_back(r.peak_frame_kib / 1024.0), fc.push_back(r.frame_float_cpu);
    }
    if (load.size() != size_t(repeat)) continue;
    const char* base = std::strrchr(f, '/') ? std::strrchr(f, '/') + 1 : f;
    if (frame)
      std::printf("%-24s %10lld %5d %9.3f %9.3f %9.4f %9.4f %9.3f %9.4f %8.0f MiB\n", base, r.triangles, repeat,
                  median(load), median(sf), median(ff), median(fc), median(sd), median(fd), median(pk));
    else
      std::printf("%-24s %10lld %5d %9.3f %9.3f %9.3f %9.3f %8.0f MiB %8.0f MiB %8.0f MiB\n", base, r.triangles,
                  repeat, median(load), median(cpu), median(bf), median(bd), median(pi), median(pl), median(pa));
    std::fflush(stdout);
  }
  return status;
}
