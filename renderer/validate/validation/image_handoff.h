// Images a render job of this process has just written, kept for its
// case's compare in the same run (run_job.h runJobs with a CaseComparer),
// so that the compare step decodes no EXR this process wrote moments
// before.
//
// What is kept is the image as read back from the written file (writeImage
// reads every image back before renaming it into place, image/image.h):
// the very Image readImage(file) would return, bit for bit, not the
// renderer's in-memory image. It is handed over only while the file is
// still the one written: the same device, inode, size and modification
// time as right after the write; otherwise (a file replaced or touched,
// a job of an earlier run, --compare-only, another process's job) the
// compare step reads the file as before. Each image is handed over once.
//
//   max_bytes  the most pixel bytes kept at once (kImageHandoffBytes by
//              default); an image that would exceed it is not kept, and
//              its case reads its file.
#pragma once

#include <cstddef>
#include <filesystem>
#include <map>
#include <mutex>
#include <optional>

#include "image/image.h"

namespace xval::validation {

inline constexpr size_t kImageHandoffBytes = size_t(1) << 30;

class ImageHandoff {
 public:
  explicit ImageHandoff(size_t max_bytes = kImageHandoffBytes) : max_bytes_(max_bytes) {}
  // Keeps `image` (as read back from `file`, just written) for `file`,
  // with the file's identity now. A file that cannot be stat'ed, or an
  // image over the limit, is not kept.
  void put(const std::filesystem::path& file, Image image);
  // The image kept for `file` if the file is still the one written, and
  // forgets it; nullopt otherwise.
  std::optional<Image> take(const std::filesystem::path& file);
  // Pixel bytes kept now.
  size_t bytes() const;

 private:
  struct Identity {
    unsigned long long dev = 0, ino = 0, size = 0;
    long long mtime_ns = 0;
    bool operator==(const Identity& o) const {
      return dev == o.dev && ino == o.ino && size == o.size && mtime_ns == o.mtime_ns;
    }
  };
  static std::optional<Identity> identityOf(const std::filesystem::path& file);
  struct Kept {
    Identity identity;
    Image image;
    size_t bytes = 0;
  };
  size_t max_bytes_;
  size_t bytes_ = 0;
  std::map<std::filesystem::path, Kept> kept_;
  mutable std::mutex lock_;
};

}  // namespace xval::validation
