// A scene set as one archive (`xval pack`), so a set made here can be
// checked on another machine, and the check of an unpacked one.
//
// The set is a folder SET holding SET/scenes/*.json (docs/pack.md). The
// archive SET_NAME.tar.gz (gzip-compressed POSIX tar, written with
// libarchive) holds, under the top folder named like SET:
//   scenes/*.json                every JSON file of the scenes folder (the
//                                scenes, and files validate skips there)
//   each file a scene refers to  its image textures, its model files and
//                                every file a model file is made of (an OBJ's
//                                mtl and images, a glTF's buffers: Model::files,
//                                geometry/model_file.h), at their paths
//                                relative to SET
//   the tolerance file           the one the scenes find (validate/tolerances.h,
//                                findToleranceFile): at its path when it is
//                                inside SET, else as SET/tolerances.json, where
//                                the unpacked set's scenes find it by the same rule
//   golden/R/manifest.json and   every golden set stored beside the scenes
//   each image it lists          (golden/golden_set.h)
//   pack-manifest.json           last: every file above with its SHA-256 and
//                                size, the xval version, the git commit, the date
//
// Every path is relative to SET, so the unpacked set is read from wherever
// it is unpacked: a scene's relative references resolve as before, the
// golden images are found beside the scenes folder, the tolerance file by
// the nearest-ancestor rule.
//
// Refused, naming the scene, the field and the path (nothing is written):
//   - a file referred to from outside SET (a relative path that leaves it,
//     or an absolute path: the copy on another machine would not find it);
//     the file is to be copied into the set and referred to from there
//     (the packed scenes are the set's files byte for byte, so their golden
//     images stay valid: no path is rewritten);
//   - a file inside SET that is a symbolic link resolving outside it;
//   - a path with a backslash (a separator to other tools) or a control
//     character in a name.
// The archive is written under a temporary name and renamed when whole
// (files/atomic_write.h): an interrupt or a full disk leaves no archive.
#pragma once

#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace xval::pack {

inline constexpr const char* kManifestFormat = "xval-pack/1";
inline constexpr const char* kManifestName = "pack-manifest.json";

class PackError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// One file of the set as packed.
struct SetFile {
  std::string path;              // relative to SET, '/'-separated: its name in the archive below the top folder
  std::filesystem::path source;  // where it is read from
  std::string role;              // "scene", "texture", "model", "tolerances", "golden manifest", "golden image", "file"
};

// The files of the set SET, in archive order (scenes first, then what they
// refer to, the tolerance file, the golden sets), each once. Throws
// PackError for every refusal above, naming the file and the reason.
std::vector<SetFile> setFiles(const std::filesystem::path& set);

// Progress of packSet: file k (1-based) of n, with the bytes packed so far
// and in all.
struct Progress {
  size_t k = 0, n = 0;
  long long bytes_done = 0, bytes_total = 0;
  const SetFile* file = nullptr;
};

struct PackSummary {
  size_t files = 0;     // without the manifest
  long long bytes = 0;  // of those files, uncompressed
  std::string top;      // the archive's top folder
};

// Writes the archive (a path ending in .tar.gz). Each file is hashed as it
// is copied (a file whose size changes while it is read is an error).
PackSummary packSet(const std::filesystem::path& set, const std::filesystem::path& archive,
                    const std::function<void(const Progress&)>& progress = {});

// What is wrong with the unpacked set DIR (the folder holding
// pack-manifest.json), one line per file, by name: missing, changed
// (size or SHA-256, both quoted), not a regular file (a symbolic link
// included), or present but not in the manifest. Empty: every file is as
// packed. Throws PackError when the manifest is missing or malformed (a
// path in it that is absolute, has a '..' component or a backslash
// included).
std::vector<std::string> verifyUnpacked(const std::filesystem::path& dir);

}  // namespace xval::pack
