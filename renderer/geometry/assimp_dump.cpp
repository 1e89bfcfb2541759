// The loader's part of an Assimp scene as bytes and back (assimp_dump.h).
//
// Layout (native byte order: the writer is a fork of the reader's process):
//   "XVALAIS1"
//   u32 meshes; each: str name, u32 primitive types, u32 material index,
//     u32 vertices V, u8 has normals, u8 has uv0, u32 uv0 components,
//     V x 3 f32 positions, [V x 3 f32 normals], [V x 3 f32 uv0],
//     u32 faces F, F x u32 index counts, u64 indices I, I x u32 indices
//   u32 nodes (preorder); each: str name, 16 f32 (row-major a1..d4),
//     u32 meshes M, M x u32 mesh indices, u32 children
//   u32 materials; each, for base colour then diffuse: u8 present,
//     [str path, u32 uv index]
//   u32 textures; each: str file name, u32 width, u32 height, 9 bytes
//     format hint, [width bytes when height is 0]
//   "END!"
// with str = u32 length and the bytes.
#include "geometry/assimp_dump.h"

#include <assimp/material.h>
#include <assimp/scene.h>

#include <cstdint>
#include <cstring>
#include <vector>

#include "geometry/model_file.h"

namespace xval {

namespace {

constexpr char kMagic[8] = {'X', 'V', 'A', 'L', 'A', 'I', 'S', '1'};
constexpr char kEnd[4] = {'E', 'N', 'D', '!'};
constexpr aiTextureType kTextureTypes[2] = {aiTextureType_BASE_COLOR, aiTextureType_DIFFUSE};

struct Out {
  std::string s;
  void raw(const void* p, size_t n) { s.append(static_cast<const char*>(p), n); }
  template <class T> void put(T v) { raw(&v, sizeof v); }
  void str(const aiString& a) {
    const uint32_t n = a.length < MAXLEN ? a.length : MAXLEN - 1;
    put(n);
    raw(a.data, n);
  }
};

struct In {
  std::string_view s;
  const std::string& file;
  size_t at = 0;

