#include "image/other_formats.h"

#include <dlfcn.h>
#include <unistd.h>

#include <cstdio>
#include <mutex>
#include <stdexcept>

#include "image/oiio_module_api.h"

namespace xval {

namespace {

struct ModuleState {
  std::mutex lock;
  std::filesystem::path test_path;      // setOiioModulePathForTesting
  const OiioModuleApi* api = nullptr;   // once loaded
};
ModuleState& moduleState() {
  static ModuleState s;
  return s;
}

// What a file is, for the message when the module cannot decode it: its
// extension and first bytes (xval cannot name the format without the
// module).
std::string describeFile(const std::filesystem::path& file, const std::vector<std::uint8_t>* embedded) {
  unsigned char b[4] = {};
  size_t got = 0;
  if (embedded) {
    for (; got < 4 && got < embedded->size(); ++got) b[got] = (*embedded)[got];
  } else if (std::FILE* f = std::fopen(file.c_str(), "rb")) {
    got = std::fread(b, 1, 4, f);
    std::fclose(f);
  }
  std::string bytes;
  for (size_t i = 0; i < got; ++i) {
    char hex[4];
    std::snprintf(hex, sizeof hex, "%02X", b[i]);
    bytes += (i ? " " : "") + std::string(hex);
  }
  return std::string(embedded ? "an embedded image" : "an image") + " neither EXR nor PNG (extension \"" +
         file.extension().string() + "\", first bytes " + (bytes.empty() ? "none" : bytes) + ")";
}

// Loads the module on first use; throws std::runtime_error naming `file`,
// what it is and the module's path if it cannot be loaded. No fallback: an
// image that needs the module and cannot have it is an error.
const OiioModuleApi& module(const std::filesystem::path& file, const std::vector<std::uint8_t>* embedded) {
  ModuleState& s = moduleState();
  std::lock_guard<std::mutex> hold(s.lock);
  if (s.api) return *s.api;
  const std::filesystem::path path = oiioModulePath();
  auto fail = [&](const std::string& why) -> std::runtime_error {
    return std::runtime_error(file.string() + ": " + describeFile(file, embedded) +
                              " is decoded by OpenImageIO in the module " + path.string() +
                              ", which cannot be loaded: " + why);
  };
  // RTLD_LOCAL: OpenImageIO's symbols stay the module's.
  void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) {
    const char* e = dlerror();
    throw fail(e ? e : "dlopen failed");
  }
  auto entry = reinterpret_cast<const OiioModuleApi* (*)()>(dlsym(handle, kOiioModuleEntry));
  const OiioModuleApi* api = entry ? entry() : nullptr;
  if (!api) {
    dlclose(handle);
    throw fail(std::string("it has no ") + kOiioModuleEntry + " entry point");
  }
  if (api->abi != kOiioModuleAbi) {
    dlclose(handle);
    throw fail("its interface is version " + std::to_string(api->abi) + ", expected " +
               std::to_string(kOiioModuleAbi) + " (a module from another build)");
  }
  s.api = api;  // kept loaded for the process's life
  return *api;
}

}  // namespace

std::filesystem::path oiioModulePath() {
  {
    ModuleState& s = moduleState();
    // Called under the lock by module(); test_path only changes before the
    // module is loaded.
    if (!s.test_path.empty()) return s.test_path;
  }
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec) throw std::runtime_error("cannot find the running executable (/proc/self/exe): " + ec.message());
  return exe.parent_path() / "xval_oiio.so";
}

void setOiioModulePathForTesting(const std::filesystem::path& path) {
  ModuleState& s = moduleState();
  std::lock_guard<std::mutex> hold(s.lock);
  s.test_path = path;
  s.api = nullptr;  // the next use loads from `path` (dlopen of a loaded file is cheap)
}

std::string loadedOpenImageIoVersion() {
  ModuleState& s = moduleState();
  std::lock_guard<std::mutex> hold(s.lock);
  return s.api ? s.api->version() : "";
}

OtherFormatImage decodeOtherFormat(const std::filesystem::path& file, const std::vector<std::uint8_t>* embedded,
                                   const OtherFormatCheck& check) {
  const std::string what = embedded ? file.string() + " (embedded image)" : file.string();
  return module(file, embedded).decode(file, embedded, what, check);
}

ImageHeader otherFormatHeader(const std::filesystem::path& file) { return module(file, nullptr).header(file); }

}  // namespace xval
