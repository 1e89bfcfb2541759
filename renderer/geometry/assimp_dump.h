// The part of an Assimp scene the model loader reads, as bytes and back:
// how the scene Assimp read in its child process (model_file.cpp, "Assimp
// in a child process") reaches xval.
//
// Kept, exactly (floats bit for bit, names as Assimp holds them):
//   meshes     name, primitive types, material index, positions, normals
//              (if any), the first uv set (if any) with its component
//              count, and every face's indices;
//   nodes      name, transformation, mesh indices, children (the tree);
//   materials  per material, for the base-colour and the diffuse texture
//              type, the texture of index 0 that aiMaterial::GetTexture
//              returns (its path and uv set), if it returns one;
//   textures   the embedded textures: file name, width, height, format
//              hint, and the bytes of an encoded image (height 0).
// Not kept: everything else (other uv sets, colours, tangents, bones,
// animations, cameras, lights, other material properties, the texels of a
// raw embedded texture: the loader refuses those by their height).
//
// Why not Assimp's own binary dump (assbin): writing and reading it back
// doubled the load time of a 1M-triangle file (docs/model-files.md,
// "Cost of the child process"); this is one copy of each array.
//
// The bytes come from a child process that ran Assimp on a hostile file,
// whose memory a defect of Assimp's may have corrupted: readAssimpDump
// checks every count against the bytes left before allocating, refuses a
// node tree deeper than `max_node_depth` (aiNode's destructor recurses)
// and every name longer than an aiString holds, and throws ModelFileError
// naming `file` and the field.
#pragma once

#include <memory>
#include <string>
#include <string_view>

struct aiScene;

namespace xval {

std::string writeAssimpDump(const aiScene& scene);

std::unique_ptr<aiScene> readAssimpDump(std::string_view bytes, const std::string& file, int max_node_depth);

}  // namespace xval
