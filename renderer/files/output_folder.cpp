#include "files/output_folder.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace xval {

namespace fs = std::filesystem;

namespace {
std::string reason(int err) { return std::strerror(err); }
}  // namespace

void makeRealFolder(const fs::path& root, const fs::path& dir) {
  const fs::path r = root.lexically_normal(), d = dir.lexically_normal();
  const fs::path rel = d.lexically_relative(r);
  if (rel.empty() || *rel.begin() == "..")
    throw OutputFolderError(dir.string() + ": not inside " + root.string());
  std::error_code ec;
  fs::create_directories(r, ec);
  if (!fs::is_directory(r))
    throw OutputFolderError(r.string() + ": cannot create the folder" + (ec ? ": " + ec.message() : ""));
  fs::path at = r;
  for (const auto& part : rel) {
    if (part == ".") continue;
    at /= part;
    struct stat st;
    if (lstat(at.c_str(), &st) != 0) {
      // Absent: create it. EEXIST: another job (a thread or a process of
      // the same run) just did; it is checked below like any existing one.
      if (errno != ENOENT || (mkdir(at.c_str(), 0755) != 0 && errno != EEXIST))
        throw OutputFolderError(at.string() + ": cannot create the folder: " + reason(errno));
      if (lstat(at.c_str(), &st) != 0)
        throw OutputFolderError(at.string() + ": cannot create the folder: " + reason(errno));
    }
    if (S_ISLNK(st.st_mode))
      throw OutputFolderError(at.string() + ": is a symbolic link; xval does not write through links "
                              "inside its output folder (remove it)");
    if (!S_ISDIR(st.st_mode))
      throw OutputFolderError(at.string() + ": exists and is not a folder");
  }
}

void checkToolPath(const fs::path& path) {
  const std::string s = path.string();
  for (unsigned char c : s) {
    const char* why = c == '\\' ? "Blender reads '\\' as a folder separator and would write outside it"
                      : c == '?' ? "OpenImageIO reads what follows '?' in a file name as options"
                      : c < 0x20 || c == 0x7f ? "a control character breaks logs and messages"
                                              : nullptr;
    if (why)
      throw OutputFolderError(s + ": cannot be used as an output folder: it contains '" +
                              (c < 0x20 || c == 0x7f ? std::string("\\x") + "0123456789abcdef"[c >> 4] +
                                                           "0123456789abcdef"[c & 15]
                                                     : std::string(1, char(c))) +
                              "' (" + why + ")");
  }
}

void makeFreshFolder(const fs::path& dir) {
  std::error_code ec;
  fs::remove_all(dir, ec);  // a link is removed itself, its target is untouched
  if (ec) throw OutputFolderError(dir.string() + ": cannot remove the previous work folder: " + ec.message());
  if (mkdir(dir.c_str(), 0755) != 0)
    throw OutputFolderError(dir.string() + ": cannot create the work folder: " + reason(errno));
}

FolderLock::FolderLock(const fs::path& dir, Mode mode, const std::string& who) {
  const fs::path file = dir / kLockFileName;
  fd_ = open(file.c_str(), O_RDWR | O_CREAT | O_NOFOLLOW | O_CLOEXEC, 0644);
  if (fd_ < 0) throw OutputFolderError(file.string() + ": cannot open the lock file: " + reason(errno));
  if (flock(fd_, (mode == Mode::Exclusive ? LOCK_EX : LOCK_SH) | LOCK_NB) != 0) {
    const int err = errno;
    char buf[32] = {0};
    const ssize_t n = pread(fd_, buf, sizeof buf - 1, 0);
    std::string holder = n > 0 ? std::string(buf, size_t(n)) : std::string();
    while (!holder.empty() && (holder.back() == '\n' || holder.back() == ' ')) holder.pop_back();
    close(fd_);
    fd_ = -1;
    if (err != EWOULDBLOCK) throw OutputFolderError(file.string() + ": cannot lock: " + reason(err));
    throw OutputFolderError(dir.string() + ": another " + who + " is writing into this folder (" +
                            (holder.empty() ? std::string("a --run-job, or a run whose pid is not recorded")
                                            : "pid " + holder) +
                            ", lock " + file.string() + "); wait for it or choose another folder");
  }
  // The exclusive holder's pid, for the message of whoever is refused; a
  // shared holder (one of several) clears it, so no stale pid is named.
  // Failing to write it loses only that detail: the lock holds all the same.
  const std::string pid = mode == Mode::Exclusive ? std::to_string(getpid()) + "\n" : "";
  if (ftruncate(fd_, 0) == 0 && !pid.empty()) (void)!pwrite(fd_, pid.data(), pid.size(), 0);
}

FolderLock::~FolderLock() {
  if (fd_ >= 0) close(fd_);  // releases the lock
}

}  // namespace xval
