// Assimp's read of a model file (geometry/assimp_read.h).
#include "geometry/assimp_read.h"

#include <assimp/BaseImporter.h>
#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <charconv>
#include <cstring>
#include <memory>
#include <set>

#include "geometry/assimp_dump.h"
#include "geometry/model_references.h"

// Debian's Assimp 5.2.5 is built with its internal assertions on, and a
// failed one calls this hook, whose library definition prints and calls
// abort(): a malformed file (a PLY face with 0 indices fails an assertion
// of aiProcess_Triangulate) would end the program. The library exports the
// hook and calls it through the dynamic symbol table, so this definition in
// the program takes precedence: it throws instead, and Importer::ReadFile
// (which catches std::exception around reading and post-processing) turns
// that into a failed read with this message. tests/unit/model_file_test.cpp
// (ModelFile.AssimpAssertionIsAnError) aborts without it.
namespace Assimp {
void aiAssertViolation(const char* expression, const char* file, int line) {
  throw std::runtime_error(std::string("Assimp internal check failed: ") + expression + " (" + file + ":" +
                           std::to_string(line) + ")");
}
}  // namespace Assimp

namespace xval {

namespace fs = std::filesystem;

const std::vector<std::string>& modelFileExtensions() {
  static const std::vector<std::string> e{".obj", ".ply", ".stl", ".off", ".gltf", ".glb"};
  return e;
}

Assimp::IOStream* GuardedIO::Open(const char* file, const char* mode) {
  if (std::strchr(mode, 'w') || std::strchr(mode, 'a') || std::strchr(mode, '+')) {
    refusals_.push_back(std::string(file) + ": opened for writing (refused)");
    return nullptr;
  }
  std::string why;
  auto path = allowed(file, &why);
  if (!path) {
    refusals_.push_back(why);
    return nullptr;
  }
  std::error_code ec;
  const auto size = (long long)fs::file_size(*path, ec);
  if (ec) {
    refusals_.push_back(std::string(file) + ": " + ec.message());
    return nullptr;
  }
  if (size > limits_.max_file_bytes) {
    refusals_.push_back(std::string(file) + ": " + std::to_string(size) + " bytes; the limit is " +
                        std::to_string(limits_.max_file_bytes));
    return nullptr;
  }
  if (total_ + size > limits_.max_total_bytes) {
    refusals_.push_back(std::string(file) + ": the files read for this model exceed " +
                        std::to_string(limits_.max_total_bytes) + " bytes in all");
    return nullptr;
  }
  total_ += size;
  if (std::find(opened_.begin(), opened_.end(), *path) == opened_.end()) opened_.push_back(*path);
  return DefaultIOSystem::Open(path->c_str(), "rb");
}

std::optional<fs::path> GuardedIO::allowed(const std::string& name, std::string* why) const {
  const ResolvedName r = resolveInsideFolder(folder_, name);
  if (r.kind == NameResolution::RegularFile) return r.real;
  if (why) *why = r.why;
  return std::nullopt;
}


namespace {

// The Importer with only the readers of modelFileExtensions() (glTF 2.0's,
// not glTF 1.0's): a file is never handed to another format's reader, even
// by Assimp's content sniffing. The unregistered readers are ours to delete.
struct RestrictedImporter {
  Assimp::Importer importer;
  std::vector<std::unique_ptr<Assimp::BaseImporter>> removed;
  RestrictedImporter() {
    std::vector<Assimp::BaseImporter*> others;
    for (size_t i = 0; i < importer.GetImporterCount(); ++i) {
      Assimp::BaseImporter* r = importer.GetImporter(i);
      std::set<std::string> exts;
      r->GetExtensionList(exts);
      const std::string name = r->GetInfo()->mName ? r->GetInfo()->mName : "";
      bool keep = name.find("glTF Importer") == std::string::npos;  // glTF 1.0
      bool ours = false;
      for (const auto& e : modelFileExtensions()) ours = ours || exts.count(e.substr(1));
      if (!(keep && ours)) others.push_back(r);
    }
    for (auto* r : others)
      if (importer.UnregisterLoader(r) == aiReturn_SUCCESS) removed.emplace_back(r);
  }
};

}  // namespace

void putField(std::string& out, const std::string& bytes) {
  const uint64_t n = bytes.size();
  for (int k = 0; k < 8; ++k) out.push_back(char((n >> (8 * k)) & 0xff));
  out += bytes;
}

std::string readWithAssimp(const fs::path& real, const ModelLimits& lim) {
  const std::string file = real.string();
  RestrictedImporter ri;
  Assimp::Importer& imp = ri.importer;
  auto io_owner = std::make_unique<GuardedIO>(real.parent_path(), lim);
  GuardedIO* io = io_owner.get();
  imp.SetIOHandler(io_owner.release());  // the Importer owns it now
  imp.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
  const aiScene* scene = nullptr;
  std::string error;
  try {
    scene = imp.ReadFile(file, aiProcess_ValidateDataStructure | aiProcess_Triangulate | aiProcess_SortByPType);
  } catch (const std::exception& e) {  // should ReadFile let one through
    error = e.what();
  }
  if (!scene && error.empty()) error = imp.GetErrorString();
  if (!scene && error.empty()) error = "Assimp read no scene and gave no reason";
  const std::string dump = scene ? writeAssimpDump(*scene) : std::string();
  std::string out;
  putField(out, error);
  putField(out, std::to_string(io->refusals().size()));
  for (const auto& r : io->refusals()) putField(out, r);
  putField(out, std::to_string(io->opened().size()));
  for (const auto& o : io->opened()) putField(out, o.string());
  putField(out, dump);
  return out;
}

// The reader uses three of the limits: GuardedIO's two and its memory cap.
std::vector<std::string> modelReaderArguments(const fs::path& reader, const fs::path& real, const ModelLimits& lim) {
  return {reader.string(), real.string(), std::to_string(lim.max_file_bytes), std::to_string(lim.max_total_bytes),
          std::to_string(lim.max_import_memory_bytes)};
}

std::string parseModelReaderArguments(const std::vector<std::string>& args, fs::path& real, ModelLimits& lim) {
  if (args.size() != 5)
    return "usage: " + std::string(kModelReader) + " FILE MAX_FILE_BYTES MAX_TOTAL_BYTES MAX_MEMORY_BYTES (" +
           std::to_string(args.size()) + " arguments given)";
  const char* names[] = {"MAX_FILE_BYTES", "MAX_TOTAL_BYTES", "MAX_MEMORY_BYTES"};
  long long* fields[] = {&lim.max_file_bytes, &lim.max_total_bytes, &lim.max_import_memory_bytes};
  for (int k = 0; k < 3; ++k) {
    const std::string& a = args[size_t(k) + 2];
    long long v = 0;
    const auto [end, ec] = std::from_chars(a.data(), a.data() + a.size(), v);
    if (ec != std::errc() || end != a.data() + a.size() || v < 0)
      return std::string(names[k]) + " '" + a + "': expected a whole number >= 0";
    *fields[k] = v;
  }
  real = args[1];
  if (!real.is_absolute()) return "FILE '" + args[1] + "': expected an absolute path";
  return "";
}

bool modelReaderCapsMemory() {
#if defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(undefined_behavior_sanitizer)
  return false;
#endif
#endif
#if defined(__SANITIZE_ADDRESS__)
  return false;
#endif
  return true;
}

}  // namespace xval
