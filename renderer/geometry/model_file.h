// Reading a model file (OBJ, PLY, STL, OFF, glTF 2.0, GLB) into the
// project's mesh form, with Assimp (docs/model-files.md: the choice, the
// per-format conventions, the limits).
//
// The result is one ModelPrimitive per (node, mesh) pair of the file: each
// mesh every node places, with the node's transform (the product of the
// matrices from the root down) applied by the rule of geometry/transform.h
// (positions by the matrix, normals by its inverse transpose, triangles
// re-wound under a mirroring matrix).
//   Triangles: polygons are triangulated (Assimp's aiProcess_Triangulate);
//     points and lines are dropped, they are not surfaces; so are the
//     triangles that repeat a vertex index or an earlier triangle's three
//     vertices (geometry/degenerate_triangles.h: they cover no pixel, and
//     Blender's importer drops them), each primitive's count in `notes`.
//   Normals: the file's, where the mesh has them (a zero-length one is
//     replaced by the computed one of that vertex); otherwise computed:
//       n_v = normalize(sum over the triangles t that use vertex v of
//                       (P1 - P0) x (P2 - P0))
//     (the winding normals weighted by twice the triangle's area), after
//     the node transform. A vertex only zero-area triangles use gets
//     (0, 0, 1). Assimp gives each face corner of an OBJ or STL file its
//     own vertex, so those files get flat (face) normals; PLY, OFF and glTF
//     share vertices and get smooth ones.
//   uv: the first uv set, as (u, 1 - v_assimp). Assimp presents every
//     format with v running up (OBJ's vt and PLY's as written; glTF's v,
//     which runs down, it flips to 1 - v), the scene's uv runs down
//     (geometry/mesh.h), so: OBJ, PLY: (u, 1 - v); glTF, GLB: (u, v) as in
//     the file, to within 2^-25 (Assimp's flip rounds in float). A mesh
//     without uvs gets (0, 0) everywhere and has_uvs = false.
//   Texture: the base-colour texture the primitive's material assigns
//     (glTF baseColorTexture, OBJ map_Kd): an external file, resolved
//     against the model's folder, or an image embedded in the file. Every
//     other material datum (PBR factors, specular maps, colours) is ignored.
//
// Assimp reads the file in a child process of its own (model_file.cpp,
// "Assimp in a child process"): a crash or a hang of its reader on a
// malformed file is that file's ModelFileError, not the end of xval.
//
// Every failure throws ModelFileError with a message naming the file, the
// element (mesh index and name, node, vertex or face index, field) and the
// value or limit. Limits (ModelLimits) are checked before the memory they
// bound is allocated where the count is known first: the file sizes before
// Assimp reads them (every file it opens goes through a guarded IO system),
// a PLY header's element counts against the file's size before Assimp
// reserves for them, a glTF node graph's nodes, placed meshes, triangles
// and depth counted per path (without expanding the paths) before Assimp
// copies a node once per path, and Assimp's reported counts before the
// mesh arrays are filled. Files the model refers to (OBJ's mtl and textures, glTF
// buffers and images) must resolve to regular files inside the model's
// folder (after following symlinks; a backslash is taken as a separator:
// the rule of geometry/model_references.h).
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "geometry/mesh.h"

namespace xval {

class ModelFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct ModelLimits {
  long long max_file_bytes = 1ll << 30;         // any one file read (model, mtl, buffer, image)
  long long max_total_bytes = 2ll << 30;        // all files read for one model
  long long max_triangles = 16ll << 20;         // over all primitives (the scene budget's default)
  long long max_vertices = 48ll << 20;          // over all primitives
  long long max_primitives = 65536;             // (node, mesh) pairs
  long long max_nodes = 1 << 20;                // nodes visited
  int max_node_depth = 256;                     // root = depth 0
  long long max_texture_bytes = 256ll << 20;    // one embedded image
  double max_import_seconds = 600.0;            // Assimp's read, in its child process (then killed)
  long long max_import_memory_bytes = 8ll << 30;  // that child's address space (RLIMIT_AS; not in a sanitizer build)
};

// Which primitives must carry uvs (a texture on a mesh without uvs is an
// error): none; those whose material assigns a base-colour texture (the
// scene's "texture": {"source": "model"}: then a referenced image must also
// exist inside the model's folder); every primitive (an image or brick
// texture of the scene on the whole object).
enum class UvRequirement { None, ModelTextures, All };

struct ModelLoadOptions {
  ModelLimits limits;
  UvRequirement uvs = UvRequirement::None;
};

struct ModelTexture {
  std::filesystem::path file;        // external image, absolute; empty when embedded
  std::vector<std::uint8_t> bytes;   // embedded image (PNG, JPEG, ...) as stored in the file
  std::string format_hint;           // embedded: Assimp's hint ("png", "jpg"), may be empty
  std::string name;                  // as the file names it (a path or "*index")
  bool embedded() const { return file.empty(); }
};

struct ModelPrimitive {
  std::string label;            // "mesh 2 'Body' (node 'root/legs')", for messages
  unsigned mesh_index = 0;      // in the file's mesh list (Assimp's order)
  std::string mesh_name, node_path;
  TriangleMesh mesh;            // node transform applied; doubles, not yet rounded to float32
  bool file_normals = false;    // the normals are the file's (else computed, see above)
  bool has_uvs = false;
  std::optional<ModelTexture> texture;  // the base-colour texture, if the material has one
};

struct Model {
  std::filesystem::path file;
  std::string format;  // "obj", "ply", "stl", "off", "gltf", "glb" (the extension, lower case)
  std::vector<ModelPrimitive> primitives;
  // Every file the model is made of, canonical, each once, the model file
  // first: the files Assimp opened (an OBJ's mtl, a glTF's buffers and
  // images) and the external base-colour textures its materials name that
  // exist inside the model's folder (Assimp only names those). What a
  // render of the model depends on (validate's input hash) and what
  // `xval pack` packs with it.
  std::vector<std::filesystem::path> files;
  // What the loader changed, one line each, naming the file: the triangles
  // dropped by the rule of geometry/degenerate_triangles.h (a repeated
  // vertex index, a twin of an earlier triangle), counted over every
  // placed mesh, with the first such mesh. Empty when the file's triangles
  // are taken as they are.
  std::vector<std::string> notes;
  long long triangleCount() const;
  long long vertexCount() const;
};

// The extensions read (lower case, with the dot).
const std::vector<std::string>& modelFileExtensions();

// Reads `file`. Throws ModelFileError (see above).
Model loadModelFile(const std::filesystem::path& file, const ModelLoadOptions& options = {});

}  // namespace xval
