#include "files/atomic_write.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>

namespace xval {

namespace fs = std::filesystem;

namespace {

std::string reason(int err) { return std::strerror(err); }

// A folder only this call uses, beside the target(s): <dir>/<name>.partial-<pid>-<n>.
class PrivateFolder {
 public:
  PrivateFolder(const fs::path& dir, const std::string& name, const fs::path& target) {
    static std::atomic<unsigned long> counter{0};
    path_ = (dir.empty() ? fs::path(".") : dir) /
            (name + ".partial-" + std::to_string(getpid()) + "-" + std::to_string(counter++));
    if (mkdir(path_.c_str(), 0700) != 0)
      throw FileWriteError(target.string() + ": cannot write: cannot create the temporary folder " +
                           path_.string() + ": " + reason(errno));
  }
  ~PrivateFolder() {
    std::error_code ec;
    fs::remove_all(path_, ec);  // empty after a success; the partial files after a failure
  }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

// fsync a file the writer has closed; refuses anything but a regular file.
void syncWritten(const fs::path& tmp, const fs::path& target) {
  const int fd = open(tmp.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC);
  if (fd < 0)
    throw FileWriteError(target.string() + ": cannot write: the writer left no file (" + reason(errno) + ")");
  struct stat st;
  const bool regular = fstat(fd, &st) == 0 && S_ISREG(st.st_mode);
  const int rc = regular ? fsync(fd) : -1;
  const int err = errno;
  close(fd);
  if (!regular) throw FileWriteError(target.string() + ": cannot write: the writer left no regular file");
  if (rc != 0) throw FileWriteError(target.string() + ": cannot write: " + reason(err));
}

// The target may be absent, a regular file, or a link (which is replaced,
// never followed) to a regular file or to nothing. A device, a FIFO, a
// folder or a link to one is refused: renaming over it would replace
// /dev/full or /dev/stdout, and a folder cannot be replaced.
void requireReplaceable(const fs::path& target) {
  struct stat st;
  if (lstat(target.c_str(), &st) != 0) return;  // absent
  if (S_ISLNK(st.st_mode) && stat(target.c_str(), &st) != 0) return;  // a dangling link
  if (!S_ISREG(st.st_mode))
    throw FileWriteError(target.string() + ": cannot write: it exists and is not a regular file" +
                         (S_ISDIR(st.st_mode) ? " (a folder)" : ""));
}

void moveIntoPlace(const fs::path& tmp, const fs::path& target) {
  if (std::rename(tmp.c_str(), target.c_str()) != 0)
    throw FileWriteError(target.string() + ": cannot write: cannot rename the finished file into place: " +
                         reason(errno));
}

void syncFolder(const fs::path& dir) {
  const int fd = open(dir.empty() ? "." : dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  fsync(fd);  // best effort: the rename is already visible
  close(fd);
}

}  // namespace

void writeFileAtomically(const fs::path& file, std::string_view bytes) {
  requireReplaceable(file);
  PrivateFolder tmp_dir(file.parent_path(), file.filename().string(), file);
  const fs::path tmp = tmp_dir.path() / file.filename();
  const int fd = open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
  if (fd < 0) throw FileWriteError(file.string() + ": cannot write: " + reason(errno));
  size_t done = 0;
  int err = 0;
  while (done < bytes.size()) {
    const ssize_t n = write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      err = n < 0 ? errno : EIO;
      break;
    }
    done += size_t(n);
  }
  if (!err && fsync(fd) != 0) err = errno;
  if (close(fd) != 0 && !err) err = errno;
  if (err)
    throw FileWriteError(file.string() + ": cannot write (" + std::to_string(done) + " of " +
                         std::to_string(bytes.size()) + " bytes written): " + reason(err));
  moveIntoPlace(tmp, file);
  syncFolder(file.parent_path());
}

void writeFileAtomically(const fs::path& file, const std::function<bool(const fs::path& tmp)>& write) {
  writeFilesAtomically(file.parent_path(), {file.filename().string()},
                       [&](const fs::path& dir) { return write(dir / file.filename()); });
}

void writeFilesAtomically(const fs::path& dir, const std::vector<std::string>& names,
                          const std::function<bool(const fs::path& tmp_dir)>& write) {
  if (names.empty()) return;
  for (const auto& n : names) requireReplaceable(dir / n);
  const fs::path first = dir / names.front();
  PrivateFolder tmp_dir(dir, names.front(), first);
  bool ok = false;
  try {
    ok = write(tmp_dir.path());
  } catch (const std::exception& e) {
    throw FileWriteError(first.string() + ": cannot write: " + e.what());
  }
  if (!ok) throw FileWriteError(first.string() + ": cannot write: the writer reported a failure");
  for (const auto& n : names) syncWritten(tmp_dir.path() / n, dir / n);
  for (const auto& n : names) moveIntoPlace(tmp_dir.path() / n, dir / n);
  syncFolder(dir);
}

}  // namespace xval
