#include "validate/compare_outputs.h"

#include <algorithm>
#include <stdexcept>
#include <string_view>
#include <system_error>

namespace xval {

namespace fs = std::filesystem;

namespace {

// A kind of file: its name's prefix and extension.
struct OutputKind {
  std::string_view prefix, extension;
  std::string name(const std::string& middle) const {
    return std::string(prefix) + middle + std::string(extension);
  }
};

constexpr OutputKind kDiff{"diff_", ".exr"};
constexpr OutputKind kHeat{"heat_", ".png"};  // the bound map's too: heat_bound_<pair>.png
constexpr OutputKind kCrop{"crop_", ".png"};
constexpr OutputKind kKinds[] = {kDiff, kHeat, kCrop};

}  // namespace

std::string diffExrName(const std::string& pair) { return kDiff.name(pair); }
std::string heatMapName(const std::string& pair) { return kHeat.name(pair); }
std::string boundMapName(const std::string& pair) { return kHeat.name("bound_" + pair); }
std::string cropName(const std::string& pair, const std::string& pixel, const std::string& of) {
  return kCrop.name(pair + "_" + pixel + "_" + of);
}

bool isCompareOutputName(const std::string& file_name) {
  const std::string_view n(file_name);
  return std::any_of(std::begin(kKinds), std::end(kKinds), [&](const OutputKind& k) {
    return n.size() > k.prefix.size() + k.extension.size() && n.substr(0, k.prefix.size()) == k.prefix &&
           n.substr(n.size() - k.extension.size()) == k.extension;
  });
}

std::vector<std::string> removeStaleCompareOutputs(const fs::path& case_dir, const std::set<std::string>& named) {
  std::vector<std::string> removed;
  std::error_code ec;
  fs::directory_iterator it(case_dir, ec), end;
  for (; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (!isCompareOutputName(name) || named.count(name)) continue;
    // symlink_status: a link is the user's, whatever it points to.
    std::error_code sec;
    if (!fs::is_regular_file(it->symlink_status(sec)) || sec) continue;
    if (!fs::remove(it->path(), sec) && sec)
      throw std::runtime_error(it->path().string() + ": a stale comparison output (this run's results do not name "
                               "it) cannot be removed: " + sec.message());
    removed.push_back(name);
  }
  if (ec)
    throw std::runtime_error(case_dir.string() + ": cannot list the case folder for stale comparison outputs: " +
                             ec.message());
  std::sort(removed.begin(), removed.end());
  return removed;
}

}  // namespace xval
