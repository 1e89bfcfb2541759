// Which files of the scenes a command is given are scene files: the one
// rule for validate (validate/validation/plan.h), golden update and check
// (validate/golden/golden_run.h) and pack (pack/set_pack.h).
//
// An input is a scene file or a folder. A folder stands for its files
// named *.json (not its subfolders' files), sorted by path so that every
// run lists them in the same order; a symbolic link among them is taken
// as the file it names (pack refuses one that leaves the set, as it
// refuses every file outside it). A file given by name is taken as it is,
// whatever its name. A *.json of a folder that is not a scene file (a
// tolerance file, or a file of another xval format: nonSceneReason,
// scene_file/scene_loader.h) is skipped, said on stderr; one that is not a
// regular file (a FIFO, a folder named x.json, a dangling link) is kept,
// so that loading it reports it as an error rather than it being passed
// over in silence.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace xval {

// The files the inputs stand for, in input order (each folder's *.json
// sorted), before any is read. Throws std::runtime_error naming an input
// that is neither a file nor a folder, or a folder that cannot be listed.
std::vector<std::filesystem::path> jsonFilesOf(const std::vector<std::string>& inputs);

// A file of jsonFilesOf that is not a scene, and why (nonSceneReason).
struct SkippedFile {
  std::filesystem::path file;
  std::string reason;
};

struct SceneFiles {
  std::vector<std::filesystem::path> scenes;  // in jsonFilesOf's order
  std::vector<SkippedFile> skipped;           // folder files that are not scenes
};

// jsonFilesOf's files split into scenes and skipped files (a file given by
// name is never skipped). Throws std::runtime_error as jsonFilesOf does, and
// when no scene file is left, naming the inputs and what was skipped.
SceneFiles findSceneFiles(const std::vector<std::string>& inputs);

// findSceneFiles' scenes, each skipped file said on stderr as
// "COMMAND: skipping FILE: REASON".
std::vector<std::filesystem::path> sceneFiles(const std::vector<std::string>& inputs, const std::string& command);

}  // namespace xval
