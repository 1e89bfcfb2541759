// Scratch folders: private, fresh, and never at a name known in advance.
//
// Every scratch folder xval makes outside its output folder (the golden
// update's renders, bench's renders, the export check, a refusal read back
// through the export cache, the logs of version and git probes) is made
// here, with mkdtemp(3) in the temporary folder ($TMPDIR, else /tmp):
// the name ends in random characters, the folder is created by this call
// or the call fails (never an existing folder, nor a link planted at the
// name), and it is mode 0700 (nobody else can put a link or a file in it).
// A predictable name such as $TMPDIR/xval-bench-<pid>-<renderer> lets
// another user plant a link there first and receive what xval writes.
#pragma once

#include <filesystem>
#include <string>

namespace xval {

// A new folder `<temp>/xval-<what>-XXXXXX`, removed with everything in it
// when the object goes. Throws OutputFolderError (files/output_folder.h)
// naming the temporary folder and the reason when it cannot be made.
class ScratchFolder {
 public:
  explicit ScratchFolder(const std::string& what);
  ~ScratchFolder();
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;
  const std::filesystem::path& dir() const { return dir_; }

 private:
  std::filesystem::path dir_;
};

}  // namespace xval
