#include "files/scratch_folder.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "files/output_folder.h"

namespace xval {

namespace fs = std::filesystem;

ScratchFolder::ScratchFolder(const std::string& what) {
  std::error_code ec;
  const fs::path temp = fs::temp_directory_path(ec);
  if (ec) throw OutputFolderError("no temporary folder for a scratch folder (" + what + "): " + ec.message());
  const std::string pattern = (temp / ("xval-" + what + "-XXXXXX")).string();
  std::vector<char> name(pattern.begin(), pattern.end());
  name.push_back('\0');
  if (!mkdtemp(name.data()))  // creates it, mode 0700, or fails: never an existing name
    throw OutputFolderError(pattern + ": cannot create a scratch folder: " + std::strerror(errno));
  dir_ = name.data();
}

ScratchFolder::~ScratchFolder() {
  std::error_code ec;
  fs::remove_all(dir_, ec);
}

}  // namespace xval
