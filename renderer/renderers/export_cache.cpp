// The export cache (export_cache.h).
#include "renderers/export_cache.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <mutex>
#include <stdexcept>
#include <vector>

#include <nlohmann/json.hpp>

#include "files/atomic_write.h"
#include "files/scratch_folder.h"
#include "files/sha256.h"
#include "process/run_process.h"
#include "scene/json_reader.h"
#include "scene_file/scene_loader.h"

namespace xval::renderers {

namespace {

namespace fs = std::filesystem;
constexpr const char* kEntryFormat = "xval-export-cache/2";
constexpr const char* kManifest = "manifest.json";
constexpr std::uintmax_t kMaxManifestBytes = 1 << 20;
constexpr const char* kTempPrefix = ".tmp-";

std::mutex g_lock;
ExportCache g_cache;

// The marker's text: the format line (written first into every folder the
// cache makes, so it is what tells xval's folders from the user's).
std::string markerText() { return std::string(kEntryFormat) + "\n"; }

// Whether `dir` is a folder the cache made: a real folder (not a link)
// holding the marker, a regular file with the marker's text. Nothing
// else in the cache folder is ever removed, whatever its name.
bool markedByTheCache(const fs::path& dir) {
  std::error_code ec;
  if (!fs::is_directory(fs::symlink_status(dir, ec))) return false;
  const fs::path m = dir / kExportCacheMarker;
  const fs::file_status st = fs::symlink_status(m, ec);
  if (!fs::is_regular_file(st) || fs::file_size(m, ec) != markerText().size()) return false;
  std::ifstream in(m, std::ios::binary);
  std::string text(markerText().size(), '\0');
  return in.read(text.data(), std::streamsize(text.size())) && text == markerText();
}

// A name the cache stores: a plain file name of the export folder.
bool plainName(const std::string& n) {
  return !n.empty() && n.front() != '.' && n != kManifest &&
         std::all_of(n.begin(), n.end(), [](char c) {
           return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
                  c == '-' || c == '.';
         });
}

struct StoredFile {
  std::string name;
  std::uintmax_t size = 0;
  std::string sha256;
};

// Copies `from` to `to` (created, never through a link) and returns the
// SHA-256 of the bytes copied; throws on a read or write error.
std::string copyHashing(const fs::path& from, const fs::path& to) {
  std::ifstream in(from, std::ios::binary);
  if (!in) throw std::runtime_error(from.string() + ": cannot read");
  std::string bytes;
  const std::string h = sha256Pieces([&](const std::function<void(const char*, size_t)>& update) {
    std::vector<char> buf(1 << 16);
    while (in.read(buf.data(), std::streamsize(buf.size())) || in.gcount() > 0) {
      update(buf.data(), size_t(in.gcount()));
      bytes.append(buf.data(), size_t(in.gcount()));
    }
    if (in.bad()) throw std::runtime_error(from.string() + ": read error");
  });
  writeFileAtomically(to, bytes);
  return h;
}

// The files of an export folder (plain files only); nullopt-like empty
// `why` on success.
std::vector<StoredFile> exportedFiles(const fs::path& dir, std::string* why) {
  std::vector<StoredFile> files;
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string n = e.path().filename().string();
    if (!plainName(n) || !e.is_regular_file() || e.is_symlink()) {
      *why = "the export holds " + n + ", not a plain file";
      return {};
    }
    files.push_back({n, e.file_size(), sha256File(e.path())});
  }
  std::sort(files.begin(), files.end(), [](const auto& a, const auto& b) { return a.name < b.name; });
  return files;
}

// The entry's files as its manifest lists them; throws with the reason
// when the manifest is missing, too large, not valid, or names anything
// but a plain file.
std::vector<StoredFile> readManifest(const fs::path& entry, const std::string& key) {
  const fs::path m = entry / kManifest;
  const fs::file_status st = fs::symlink_status(m);
  if (!fs::is_regular_file(st)) throw std::runtime_error("no manifest");
  if (fs::file_size(m) > kMaxManifestBytes) throw std::runtime_error("manifest larger than 1 MiB");
  const nlohmann::json j = parseJsonText(readJsonFile(m, "export cache manifest"), m.string());
  if (!j.is_object() || j.value("format", "") != kEntryFormat || j.value("key", "") != key ||
      !j.contains("files") || !j["files"].is_array())
    throw std::runtime_error("manifest not of format " + std::string(kEntryFormat) + " for this key");
  std::vector<StoredFile> files;
  for (const auto& f : j["files"]) {
    if (!f.is_object() || !f.contains("name") || !f["name"].is_string() || !f.contains("size") ||
        !f["size"].is_number_unsigned() || !f.contains("sha256") || !f["sha256"].is_string())
      throw std::runtime_error("manifest entry without name, size and sha256");
    StoredFile s{f["name"].get<std::string>(), f["size"].get<std::uintmax_t>(), f["sha256"].get<std::string>()};
    if (!plainName(s.name)) throw std::runtime_error("manifest names \"" + s.name + "\", not a plain file name");
    files.push_back(std::move(s));
  }
  return files;
}

// Restores the entry into `dir`; throws with the reason when any file is
// not as its manifest says (what was copied is removed again).
void restoreEntry(const fs::path& entry, const std::string& key, const fs::path& dir) {
  const std::vector<StoredFile> files = readManifest(entry, key);
  std::vector<fs::path> copied;
  try {
    fs::create_directories(dir);
    for (const StoredFile& f : files) {
      const fs::path from = entry / f.name;
      if (!fs::is_regular_file(fs::symlink_status(from))) throw std::runtime_error(f.name + ": not a regular file");
      if (fs::file_size(from) != f.size)
        throw std::runtime_error(f.name + ": " + std::to_string(fs::file_size(from)) + " bytes, the manifest says " +
                                 std::to_string(f.size));
      copied.push_back(dir / f.name);
      // The hash of the bytes copied, so a file changed after the checks is caught too.
      if (const std::string h = copyHashing(from, dir / f.name); h != f.sha256)
        throw std::runtime_error(f.name + ": SHA-256 " + h + ", the manifest says " + f.sha256);
    }
  } catch (...) {
    std::error_code ec;
    for (const fs::path& p : copied) fs::remove(p, ec);
    throw;
  }
  std::error_code ec;
  fs::last_write_time(entry / kManifest, fs::file_time_type::clock::now(), ec);  // recently used
}

// Stores the export in `dir` as the entry; a concurrent store of the same
// key wins or loses whole. Throws on a write error (the temporary removed).
void storeEntry(const ExportCache& cache, const fs::path& entry, const std::string& key, const fs::path& dir) {
  std::string why;
  const std::vector<StoredFile> files = exportedFiles(dir, &why);
  if (!why.empty()) throw std::runtime_error(why);
  fs::create_directories(cache.dir);
  const fs::path tmp = cache.dir / (kTempPrefix + attemptToken());
  struct Cleanup {
    fs::path p;
    ~Cleanup() {
      std::error_code ec;
      if (!p.empty()) fs::remove_all(p, ec);
    }
  } cleanup{tmp};
  // A new folder (create_directory reports one already there), marked
  // before anything else is written in it: a store killed at any point
  // leaves a folder removeStaleTemporaries recognises.
  if (!fs::create_directory(tmp)) throw std::runtime_error(tmp.string() + ": already exists");
  writeFileAtomically(tmp / kExportCacheMarker, markerText());
  nlohmann::json j = {{"format", kEntryFormat}, {"key", key}, {"files", nlohmann::json::array()}};
  for (const StoredFile& f : files) {
    if (copyHashing(dir / f.name, tmp / f.name) != f.sha256)
      throw std::runtime_error(f.name + ": changed while it was stored");
    j["files"].push_back({{"name", f.name}, {"size", f.size}, {"sha256", f.sha256}});
  }
  writeFileAtomically(tmp / kManifest, j.dump(1));
  std::error_code ec;
  fs::rename(tmp, entry, ec);  // fails when another process stored it first: its entry stays
  if (!ec) cleanup.p.clear();
}

// Removes the temporaries of stores that ended without renaming them (a
// process killed while storing; marked by the cache, whatever their name)
// once they are older than
// kStaleTempSeconds: a live store writes into its temporary all the time,
// so its folder's time is at most the time one file takes to copy.
void removeStaleTemporaries(const ExportCache& cache) {
  std::error_code ec;
  const auto now = fs::file_time_type::clock::now();
  for (const auto& e : fs::directory_iterator(cache.dir, ec)) {
    const std::string n = e.path().filename().string();
    if (n.rfind(kTempPrefix, 0) != 0 || !markedByTheCache(e.path())) continue;
    const auto written = fs::last_write_time(e.path(), ec);
    if (ec || now - written < std::chrono::seconds(kStaleTempSeconds)) continue;
    const std::uintmax_t removed = fs::remove_all(e.path(), ec);
    if (!ec) std::fprintf(stderr, "export cache: removed %s, an interrupted store (%ju files)\n", e.path().c_str(),
                          removed);
  }
}

// Removes least recently used entries until the cache's entries hold at
// most max_bytes; an entry is a folder the cache marked, never anything
// else in the cache folder (the user's own folders are neither counted nor
// touched).
void prune(const ExportCache& cache) {
  removeStaleTemporaries(cache);
  struct Entry {
    fs::path dir;
    fs::file_time_type used;
    std::uintmax_t bytes = 0;
  };
  std::vector<Entry> entries;
  std::uintmax_t total = 0;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(cache.dir, ec)) {
    if (e.path().filename().string().front() == '.' || !markedByTheCache(e.path())) continue;
    Entry en{e.path(), fs::last_write_time(e.path() / kManifest, ec), 0};
    for (const auto& f : fs::directory_iterator(e.path(), ec))
      if (f.is_regular_file()) en.bytes += f.file_size(ec);
    total += en.bytes;
    entries.push_back(en);
  }
  std::sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) { return a.used < b.used; });
  for (const Entry& e : entries) {
    if (total <= cache.max_bytes) break;
    fs::remove_all(e.dir, ec);
    total -= e.bytes;
  }
}

