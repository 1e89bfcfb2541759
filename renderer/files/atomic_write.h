// Writing a file so that it is either whole or absent.
//
// Every file xval writes goes through here. The bytes go to a temporary
// name in a private folder created next to the target
// (`<target>.partial-<pid>-<n>/<target's name>`, so writers that pick the
// format from the extension still see it); the file is flushed, its write
// checked, fsync'ed, then renamed over the target and the folder synced.
// rename() replaces a symbolic link at the target itself, never what it
// points to, and the temporary is created with O_EXCL | O_NOFOLLOW in a
// folder nobody else knows, so nothing is ever written through a planted
// link. On any failure (a full disk, a read-only folder, a writer that
// reports an error) the temporary is removed, the target is left as it
// was, and FileWriteError names the target and the reason. A target that
// exists and is not a regular file (a device such as /dev/full, a FIFO, a
// folder, or a link to one of these) is refused before anything is written.
#pragma once

#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace xval {

class FileWriteError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Writes `bytes` as `file`.
void writeFileAtomically(const std::filesystem::path& file, std::string_view bytes);

// For writers that open the file themselves (OpenImageIO, gnuplot):
// `write(tmp)` must write the temporary `tmp` (same file name as `file`, in
// the private folder) and throw or return false on failure.
void writeFileAtomically(const std::filesystem::path& file,
                         const std::function<bool(const std::filesystem::path& tmp)>& write);

// For a writer that writes several files side by side (TinyGLTF: scene.gltf
// and scene.bin): `write(tmp_dir)` writes every one of `names` into the
// private folder; they are checked and renamed into `dir` in the order
// given, so the last one's presence says the set is whole.
void writeFilesAtomically(const std::filesystem::path& dir, const std::vector<std::string>& names,
                          const std::function<bool(const std::filesystem::path& tmp_dir)>& write);

}  // namespace xval
