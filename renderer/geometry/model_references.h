// The files a model file names, and the one rule for which of them may be
// opened: the loader's (geometry/model_file.h) for every file Assimp opens,
// and the Blender-import check's (blender/model_import.h) for every name
// Blender's importers would open.
//
// The rule: a name is a path relative to the model's folder (a backslash
// taken as a separator) that resolves, after following symlinks, inside
// that folder to a regular file. An absolute path, a ".." that leaves the
// folder, a symlink out of it, a FIFO, a device or a folder is refused.
//
// The names, per format (what Blender 3.4's importers open; Assimp opens a
// subset of them):
//   glTF, GLB  every string member named "uri", at any depth of the JSON
//              (images[].uri, buffers[].uri, and any extension's or
//              extras' uri), except a "data:" uri. A uri with another
//              scheme ("file:", "http:", ...) is refused: it is not a name
//              in the folder. Each is checked as written and
//              percent-decoded (Blender's importer decodes it).
//   OBJ        every mtllib line; in each material file that resolves
//              inside the folder, every map_* line and bump, disp, decal,
//              refl and norm (case-insensitive), relative to the material
//              file's folder and to the model's. The rest of the line is
//              checked whole and word by word (importers differ on names
//              with spaces and on options such as "-bm 0.5").
//   PLY, STL, OFF  none.
// A name that resolves inside the folder to nothing is not refused here:
// there is nothing to open (the loader refuses a missing file Assimp needs
// on its own, see GuardedIO in model_file.cpp).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace xval {

enum class NameResolution { RegularFile, NoSuchFile, NotRegularFile, Outside, Unresolvable };

struct ResolvedName {
  NameResolution kind = NameResolution::Unresolvable;
  std::filesystem::path real;  // canonical (the parts that exist resolved)
  std::string why;             // "NAME: why", empty for RegularFile
};

// `name` (relative to `folder`, which is canonical) by the rule above.
ResolvedName resolveInsideFolder(const std::filesystem::path& folder, const std::string& name);

struct ModelReference {
  std::filesystem::path file;  // the file that names it (the model or its material file)
  std::string field;           // "images[0].uri", "mtllib", "map_Bump"
  std::string value;           // as written
};

// Every name `model` (canonical) gives for another file, by the list above.
// A file of this list that cannot be read is taken as naming nothing (the
// loader reports it).
std::vector<ModelReference> modelReferences(const std::filesystem::path& model);

// "FILE: FIELD: 'VALUE': why" for the first name of `model` (canonical)
// that the rule refuses; empty when none.
std::string refusedModelReference(const std::filesystem::path& model);

}  // namespace xval
