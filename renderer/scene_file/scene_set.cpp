// The scene files of a command's inputs (scene_file/scene_set.h).
#include "scene_file/scene_set.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <system_error>

#include "scene_file/scene_loader.h"

namespace xval {

namespace fs = std::filesystem;

namespace {

std::string joined(const std::vector<std::string>& inputs) {
  std::string out;
  for (const std::string& in : inputs) out += (out.empty() ? "" : ", ") + in;
  return out;
}

// A file of the inputs, and whether a folder's listing found it (else it
// was given by name).
struct Found {
  fs::path path;
  bool in_folder = false;
};

std::vector<Found> found(const std::vector<std::string>& inputs) {
  std::vector<Found> out;
  for (const std::string& in : inputs) {
    const fs::path p(in);
    std::error_code ec;
    if (fs::is_directory(p, ec)) {
      std::vector<fs::path> files;
      fs::directory_iterator it(p, ec);
      for (; !ec && it != fs::directory_iterator(); it.increment(ec))
        if (it->path().extension() == ".json") files.push_back(it->path());
      if (ec) throw std::runtime_error(in + ": cannot list the scene folder: " + ec.message());
      std::sort(files.begin(), files.end());
      for (fs::path& f : files) out.push_back({std::move(f), true});
    } else if (fs::is_regular_file(p, ec)) {
      out.push_back({p, false});
    } else {
      throw std::runtime_error(in + ": no such scene file or folder");
    }
  }
  return out;
}

}  // namespace

std::vector<fs::path> jsonFilesOf(const std::vector<std::string>& inputs) {
  std::vector<fs::path> out;
  for (Found& f : found(inputs)) out.push_back(std::move(f.path));
  return out;
}

SceneFiles findSceneFiles(const std::vector<std::string>& inputs) {
  SceneFiles out;
  for (Found& f : found(inputs)) {
    // A file given by name is a scene whatever it holds: loading it says
    // what is wrong with it.
    if (const std::string why = f.in_folder ? nonSceneReason(f.path) : std::string(); !why.empty())
      out.skipped.push_back({std::move(f.path), why});
    else
      out.scenes.push_back(std::move(f.path));
  }
  if (out.scenes.empty()) {
    std::string what = "no scene files found in " + joined(inputs);
    if (!out.skipped.empty()) {
      what += " (skipped:";
      for (const SkippedFile& s : out.skipped) what += " " + s.file.string() + ": " + s.reason + ";";
      what.back() = ')';
    }
    throw std::runtime_error(what);
  }
  return out;
}

std::vector<fs::path> sceneFiles(const std::vector<std::string>& inputs, const std::string& command) {
  SceneFiles found = findSceneFiles(inputs);
  for (const SkippedFile& s : found.skipped)
    std::fprintf(stderr, "%s: skipping %s: %s\n", command.c_str(), s.file.c_str(), s.reason.c_str());
  return std::move(found.scenes);
}

}  // namespace xval