  [[noreturn]] void bad(const std::string& what) const {
    throw ModelFileError(file + ": the scene Assimp's child process wrote is malformed at byte " +
                         std::to_string(at) + " of " + std::to_string(s.size()) + ": " + what);
  }
  size_t left() const { return s.size() - at; }
  void raw(void* p, size_t n, const char* what) {
    if (n > left()) bad(std::string(what) + ": " + std::to_string(n) + " bytes, " + std::to_string(left()) + " left");
    std::memcpy(p, s.data() + at, n);
    at += n;
  }
  template <class T> T take(const char* what) {
    T v;
    raw(&v, sizeof v, what);
    return v;
  }
  // A count of items of at least `item_bytes` each: no more than the bytes left hold.
  uint32_t count(const char* what, size_t item_bytes) {
    const uint32_t n = take<uint32_t>(what);
    if (item_bytes && uint64_t(n) * item_bytes > left())
      bad(std::string(what) + " " + std::to_string(n) + ": more than the " + std::to_string(left()) +
          " bytes left hold");
    return n;
  }
  void str(aiString& a, const char* what) {
    const uint32_t n = take<uint32_t>(what);
    if (n >= MAXLEN) bad(std::string(what) + ": " + std::to_string(n) + " bytes (an aiString holds " +
                            std::to_string(MAXLEN - 1) + ")");
    char buf[MAXLEN];
    raw(buf, n, what);
    a.length = n;
    std::memcpy(a.data, buf, n);
    a.data[n] = '\0';
  }
  // n elements of 3 floats into a new[] array.
  aiVector3D* vectors(uint32_t n, const char* what) {
    if (uint64_t(n) * sizeof(aiVector3D) > left()) bad(std::string(what) + ": cut");
    auto* v = new aiVector3D[n];
    raw(v, size_t(n) * sizeof(aiVector3D), what);
    return v;
  }
};

}  // namespace

std::string writeAssimpDump(const aiScene& scene) {
  static_assert(sizeof(aiVector3D) == 12 && sizeof(ai_real) == 4, "the layout assumes float32 vectors");
  Out o;
  const uint32_t nm = scene.mMeshes ? scene.mNumMeshes : 0;
  size_t arrays = 0;  // the bulk of the size, reserved at once (one copy of each array)
  for (uint32_t k = 0; k < nm; ++k)
    if (const aiMesh* m = scene.mMeshes[k]) arrays += size_t(m->mNumVertices) * 36 + size_t(m->mNumFaces) * 16;
  o.s.reserve(arrays + 4096);
  o.raw(kMagic, sizeof kMagic);
  o.put(nm);
  for (uint32_t k = 0; k < nm; ++k) {
    const aiMesh* m = scene.mMeshes[k];
    static const aiMesh empty;
    if (!m) m = &empty;
    const uint32_t nv = m->mVertices ? m->mNumVertices : 0;
    o.str(m->mName);
    o.put(uint32_t(m->mPrimitiveTypes));
    o.put(uint32_t(m->mMaterialIndex));
    o.put(nv);
    const bool normals = m->mNormals != nullptr && nv, uv = m->mTextureCoords[0] != nullptr && nv;
    o.put(uint8_t(normals));
    o.put(uint8_t(uv));
    o.put(uint32_t(m->mNumUVComponents[0]));
    o.raw(m->mVertices, size_t(nv) * sizeof(aiVector3D));
    if (normals) o.raw(m->mNormals, size_t(nv) * sizeof(aiVector3D));
    if (uv) o.raw(m->mTextureCoords[0], size_t(nv) * sizeof(aiVector3D));
    const uint32_t nf = m->mFaces ? m->mNumFaces : 0;
    o.put(nf);
    uint64_t indices = 0;
    for (uint32_t f = 0; f < nf; ++f) {
      const uint32_t c = m->mFaces[f].mIndices ? m->mFaces[f].mNumIndices : 0;
      o.put(c);
      indices += c;
    }
    o.put(indices);
    for (uint32_t f = 0; f < nf; ++f)
      if (m->mFaces[f].mIndices) o.raw(m->mFaces[f].mIndices, size_t(m->mFaces[f].mNumIndices) * 4);
  }
  // Nodes, preorder (explicit stack: the tree's depth is the file's).
  std::vector<const aiNode*> order, stack;
  if (scene.mRootNode) stack.push_back(scene.mRootNode);
  while (!stack.empty()) {
    const aiNode* n = stack.back();
    stack.pop_back();
    order.push_back(n);
    if (n->mChildren)
      for (uint32_t c = n->mNumChildren; c-- > 0;)
        if (n->mChildren[c]) stack.push_back(n->mChildren[c]);
  }
  o.put(uint32_t(order.size()));
  for (const aiNode* n : order) {
    o.str(n->mName);
    o.raw(&n->mTransformation, sizeof(aiMatrix4x4));
    const uint32_t meshes = n->mMeshes ? n->mNumMeshes : 0;
    o.put(meshes);
    o.raw(n->mMeshes, size_t(meshes) * 4);
    uint32_t children = 0;
    if (n->mChildren)
      for (uint32_t c = 0; c < n->mNumChildren; ++c) children += n->mChildren[c] != nullptr;
    o.put(children);
  }
  const uint32_t nmat = scene.mMaterials ? scene.mNumMaterials : 0;
  o.put(nmat);
  for (uint32_t k = 0; k < nmat; ++k) {
    for (aiTextureType type : kTextureTypes) {
      const aiMaterial* mat = scene.mMaterials[k];
      aiString path;
      unsigned uv_index = 0;
      const bool present = mat && mat->GetTextureCount(type) > 0 &&
                           mat->GetTexture(type, 0, &path, nullptr, &uv_index) == aiReturn_SUCCESS;
      o.put(uint8_t(present));
      if (present) {
        o.str(path);
        o.put(uint32_t(uv_index));
      }
    }
  }
  const uint32_t nt = scene.mTextures ? scene.mNumTextures : 0;
  o.put(nt);
  for (uint32_t k = 0; k < nt; ++k) {
    static const aiTexture none;
    const aiTexture* t = scene.mTextures[k] ? scene.mTextures[k] : &none;
    o.str(t->mFilename);
    const uint32_t w = t->pcData ? t->mWidth : 0;
    o.put(w);
    o.put(uint32_t(t->mHeight));
    o.raw(t->achFormatHint, 9);
    if (t->mHeight == 0) o.raw(t->pcData, w);
  }
  o.raw(kEnd, sizeof kEnd);
  return std::move(o.s);
}

std::unique_ptr<aiScene> readAssimpDump(std::string_view bytes, const std::string& file, int max_node_depth) {
  In in{bytes, file};
  char magic[8];
  in.raw(magic, sizeof magic, "magic");
  if (std::memcmp(magic, kMagic, sizeof magic) != 0) in.bad("not a dump (magic)");
  auto scene = std::make_unique<aiScene>();

  const uint32_t nm = in.count("meshes", 4 * 7);
  scene->mMeshes = new aiMesh*[nm]();
  scene->mNumMeshes = nm;
  for (uint32_t k = 0; k < nm; ++k) {
    aiMesh* m = scene->mMeshes[k] = new aiMesh();
    in.str(m->mName, "mesh name");
    m->mPrimitiveTypes = in.take<uint32_t>("primitive types");
    m->mMaterialIndex = in.take<uint32_t>("material index");
    const uint32_t nv = in.count("vertices", sizeof(aiVector3D));
    const bool normals = in.take<uint8_t>("has normals") != 0, uv = in.take<uint8_t>("has uv") != 0;
    m->mNumUVComponents[0] = in.take<uint32_t>("uv components");
    m->mVertices = in.vectors(nv, "positions");
    m->mNumVertices = nv;
    if (normals) m->mNormals = in.vectors(nv, "normals");
    if (uv) m->mTextureCoords[0] = in.vectors(nv, "uvs");
    const uint32_t nf = in.count("faces", 4);
    std::vector<uint32_t> counts(nf);
    in.raw(counts.data(), size_t(nf) * 4, "face index counts");
    const uint64_t ni = in.take<uint64_t>("indices");
    uint64_t sum = 0;
    for (uint32_t c : counts) sum += c;
    if (sum != ni) in.bad("indices " + std::to_string(ni) + ", the faces' counts add up to " + std::to_string(sum));
    if (ni > in.left() / 4) in.bad("indices " + std::to_string(ni) + ": cut");
    m->mFaces = new aiFace[nf];
    m->mNumFaces = nf;
    for (uint32_t f = 0; f < nf; ++f) {
      aiFace& face = m->mFaces[f];
      face.mIndices = new unsigned[counts[f]];
      face.mNumIndices = counts[f];
      in.raw(face.mIndices, size_t(counts[f]) * 4, "face indices");
    }
  }

  // Nodes: preorder, each followed by its children's subtrees.
  const uint32_t nn = in.count("nodes", 4 + 64 + 4 + 4);
  if (nn == 0) in.bad("no root node");
  struct Open { aiNode* node; uint32_t children_left; int depth; };
  std::vector<Open> open;
  for (uint32_t k = 0; k < nn; ++k) {
    auto* n = new aiNode();
    const int depth = open.empty() ? 0 : open.back().depth + 1;
    if (open.empty()) {
      if (scene->mRootNode) {
        delete n;
        in.bad("node " + std::to_string(k) + " after the whole tree");
      }
      scene->mRootNode = n;
    } else {
      Open& parent = open.back();
      parent.node->mChildren[parent.node->mNumChildren++] = n;
      n->mParent = parent.node;
      --parent.children_left;
    }
    in.str(n->mName, "node name");
    if (depth > max_node_depth)
      throw ModelFileError(file + ": node '" + std::string(n->mName.C_Str()) + "': deeper than " +
                           std::to_string(max_node_depth) + " levels");
    in.raw(&n->mTransformation, sizeof(aiMatrix4x4), "node transformation");
    const uint32_t meshes = in.count("node meshes", 4);
    n->mMeshes = new unsigned[meshes];
    n->mNumMeshes = meshes;
    in.raw(n->mMeshes, size_t(meshes) * 4, "node mesh indices");
    const uint32_t children = in.take<uint32_t>("node children");
    if (children > nn - 1 - k)
      in.bad("node '" + std::string(n->mName.C_Str()) + "': " + std::to_string(children) + " children, " +
             std::to_string(nn - 1 - k) + " nodes follow");
    if (children) {
      n->mChildren = new aiNode*[children]();
      open.push_back({n, children, depth});
    }
    while (!open.empty() && open.back().children_left == 0) open.pop_back();
  }
  if (!open.empty()) in.bad("the node tree ends before its last node's children");

  const uint32_t nmat = in.count("materials", 2);
  scene->mMaterials = new aiMaterial*[nmat]();
  scene->mNumMaterials = nmat;
  for (uint32_t k = 0; k < nmat; ++k) {
    aiMaterial* mat = scene->mMaterials[k] = new aiMaterial();
    for (aiTextureType type : kTextureTypes) {
      if (in.take<uint8_t>("material texture present") == 0) continue;
      aiString path;
      in.str(path, "material texture path");
      const int uv_index = int(in.take<uint32_t>("material texture uv set"));
      mat->AddProperty(&path, AI_MATKEY_TEXTURE(type, 0));
      mat->AddProperty(&uv_index, 1, AI_MATKEY_UVWSRC(type, 0));
    }
  }

  const uint32_t nt = in.count("textures", 4 + 4 + 4 + 9);
  scene->mTextures = new aiTexture*[nt]();
  scene->mNumTextures = nt;
  for (uint32_t k = 0; k < nt; ++k) {
    aiTexture* t = scene->mTextures[k] = new aiTexture();
    in.str(t->mFilename, "texture file name");
    const uint32_t w = in.take<uint32_t>("texture width");
    const uint32_t h = in.take<uint32_t>("texture height");
    in.raw(t->achFormatHint, 9, "texture format hint");
    t->achFormatHint[8] = '\0';
    t->mWidth = w;
    t->mHeight = h;
    if (h == 0) {
      if (w > in.left()) in.bad("texture " + std::to_string(k) + ": " + std::to_string(w) + " bytes: cut");
      // aiTexture frees pcData as aiTexel[]: allocate it so, in texels.
      t->pcData = new aiTexel[(size_t(w) + sizeof(aiTexel) - 1) / sizeof(aiTexel)];
      in.raw(t->pcData, w, "texture bytes");
    }
  }
  char end[4];
  in.raw(end, sizeof end, "end mark");
  if (std::memcmp(end, kEnd, sizeof end) != 0 || in.left() != 0) in.bad("end mark, or bytes after it");
  return scene;
}

}  // namespace xval
