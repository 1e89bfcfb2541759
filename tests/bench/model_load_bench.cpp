// Model-file loading at scale: per file, the median over N runs of
//   load   loadModelFile (Assimp's read and post-processing, our checks,
//          node transforms, normals) and the rounding to float32
//   bvh f  building the float path's Accel (Embree triangles)
//   bvh d  building the double path's Accel (Embree user geometry)
// (load also as CPU time, user + system: the loader is single-threaded, so
// on a loaded machine this is what it costs) and the peak resident memory (ru_maxrss) after the load and at the end.
// Each run is a child process of its own (fork), so that every peak is that
// run's alone. A benchmark, not a test: it prints figures, asserts nothing.
//
//   scripts/make-scale-meshes.py /tmp/knots
//   build/tests/bench/xval_model_load_bench [--repeat N] /tmp/knots/*.ply /tmp/knots/*.glb
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "geometry/mesh.h"
#include "geometry/model_file.h"
#include "render/accel.h"

namespace {

struct Run {
  double load = 0, load_cpu = 0, bvh_float = 0, bvh_double = 0;
  long peak_load_kib = 0, peak_kib = 0;
  long long triangles = 0;
  char error[512] = {0};
};

double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
double cpuSeconds() {  // user + system time of this process, all threads
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) + 1e-6 * double(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
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

// One run in a child; its Run comes back through a pipe.
bool inChild(const char* file, Run& out) {
  int fd[2];
  if (pipe(fd) != 0) return false;
  const pid_t pid = fork();
  if (pid < 0) return false;
  if (pid == 0) {
    close(fd[0]);
    const Run r = measure(file);
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
  std::vector<const char*> files;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--repeat") == 0 && i + 1 < argc) repeat = std::max(1, std::atoi(argv[++i]));
    else files.push_back(argv[i]);
  }
  if (files.empty()) {
    std::fprintf(stderr, "usage: xval_model_load_bench [--repeat N] FILE...\n");
    return 64;
  }
  std::printf("%-24s %10s %5s %9s %9s %9s %9s %12s %12s\n", "file", "triangles", "runs", "load s", "load cpu",
              "bvh f s", "bvh d s", "peak load", "peak all");
  int status = 0;
  for (const char* f : files) {
    std::vector<double> load, cpu, bf, bd, pl, pa;
    Run r;
    for (int k = 0; k < repeat; ++k) {
      if (!inChild(f, r) || r.error[0]) {
        std::printf("%s: %s\n", f, r.error[0] ? r.error : "the measuring child failed");
        status = 1;
        break;
      }
      load.push_back(r.load), cpu.push_back(r.load_cpu), bf.push_back(r.bvh_float), bd.push_back(r.bvh_double);
      pl.push_back(r.peak_load_kib / 1024.0), pa.push_back(r.peak_kib / 1024.0);
    }
    if (load.size() != size_t(repeat)) continue;
    const char* base = std::strrchr(f, '/') ? std::strrchr(f, '/') + 1 : f;
    std::printf("%-24s %10lld %5d %9.3f %9.3f %9.3f %9.3f %8.0f MiB %8.0f MiB\n", base, r.triangles, repeat,
                median(load), median(cpu), median(bf), median(bd), median(pl), median(pa));
    std::fflush(stdout);
  }
  return status;
}
