// Folders xval writes into: never through a symbolic link, fresh work
// folders per attempt, and one writer at a time.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>

namespace xval {

class OutputFolderError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Makes `dir` (and its missing parents) a folder. Throws OutputFolderError
// naming `dir` when it, or any folder on the way below `root` (which must
// contain it; the user's own folder and what leads to it are trusted), is
// a symbolic link or not a folder: xval never writes through a link inside
// its output folder.
void makeRealFolder(const std::filesystem::path& root, const std::filesystem::path& dir);

// Makes `dir` a new empty folder: whatever is there (a folder and its
// contents, a file, or a symbolic link itself, never what it points to) is
// removed first. A tool started in it can only see files written for this
// attempt; a tool left from an earlier attempt that still writes relative
// to its old working folder writes into the removed one.
void makeFreshFolder(const std::filesystem::path& dir);

// An exclusive or shared flock(2) on `dir`/.xval.lock, held while the
// object lives (and released by the kernel if the process dies). An
// exclusive holder writes its pid into the file. Throws OutputFolderError
// naming the folder and the holder's pid when the lock is taken.
class FolderLock {
 public:
  enum class Mode { Exclusive, Shared };
  FolderLock(const std::filesystem::path& dir, Mode mode, const std::string& who);
  ~FolderLock();
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;

 private:
  int fd_ = -1;
};

// Throws OutputFolderError unless the path can be handed to the tools as
// part of their paths: no '\\' (Blender reads it as a folder separator and
// would write elsewhere), no '?' (OpenImageIO reads options after it) and
// no control characters. Checked before anything is rendered.
void checkToolPath(const std::filesystem::path& path);

// The lock file's name (a reserved name in an output folder).
inline constexpr const char* kLockFileName = ".xval.lock";

}  // namespace xval
