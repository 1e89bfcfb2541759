// The scene dump that brings Assimp's read back from its child process
// (geometry/assimp_dump.h): every field the model loader reads survives
// bit for bit, on files of Debian's assimp-testmodels; a dump cut at any
// byte, or with bytes changed, is an error or a scene, never a crash.
#include <gtest/gtest.h>

#include <assimp/Importer.hpp>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "geometry/assimp_dump.h"
#include "geometry/model_file.h"

namespace xval {
namespace {

const std::string kModels = "/usr/share/assimp/models/";

const aiScene* readWithAssimp(Assimp::Importer& imp, const std::string& file) {
  // The loader's flags (model_file.cpp).
  imp.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
  return imp.ReadFile(file, aiProcess_ValidateDataStructure | aiProcess_Triangulate | aiProcess_SortByPType);
}

bool sameBytes(const void* a, const void* b, size_t n) {
  if (n == 0) return true;
  return a && b && std::memcmp(a, b, n) == 0;
}

void expectSameNode(const aiNode* a, const aiNode* b, const std::string& path) {
  ASSERT_NE(b, nullptr) << path;
  EXPECT_STREQ(a->mName.C_Str(), b->mName.C_Str()) << path;
  EXPECT_TRUE(sameBytes(&a->mTransformation, &b->mTransformation, sizeof(aiMatrix4x4))) << path;
  ASSERT_EQ(a->mNumMeshes, b->mNumMeshes) << path;
  EXPECT_TRUE(sameBytes(a->mMeshes, b->mMeshes, a->mNumMeshes * 4u)) << path;
  ASSERT_EQ(a->mNumChildren, b->mNumChildren) << path;
  for (unsigned c = 0; c < a->mNumChildren; ++c) {
    EXPECT_EQ(b->mChildren[c]->mParent, b) << path;
    expectSameNode(a->mChildren[c], b->mChildren[c], path + "/" + a->mChildren[c]->mName.C_Str());
  }
}

void expectSameScene(const aiScene& a, const aiScene& b, const std::string& file) {
  ASSERT_EQ(a.mNumMeshes, b.mNumMeshes) << file;
  for (unsigned k = 0; k < a.mNumMeshes; ++k) {
    const aiMesh& m = *a.mMeshes[k];
    const aiMesh& n = *b.mMeshes[k];
    const std::string where = file + " mesh " + std::to_string(k);
    EXPECT_STREQ(m.mName.C_Str(), n.mName.C_Str()) << where;
    EXPECT_EQ(m.mPrimitiveTypes, n.mPrimitiveTypes) << where;
    EXPECT_EQ(m.mMaterialIndex, n.mMaterialIndex) << where;
    ASSERT_EQ(m.mNumVertices, n.mNumVertices) << where;
    const size_t bytes = m.mNumVertices * sizeof(aiVector3D);
    EXPECT_TRUE(sameBytes(m.mVertices, n.mVertices, bytes)) << where;
    EXPECT_EQ(m.mNormals != nullptr, n.mNormals != nullptr) << where;
    if (m.mNormals) EXPECT_TRUE(sameBytes(m.mNormals, n.mNormals, bytes)) << where;
    EXPECT_EQ(m.mTextureCoords[0] != nullptr, n.mTextureCoords[0] != nullptr) << where;
    if (m.mTextureCoords[0]) EXPECT_TRUE(sameBytes(m.mTextureCoords[0], n.mTextureCoords[0], bytes)) << where;
    EXPECT_EQ(m.mNumUVComponents[0], n.mNumUVComponents[0]) << where;
    ASSERT_EQ(m.mNumFaces, n.mNumFaces) << where;
    for (unsigned f = 0; f < m.mNumFaces; ++f) {
      ASSERT_EQ(m.mFaces[f].mNumIndices, n.mFaces[f].mNumIndices) << where << " face " << f;
      ASSERT_TRUE(sameBytes(m.mFaces[f].mIndices, n.mFaces[f].mIndices, m.mFaces[f].mNumIndices * 4u))
          << where << " face " << f;
    }
  }
  ASSERT_NE(a.mRootNode, nullptr);
  expectSameNode(a.mRootNode, b.mRootNode, file + ": " + a.mRootNode->mName.C_Str());
  ASSERT_EQ(a.mNumMaterials, b.mNumMaterials) << file;
  for (unsigned k = 0; k < a.mNumMaterials; ++k)
    for (aiTextureType type : {aiTextureType_BASE_COLOR, aiTextureType_DIFFUSE}) {
      aiString pa, pb;
      unsigned ua = 0, ub = 0;
      const bool ga = a.mMaterials[k]->GetTextureCount(type) > 0 &&
                      a.mMaterials[k]->GetTexture(type, 0, &pa, nullptr, &ua) == aiReturn_SUCCESS;
      const bool gb = b.mMaterials[k]->GetTextureCount(type) > 0 &&
                      b.mMaterials[k]->GetTexture(type, 0, &pb, nullptr, &ub) == aiReturn_SUCCESS;
      EXPECT_EQ(ga, gb) << file << " material " << k << " type " << type;
      EXPECT_STREQ(pa.C_Str(), pb.C_Str()) << file << " material " << k;
      EXPECT_EQ(ua, ub) << file << " material " << k;
      if (ga && gb) EXPECT_EQ(a.GetEmbeddedTexture(pa.C_Str()) != nullptr, b.GetEmbeddedTexture(pb.C_Str()) != nullptr);
    }
  ASSERT_EQ(a.mNumTextures, b.mNumTextures) << file;
  for (unsigned k = 0; k < a.mNumTextures; ++k) {
    const aiTexture& t = *a.mTextures[k];
    const aiTexture& u = *b.mTextures[k];
    EXPECT_STREQ(t.mFilename.C_Str(), u.mFilename.C_Str()) << file;
    EXPECT_EQ(t.mWidth, u.mWidth) << file;
    EXPECT_EQ(t.mHeight, u.mHeight) << file;
    EXPECT_STREQ(t.achFormatHint, u.achFormatHint) << file;
    if (t.mHeight == 0) EXPECT_TRUE(sameBytes(t.pcData, u.pcData, t.mWidth)) << file;
  }
}

// Files with what the dump must carry: an embedded PNG (GLB), an external
// texture and a buffer (glTF), a node hierarchy of many meshes, OBJ
// materials, PLY's shared vertices, STL's face normals.
const char* kFiles[] = {
    "glTF2/BoxTextured-glTF-Binary/BoxTextured.glb",
    "glTF2/BoxTextured-glTF/BoxTextured.gltf",
    "glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb",
    "OBJ/spider.obj",
    "PLY/Wuson.ply",
    "STL/Spider_ascii.stl",
};

TEST(AssimpDump, EveryFieldTheLoaderReadsSurvives) {
  int read = 0;
  for (const char* name : kFiles) {
    const std::string file = kModels + name;
    ASSERT_TRUE(std::filesystem::exists(file)) << file << " (scripts/install-deps.sh installs assimp-testmodels)";
    Assimp::Importer imp;
    const aiScene* scene = readWithAssimp(imp, file);
    ASSERT_NE(scene, nullptr) << file << ": " << imp.GetErrorString();
    const std::string dump = writeAssimpDump(*scene);
    const auto back = readAssimpDump(dump, file, 256);
    expectSameScene(*scene, *back, file);
    ++read;
  }
  EXPECT_EQ(read, int(std::size(kFiles)));
}

TEST(AssimpDump, CutOrChangedDumpIsAnErrorNeverACrash) {
  const std::string file = kModels + "glTF2/BoxTextured-glTF-Binary/BoxTextured.glb";
  Assimp::Importer imp;
  const aiScene* scene = readWithAssimp(imp, file);
  ASSERT_NE(scene, nullptr) << imp.GetErrorString();
  const std::string dump = writeAssimpDump(*scene);
  ASSERT_GT(dump.size(), 1000u);
  // Every cut: an error naming the file and the field.
  for (size_t n = 0; n < dump.size(); ++n) {
    try {
      readAssimpDump(std::string_view(dump).substr(0, n), file, 256);
      ADD_FAILURE() << "a dump cut to " << n << " of " << dump.size() << " bytes was read";
      break;
    } catch (const ModelFileError& e) {
      const std::string m = e.what();
      if (m.find(file) != 0 || m.find("malformed at byte") == std::string::npos) {
        ADD_FAILURE() << m;
        break;
      }
    }
  }
  // Every byte of the structure (the texture's own bytes aside) set to
  // 0xff, one at a time: a scene or an error, and the sanitizers watch.
  int errors = 0, scenes = 0;
  for (size_t k = 0; k < dump.size(); k += 7) {
    std::string bad = dump;
    bad[k] = char(0xff);
    try {
      readAssimpDump(bad, file, 256);
      ++scenes;
    } catch (const ModelFileError&) {
      ++errors;
    }
  }
  EXPECT_GT(errors, 0);
  // Bytes after the end mark.
  EXPECT_THROW(readAssimpDump(dump + "x", file, 256), ModelFileError);
}

TEST(AssimpDump, DeepNodeTreeIsRefusedBeforeItIsBuilt) {
  // A chain of 300 nodes: aiNode's destructor recurses, so the rebuild
  // refuses depth 257 with the loader's message.
  aiScene scene;
  scene.mRootNode = new aiNode("n0");
  aiNode* at = scene.mRootNode;
  for (int k = 1; k < 300; ++k) {
    auto* c = new aiNode("n" + std::to_string(k));
    at->mChildren = new aiNode*[1]{c};
    at->mNumChildren = 1;
    c->mParent = at;
    at = c;
  }
  const std::string dump = writeAssimpDump(scene);
  try {
    readAssimpDump(dump, "deep.glb", 256);
    ADD_FAILURE() << "a 300-deep node tree was rebuilt with a limit of 256";
  } catch (const ModelFileError& e) {
    EXPECT_STREQ(e.what(), "deep.glb: node 'n257': deeper than 256 levels");
  }
  EXPECT_NO_THROW(readAssimpDump(dump, "deep.glb", 300));
}

}  // namespace
}  // namespace xval
