// The export cache: an outside renderer's export (POV-Ray's scene.pov and
// images, the glTF for Blender and EEVEE), and an exporter's refusal of a
// scene, stored by a hash of everything they depend on, so that a scene
// exported for one `xval validate` run is not exported again for the next.
//
// Key (exportKey): SHA-256 of the entry format, the exporter's name, this
// xval's identity (the SHA-256 of its own executable, so any change of the
// code that exports makes new keys) and the scene's inputs key (validation
// computes it from the bytes of the scene file, its textures and every file
// of its model files, and the scene file's absolute path).
//
// An entry is the folder CACHE/<exporter>-<key>/ holding the exported
// files and, last, manifest.json (each file's name, size and SHA-256). It
// is written under a temporary name in CACHE and renamed into place whole;
// a reader uses it only when the manifest parses, names plain files only
// (no '/', no '\\', no leading '.', no links), and every file has the size
// and the SHA-256 the manifest says while it is copied out; otherwise the
// entry is removed, the scene exported again and the entry stored anew.
// So an interrupted write, a truncated or altered file, or a planted link
// is never used; a refusal is stored the same way (refusal.txt).
//
// What the cache may remove: only folders it made, recognised by the
// marker file kExportCacheMarker it writes first into each (its text is
// the entry format line), never by their names. The cache folder may hold
// the user's own files and folders: they are never counted, used or
// removed; a folder or file without the marker at an entry's name is left
// alone and the scene exported without the cache.
//
// Size: after a store, the least recently used entries (manifest time) are
// removed until the entries hold at most ExportCache::max_bytes, and so
// are marked temporaries (.tmp-*) untouched for kStaleTempSeconds: what a
// store killed before its rename leaves behind.
//
// Every use says on stderr what it did: "export cache: cached", "stored",
// or "corrupt ... exported again" with the exporter and the key's start
// (for a refusal entry, whether it holds a refusal: "blender's refusal",
// "blender's check (no refusal)").
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>

#include "common/export_common.h"

namespace xval::renderers {

inline constexpr std::uintmax_t kDefaultExportCacheBytes = std::uintmax_t(2) << 30;  // 2 GiB
// A temporary of a store not written to for this long belongs to no live
// store (one file's copy takes seconds, not an hour).
inline constexpr long kStaleTempSeconds = 3600;
// The marker file in every folder the cache makes (docs/robustness.md: what
// xval may delete).
inline constexpr const char* kExportCacheMarker = ".xval-export-cache-entry";

struct ExportCache {
  std::filesystem::path dir;  // empty: no cache
  std::uintmax_t max_bytes = kDefaultExportCacheBytes;
};

// $XDG_CACHE_HOME/xval/exports, else $HOME/.cache/xval/exports; empty when
// neither is set.
std::filesystem::path defaultExportCacheFolder();

// The process's cache (none until a command sets one: `xval validate`).
void setExportCache(const ExportCache& cache);
ExportCache exportCache();

// SHA-256 of this process's executable (/proc/self/exe), computed once;
// throws std::runtime_error when it cannot be read.
std::string xvalIdentity();

// The key of an exporter's entry for a scene whose inputs hash to `inputs_key`.
std::string exportKey(const std::string& exporter, const std::string& inputs_key);

// The export through the process's cache: restores the entry of
// (exporter, inputs_key) into the folder, or writes it and stores it.
// Empty (the harness exports itself) when there is no cache or no key.
ExportThrough cachedExport(const std::string& exporter, const std::string& inputs_key);

// An exporter's refusal through the cache: the stored message of
// (who, inputs_key) ("" when it can express the scene), else refusal()'s,
// stored. Without a cache or key: refusal().
std::string cachedRefusal(const std::string& who, const std::string& inputs_key,
                          const std::function<std::string()>& refusal);

// Lower level, for tests: the entry folder of a key, and the export into
// `dir` through the cache `cache` (whatever the process's cache is).
std::filesystem::path entryFolder(const ExportCache& cache, const std::string& exporter, const std::string& key);
// `describe` names what the entry holds in the messages, from the folder
// it was restored or written into (empty: the exporter's name).
void exportThroughCache(const ExportCache& cache, const std::string& exporter, const std::string& key,
                        const std::filesystem::path& dir, const std::function<void(const std::filesystem::path&)>& write,
                        const std::function<std::string(const std::filesystem::path&)>& describe = {});

}  // namespace xval::renderers