std::string shortKey(const std::string& key) { return key.substr(0, 12); }

}  // namespace

fs::path defaultExportCacheFolder() {
  if (const char* x = std::getenv("XDG_CACHE_HOME"); x && *x == '/') return fs::path(x) / "xval" / "exports";
  if (const char* h = std::getenv("HOME"); h && *h == '/') return fs::path(h) / ".cache" / "xval" / "exports";
  return {};
}

void setExportCache(const ExportCache& cache) {
  std::lock_guard<std::mutex> g(g_lock);
  g_cache = cache;
}

ExportCache exportCache() {
  std::lock_guard<std::mutex> g(g_lock);
  return g_cache;
}

std::string xvalIdentity() {
  static const std::string id = sha256File("/proc/self/exe");
  return id;
}

std::string exportKey(const std::string& exporter, const std::string& inputs_key) {
  return sha256Pieces([&](const std::function<void(const char*, size_t)>& update) {
    for (const std::string& piece : {std::string(kEntryFormat), exporter, xvalIdentity(), inputs_key}) {
      update(piece.data(), piece.size());
      update("\0", 1);
    }
  });
}

fs::path entryFolder(const ExportCache& cache, const std::string& exporter, const std::string& key) {
  // The exporter names are the harnesses' own ("pov", "gltf", a renderer
  // id) and the key is hex: the name stays inside the cache folder.
  if (!plainName(exporter) || exporter.find('.') != std::string::npos)
    throw std::invalid_argument("export cache: exporter name \"" + exporter + "\" cannot name an entry");
  return cache.dir / (exporter + "-" + key);
}

