#include "gltf/gltf_exporter.h"

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <numbers>
#include <optional>

#include "camera/camera.h"
#include "common/supersample.h"
#include "geometry/degenerate_triangles.h"
#include "geometry/float_rounding.h"
#include "geometry/mesh.h"
#include "geometry/model_textures.h"
#include "geometry/scene_meshes.h"
#include "common/export_common.h"
#include "files/atomic_write.h"
#include "gltf/shading_constants.h"
#include "scene_file/scene_writer.h"
#include "shading/flat_normals.h"
#include "shading/shader.h"
#include "shading/surface_colour.h"
#include "texture/texture.h"

namespace xval {

namespace {

constexpr int kFloat = TINYGLTF_COMPONENT_TYPE_FLOAT;
constexpr int kUInt = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;

// Appends raw bytes to buffer 0 (4-byte aligned) and returns a view.
int addView(tinygltf::Model& m, const void* data, size_t bytes, int target) {
  auto& buf = m.buffers[0].data;
  while (buf.size() % 4) buf.push_back(0);
  tinygltf::BufferView v;
  v.buffer = 0;
  v.byteOffset = buf.size();
  v.byteLength = bytes;
  if (target) v.target = target;
  const auto* p = static_cast<const unsigned char*>(data);
  buf.insert(buf.end(), p, p + bytes);
  m.bufferViews.push_back(v);
  return int(m.bufferViews.size() - 1);
}

// A float32 VEC3 accessor; `target` 0 for one that is no vertex attribute.
int addVec3(tinygltf::Model& m, const std::vector<glm::dvec3>& values, bool minmax,
            int target = TINYGLTF_TARGET_ARRAY_BUFFER) {
  std::vector<float> f;
  f.reserve(values.size() * 3);
  std::vector<double> lo(3, 1e300), hi(3, -1e300);
  for (const auto& v : values)
    for (int k = 0; k < 3; ++k) {
      float x = nearestFloat(v[k]);  // min/max must be the stored floats
      f.push_back(x);
      lo[k] = std::min(lo[k], double(x));
      hi[k] = std::max(hi[k], double(x));
    }
  tinygltf::Accessor a;
  a.bufferView = addView(m, f.data(), f.size() * sizeof(float), target);
  a.componentType = kFloat;
  a.count = values.size();
  a.type = TINYGLTF_TYPE_VEC3;
  if (minmax) a.minValues = lo, a.maxValues = hi;
  m.accessors.push_back(a);
  return int(m.accessors.size() - 1);
}

int addVec2(tinygltf::Model& m, const std::vector<glm::dvec2>& values) {
  std::vector<float> f;
  for (const auto& v : values) f.push_back(nearestFloat(v.x)), f.push_back(nearestFloat(v.y));
  tinygltf::Accessor a;
  a.bufferView = addView(m, f.data(), f.size() * sizeof(float), TINYGLTF_TARGET_ARRAY_BUFFER);
  a.componentType = kFloat;
  a.count = values.size();
  a.type = TINYGLTF_TYPE_VEC2;
  m.accessors.push_back(a);
  return int(m.accessors.size() - 1);
}

int addIndices(tinygltf::Model& m, const std::vector<glm::u32vec3>& tris) {
  std::vector<uint32_t> idx;
  for (const auto& t : tris) idx.insert(idx.end(), {t[0], t[1], t[2]});
  tinygltf::Accessor a;
  a.bufferView =
      addView(m, idx.data(), idx.size() * sizeof(uint32_t), TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
  a.componentType = kUInt;
  a.count = idx.size();
  a.type = TINYGLTF_TYPE_SCALAR;
  m.accessors.push_back(a);
  return int(m.accessors.size() - 1);
}

// Unit quaternion (x, y, z, w) of the rotation with the given columns.
std::vector<double> quaternion(glm::dvec3 x, glm::dvec3 y, glm::dvec3 z) {
  glm::dmat3 r(x, y, z);
  glm::dquat q = glm::quat_cast(r);
  q = glm::normalize(q);
  return {q.x, q.y, q.z, q.w};
}

// A node whose local -Z points along `dir`.
std::vector<double> lookAlong(glm::dvec3 dir) {
  glm::dvec3 z = -glm::normalize(dir);
  glm::dvec3 hint = std::abs(z.y) > 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
  glm::dvec3 x = glm::normalize(glm::cross(hint, z));
  glm::dvec3 y = glm::cross(z, x);
  return quaternion(x, y, z);
}

tinygltf::Value attenuationExtras(const Attenuation& a) {
  tinygltf::Value::Object o;
  o["xval_attenuation"] = tinygltf::Value(tinygltf::Value::Array{
      tinygltf::Value(a.constant), tinygltf::Value(a.linear), tinygltf::Value(a.quadratic)});
  return tinygltf::Value(o);
}

}  // namespace

GltfExport exportGltf(const Scene& input, const std::filesystem::path& dir) {
  // Texture source "model": one object, so one mesh and material, per
  // primitive (geometry/model_textures.h).
  const Scene scene = resolveModelTextures(input);
  // The resolution Blender renders: n W x n H for render.spp = n^2, one
  // sample through each pixel centre (common/supersample.h); checked first.
  const SubpixelGrid grid = subpixelGrid(scene);
  std::filesystem::create_directories(dir);
  GltfExport ex{dir / kGltfFileName, dir};
  tinygltf::Model m;
  m.asset.version = "2.0";
  m.asset.generator = "xval export gltf";
  m.buffers.resize(1);
  m.buffers[0].uri = "scene.bin";

  // One glTF material per material slot (export_common.h): slot 0 the
  // scene's, then each object's own; each with its texture copy and its
  // shading constants in the material's extras.
  const MaterialSlots slots = materialSlots(scene);
  std::vector<std::optional<Texture>> textures(slots.materials.size());
  std::vector<int> gltf_material(slots.materials.size(), -1);
  for (size_t k = 0; k < slots.materials.size(); ++k) {
    if (!slots.used[k]) continue;
    const Material& material = *slots.materials[k];
    textures[k] = exportTexture(material, dir, exportedTextureName(k),
                                k == 0 ? "material" : "objects[" + std::to_string(k - 1) + "].material");
    tinygltf::Material mat;
    mat.name = k == 0 ? "xval_material" : "xval_material_object" + std::to_string(k - 1);
    mat.doubleSided = true;  // the paper's shader: CullMode None
    mat.pbrMetallicRoughness.metallicFactor = 0.0;
    if (textures[k]) {
      tinygltf::Image img;
      img.uri = exportedTextureName(k);
      img.mimeType = "image/png";
      m.images.push_back(img);
      tinygltf::Sampler smp;
      const bool nearest = material.texture->filter == TextureFilter::Nearest;
      smp.magFilter = nearest ? TINYGLTF_TEXTURE_FILTER_NEAREST : TINYGLTF_TEXTURE_FILTER_LINEAR;
      smp.minFilter = nearest ? TINYGLTF_TEXTURE_FILTER_NEAREST
                      : material.texture->filter == TextureFilter::Trilinear
                          ? TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR
                          : TINYGLTF_TEXTURE_FILTER_LINEAR;
      smp.wrapS = smp.wrapT = TINYGLTF_TEXTURE_WRAP_REPEAT;
      m.samplers.push_back(smp);
      tinygltf::Texture t;
      t.source = int(m.images.size() - 1);
      t.sampler = int(m.samplers.size() - 1);
      m.textures.push_back(t);
      mat.pbrMetallicRoughness.baseColorTexture.index = int(m.textures.size() - 1);
    } else {
      glm::dvec3 b = glm::clamp(material.base_color, 0.0, 1.0);
      mat.pbrMetallicRoughness.baseColorFactor = {b.x, b.y, b.z, 1.0};
    }
    tinygltf::Value::Object me;
    me["xval_shading"] = tinygltf::Value(shadingConstants(scene, material).dump());
    me["xval_texture"] = textures[k] ? tinygltf::Value(exportedTextureName(k)) : tinygltf::Value();
    mat.extras = tinygltf::Value(me);
    m.materials.push_back(mat);
    gltf_material[k] = int(m.materials.size() - 1);
  }

  tinygltf::Scene gs;
  const CameraRays cam(scene.camera);
  const SceneMeshes sm = sceneMeshes(scene);
  const std::vector<TriangleMesh>& meshes = sm.meshes;
  for (size_t k = 0; k < meshes.size(); ++k) {
    const TriangleMesh& mesh = meshes[k];
    // Blender's importer drops such triangles (geometry/
    // degenerate_triangles.h; the model loader drops them before any
    // renderer sees a mesh): one left here would give Blender other
    // triangles than every other renderer.
    if (const DroppedTriangles d = dropDegenerateTriangles(mesh.triangles); d.dropped() > 0)
      throw ExportError("glTF export for Blender: mesh " + std::to_string(k) + " (object " +
                        std::to_string(sm.object[k]) + ") has " + std::to_string(d.repeated_index) +
                        " triangles with a repeated vertex index and " + std::to_string(d.duplicates) +
                        " repeating an earlier triangle's three vertices, which Blender's importer drops "
                        "(geometry/degenerate_triangles.h): Blender would not render the same triangles");
    const size_t slot = slots.object_slot[sm.object[k]];
    const Material& material = *slots.materials[slot];
    const Texture* texture = textures[slot] ? &*textures[slot] : nullptr;
    tinygltf::Primitive prim;
    prim.mode = TINYGLTF_MODE_TRIANGLES;
    prim.material = gltf_material[slot];
    prim.attributes["POSITION"] = addVec3(m, mesh.positions, true);
    prim.attributes["NORMAL"] = addVec3(m, mesh.normals, false);
    if (texture) prim.attributes["TEXCOORD_0"] = addVec2(m, mesh.uvs);
    if (scene.shading == ShadingMode::Gouraud) {
      const Shader<double> shader(material, scene.lights);
      SurfaceColour<double> sc(material, texture);
      prim.attributes["_XVAL_GOURAUD"] =
          addVec3(m, gouraudVertexColours(shader, mesh, sc, cam.origin), false);
    }
    prim.indices = addIndices(m, mesh.triangles);
    if (scene.shading == ShadingMode::Flat) {
      // One normal per triangle (flat_normals.h), for the harness's face
      // attribute: the primitive's extras name the accessor.
      tinygltf::Value::Object pe;
      pe["xval_face_normals"] = tinygltf::Value(addVec3(m, flatNormals(mesh), false, 0));
      prim.extras = tinygltf::Value(pe);
    }
    tinygltf::Mesh gm;
    gm.name = "xval_mesh_" + std::to_string(k);
    gm.primitives.push_back(prim);
    m.meshes.push_back(gm);
    tinygltf::Node n;
    n.name = "xval_object_" + std::to_string(k);
    n.mesh = int(m.meshes.size() - 1);
    m.nodes.push_back(n);
    gs.nodes.push_back(int(m.nodes.size() - 1));
  }

  tinygltf::Camera c;
  c.type = "perspective";
  c.name = "xval_camera";
  c.perspective.yfov = scene.camera.fov_y_deg * std::numbers::pi / 180.0;
  c.perspective.aspectRatio = double(scene.camera.width) / scene.camera.height;
  c.perspective.znear = 1e-6 * std::max(1.0, glm::length(scene.camera.position));
  c.perspective.zfar = 1e9 * std::max(1.0, glm::length(scene.camera.position));
  m.cameras.push_back(c);
  tinygltf::Node cn;
  cn.name = "xval_camera";
  cn.camera = 0;
  cn.translation = {cam.origin.x, cam.origin.y, cam.origin.z};
  cn.rotation = quaternion(cam.right, cam.up, -cam.forward);
  m.nodes.push_back(cn);
  gs.nodes.push_back(int(m.nodes.size() - 1));

  for (const Light& l : scene.lights) {
    tinygltf::Light gl;
    tinygltf::Node ln;
    glm::dvec3 colour;
    if (auto* p = std::get_if<PointLight>(&l)) {
      gl.type = "point";
      colour = p->color;
      ln.translation = {p->position.x, p->position.y, p->position.z};
      gl.extras = attenuationExtras(p->attenuation);
    } else if (auto* s = std::get_if<SpotLight>(&l)) {
      gl.type = "spot";
      colour = s->color;
      ln.translation = {s->position.x, s->position.y, s->position.z};
      ln.rotation = lookAlong(s->direction);
      gl.spot.outerConeAngle = s->cutoff_deg * std::numbers::pi / 180.0;
      gl.spot.innerConeAngle = gl.spot.outerConeAngle * (1.0 - 1e-6);
      gl.extras = attenuationExtras(s->attenuation);
    } else if (auto* d = std::get_if<DirectionalLight>(&l)) {
      gl.type = "directional";
      colour = d->color;
      ln.rotation = lookAlong(d->direction);
    } else {
      continue;  // ambient: in the scene extras only
    }
    double peak = std::max({colour.x, colour.y, colour.z});
    gl.intensity = peak;
    gl.color = peak > 0 ? std::vector<double>{colour.x / peak, colour.y / peak, colour.z / peak}
                        : std::vector<double>{1.0, 1.0, 1.0};
    gl.name = "xval_light_" + std::to_string(m.lights.size());
    m.lights.push_back(gl);
    ln.name = gl.name;
    tinygltf::Value::Object ext;
    ext["light"] = tinygltf::Value(int(m.lights.size() - 1));
    ln.extensions["KHR_lights_punctual"] = tinygltf::Value(ext);
    m.nodes.push_back(ln);
    gs.nodes.push_back(int(m.nodes.size() - 1));
  }

  // The scene as written, every texture path replaced by its copy's name
  // (no user path is passed on).
  Scene written = scene;
  if (written.material.texture) written.material.texture->path = exportedTextureName(0);
  for (size_t k = 0; k < written.objects.size(); ++k)
    if (written.objects[k].material && written.objects[k].material->texture)
      written.objects[k].material->texture->path = exportedTextureName(k + 1);
  tinygltf::Value::Object extras;
  extras["xval"] = tinygltf::Value(sceneToJson(written).dump());
  extras["xval_shading"] = tinygltf::Value(shadingConstants(scene).dump());
  extras["xval_render"] = tinygltf::Value(
      nlohmann::json{{"width", grid.width}, {"height", grid.height}, {"subpixels_per_side", grid.n}}.dump());
  gs.extras = tinygltf::Value(extras);
  gs.name = "xval_scene";
  m.scenes.push_back(gs);
  m.defaultScene = 0;
  if (!m.lights.empty()) m.extensionsUsed.push_back("KHR_lights_punctual");

  // TinyGLTF writes scene.gltf and, beside it, scene.bin: both whole or
  // neither, scene.gltf last.
  writeFilesAtomically(dir, {"scene.bin", "scene.gltf"}, [&](const std::filesystem::path& tmp) {
    tinygltf::TinyGLTF writer;
    if (!writer.WriteGltfSceneToFile(&m, (tmp / "scene.gltf").string(), /*embedImages=*/false,
                                     /*embedBuffers=*/false, /*prettyPrint=*/true,
                                     /*writeBinary=*/false))
      throw ExportError("tinygltf could not write the glTF");
    // TinyGLTF does not check its writes: check what it left (a full disk
    // gives a short scene.bin or a truncated scene.gltf).
    std::error_code ec;
    const auto bin = std::filesystem::file_size(tmp / "scene.bin", ec);
    if (ec || bin != m.buffers[0].data.size())
      throw ExportError("scene.bin: " + std::to_string(ec ? 0 : bin) + " bytes written, expected " +
                        std::to_string(m.buffers[0].data.size()));
    std::ifstream in(tmp / "scene.gltf");
    if (!nlohmann::json::accept(in)) throw ExportError("scene.gltf: written incompletely (not valid JSON)");
    return true;
  });
  return ex;
}

}  // namespace xval
