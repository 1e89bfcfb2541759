// libFuzzer target: the model-file loader (geometry/model_file.h) on
// arbitrary bytes, written as a file whose extension follows its content:
// "OFF" -> .off, "ply" -> .ply, "glTF" -> .glb, "{" -> .gltf, "solid" or a
// NUL byte in the first 84 (a binary STL header) -> .stl, else .obj.
//
// Findings: crashes, sanitizer reports, time-outs, any exception other than
// ModelFileError, and a loaded model that breaks the mesh form: arrays of
// one length, indices in range, finite attributes, unit normals.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "fuzz_common.h"
#include "geometry/model_file.h"

namespace {
const char* extensionFor(const uint8_t* d, size_t n) {
  auto starts = [&](const char* s) { return n >= std::strlen(s) && std::memcmp(d, s, std::strlen(s)) == 0; };
  if (starts("OFF")) return ".off";
  if (starts("ply")) return ".ply";
  if (starts("glTF")) return ".glb";
  if (starts("{")) return ".gltf";
  if (starts("solid") || std::memchr(d, 0, n < 84 ? n : 84)) return ".stl";
  return ".obj";
}

[[noreturn]] void fail(const std::string& why) {
  std::fprintf(stderr, "fuzz_model: %s\n", why.c_str());
  std::abort();
}

bool finite(glm::dvec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::filesystem::path file = xval::fuzz::scratchDir() / (std::string("fuzz") + extensionFor(data, size));
  xval::fuzz::writeFile(file, data, size);
  xval::ModelLoadOptions o;
  o.limits.max_file_bytes = 1 << 20;
  o.limits.max_total_bytes = 4 << 20;
  o.limits.max_triangles = 1 << 16;
  o.limits.max_vertices = 1 << 16;
  o.limits.max_import_seconds = 20;  // under libFuzzer's -timeout=25 of smoke.cmake
  o.uvs = xval::UvRequirement::ModelTextures;
  xval::Model m;
  try {
    m = xval::loadModelFile(file, o);
  } catch (const xval::ModelFileError&) {
    std::filesystem::remove(file);
    return 0;
  }
  std::filesystem::remove(file);
  if (m.primitives.empty()) fail("loaded with no primitives");
  if (m.triangleCount() > o.limits.max_triangles) fail("more triangles than the limit");
  for (const auto& p : m.primitives) {
    const auto& t = p.mesh;
    const size_t n = t.positions.size();
    if (t.normals.size() != n || t.uvs.size() != n) fail(p.label + ": attribute arrays differ in length");
    if (t.triangles.empty()) fail(p.label + ": no triangles");
    for (const auto& tri : t.triangles)
      if (tri.x >= n || tri.y >= n || tri.z >= n) fail(p.label + ": index out of range");
    for (size_t v = 0; v < n; ++v) {
      if (!finite(t.positions[v]) || !finite(t.normals[v])) fail(p.label + ": non-finite vertex");
      if (std::abs(glm::length(t.normals[v]) - 1.0) > 1e-9) fail(p.label + ": normal not unit length");
      if (!std::isfinite(t.uvs[v].x) || !std::isfinite(t.uvs[v].y)) fail(p.label + ": non-finite uv");
    }
  }
  return 0;
}