void exportThroughCache(const ExportCache& cache, const std::string& exporter, const std::string& key,
                        const fs::path& dir, const std::function<void(const fs::path&)>& write,
                        const std::function<std::string(const fs::path&)>& describe) {
  const fs::path entry = entryFolder(cache, exporter, key);
  const auto what = [&] { return describe ? describe(dir) : exporter; };
  std::error_code ec;
  if (fs::exists(fs::symlink_status(entry, ec)) && !markedByTheCache(entry)) {
    // Something the cache did not make holds the entry's name: it is left
    // as it is, the scene exported without the cache.
    std::fprintf(stderr,
                 "export cache: %s was not made by the export cache (no %s marker): left alone, "
                 "exported without the cache\n",
                 entry.c_str(), kExportCacheMarker);
    write(dir);
    return;
  }
  if (fs::exists(fs::symlink_status(entry, ec))) {
    try {
      restoreEntry(entry, key, dir);
      std::fprintf(stderr, "export cache: cached %s %s\n", what().c_str(), shortKey(key).c_str());
      return;
    } catch (const std::exception& e) {
      std::fprintf(stderr, "export cache: corrupt entry %s (%s): exported again\n", entry.c_str(), e.what());
      fs::remove_all(entry, ec);  // marked: the cache's own
    }
  }
  write(dir);
  try {
    storeEntry(cache, entry, key, dir);
    prune(cache);
    std::fprintf(stderr, "export cache: stored %s %s\n", what().c_str(), shortKey(key).c_str());
  } catch (const std::exception& e) {
    // The export itself is whole in `dir`; only the cache misses it.
    std::fprintf(stderr, "export cache: not stored %s (%s)\n", entry.c_str(), e.what());
  }
}

ExportThrough cachedExport(const std::string& exporter, const std::string& inputs_key) {
  const ExportCache cache = exportCache();
  if (cache.dir.empty() || inputs_key.empty()) return {};
  const std::string key = exportKey(exporter, inputs_key);
  return [cache, exporter, key](const fs::path& dir, const std::function<void(const fs::path&)>& write) {
    exportThroughCache(cache, exporter, key, dir, write);
  };
}

std::string cachedRefusal(const std::string& who, const std::string& inputs_key,
                          const std::function<std::string()>& refusal) {
  const ExportCache cache = exportCache();
  if (cache.dir.empty() || inputs_key.empty()) return refusal();
  const std::string exporter = "refusal-" + who;
  const std::string key = exportKey(exporter, inputs_key);
  const ScratchFolder scratch("refusal");
  const fs::path tmp = scratch.dir() / "export";
  const auto read = [&](const fs::path& dir) {
    std::ifstream in(dir / "refusal.txt", std::ios::binary);
    if (!in) throw std::runtime_error(exporter + ": the refusal was not written");
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  // An entry holds the exporter's verdict on the scene: a refusal, or none
  // (it can express the scene): the messages say which.
  exportThroughCache(
      cache, exporter, key, tmp,
      [&](const fs::path& dir) {
        fs::create_directories(dir);
        writeFileAtomically(dir / "refusal.txt", refusal());
      },
      [&](const fs::path& dir) {
        return read(dir).empty() ? who + "'s check (no refusal)" : who + "'s refusal";
      });
  return read(tmp);
}

}  // namespace xval::renderers
