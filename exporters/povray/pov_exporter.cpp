#include "povray/pov_exporter.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <variant>
#include <fstream>
#include <optional>
#include <sstream>

#include "camera/camera.h"
#include "common/supersample.h"
#include "files/atomic_write.h"
#include "geometry/mesh.h"
#include "geometry/model_textures.h"
#include "geometry/scene_meshes.h"
#include "povray/flat_triangles.h"
#include "povray/gouraud_image.h"
#include "povray/pigment_tree.h"
#include "povray/pov_native.h"
#include "povray/pov_shading.h"
#include "povray/sdl.h"
#include "shading/shader.h"
#include "shading/surface_colour.h"
#include "texture/texture.h"

namespace xval {

using namespace pov;
using glm::dvec3;

namespace {

// blinn: POV-Ray's `specular ks roughness 1/n` (its exponent is 1/roughness).
std::string finish(double ks, double n, bool blinn = false) {
  std::string f = "finish { ambient 0 diffuse 0 emission 1";
  if (ks != 0.0 && blinn) f += " specular " + num(ks) + " roughness " + num(1.0 / n);
  else if (ks != 0.0) f += " phong " + num(ks) + " phong_size " + num(n);
  return f + " }";
}

void writeMesh(std::ostream& o, const TriangleMesh& m, const Scene& s, bool textured,
               const GouraudImage* gouraud, const std::string& gouraud_file,
               const std::string& material, bool double_illuminate) {
  o << "mesh2 {\n  vertex_vectors { " << m.positions.size();
  for (const auto& p : m.positions) o << ",\n    " << vec(p);
  o << "\n  }\n";
  // Gouraud needs no normals (its colours are per vertex) and flat shading
  // must not have them (POV-Ray then uses the face normal).
  if (s.shading == ShadingMode::Phong) {
    o << "  normal_vectors { " << m.normals.size();
    for (const auto& n : m.normals) o << ",\n    " << vec(n);
    o << "\n  }\n";
  }
  if (gouraud) {
    o << "  uv_vectors { " << gouraud->uvs.size();
    for (const auto& uv : gouraud->uvs) o << ",\n    " << vec(uv);
    o << "\n  }\n";
  } else if (textured) {
    o << "  uv_vectors { " << m.uvs.size();
    for (const auto& uv : m.uvs) o << ",\n    " << vec(glm::dvec2(uv.x, 1.0 - uv.y));
    o << "\n  }\n";
  }
  o << "  face_indices { " << m.triangles.size();
  for (const auto& t : m.triangles) o << ",\n    <" << t[0] << ", " << t[1] << ", " << t[2] << ">";
  o << "\n  }\n";
  if (gouraud) {
    o << "  uv_indices { " << m.triangles.size();
    for (size_t t = 0; t < m.triangles.size(); ++t)
      o << ",\n    <" << 3 * t << ", " << 3 * t + 1 << ", " << 3 * t + 2 << ">";
    o << "\n  }\n";
    o << "  texture { uv_mapping pigment { " << gouraud_file << " } " << finish(0, 0) << " }\n";
  } else {
    o << "  texture { " << material << " }\n";
  }
  o << "  no_shadow\n";
  if (double_illuminate) o << "  double_illuminate\n";
  o << "}\n";
}

// Phong shading writes the normals; a triangle POV-Ray takes as flat is
// shaded with its face normal (povray/flat_triangles.h): refused when that
// is not the normal the reference shades it with.
void refuseFlatTrianglesOffFace(const Scene& scene, const SceneMeshes& sm) {
  for (size_t i = 0; i < sm.meshes.size(); ++i) {
    const PovFlatTriangles f = povFlatTriangles(sm.meshes[i]);
    if (f.off_face == 0) continue;
    const SceneObject& object = scene.objects.at(sm.object[i]);
    const MeshFile* file = std::get_if<MeshFile>(&object.shape);
    char angle[64];
    std::snprintf(angle, sizeof angle, "%.3g rad (%.3g degrees)", f.max_angle_rad, f.max_angle_rad * 180.0 / M_PI);
    throw ExportError(
        "POV-Ray export: " + (file ? "model file " + file->path.string() : std::string("a built-in shape")) +
        ", mesh " + std::to_string(i) + ": " + std::to_string(f.off_face) + " of its " +
        std::to_string(sm.meshes[i].triangles.size()) +
        " triangles have three equal normals, which POV-Ray's mesh2 takes as a flat triangle and shades with "
        "its face normal instead, and their normals are up to " + angle + " from that face normal (triangle " +
        std::to_string(f.worst) + "; the bound is " + num(kPovFlatNormalBoundRad) +
        " rad): POV-Ray would shade them with another normal than the reference renderer "
        "(exporters/povray/flat_triangles.h)");
  }
}

}  // namespace

PovExport exportPov(const Scene& input, const std::filesystem::path& dir, const std::string& output_name,
                    PovTier tier) {
  const bool native = tier == PovTier::Native;
  // Texture source "model": one object, so one mesh2 and texture, per
  // primitive (geometry/model_textures.h).
  const Scene scene = resolveModelTextures(input);
  // render.spp = n^2: n x n sub-pixels, one sample through each centre
  // (common/supersample.h); POV-Ray's own antialiasing stays off, as it
  // averages unsaturated samples.
  const SubpixelGrid grid = subpixelGrid(scene);
  refuseTrilinear(scene, "POV-Ray export",
                  "POV-Ray's image_map has no mip-maps (it filters one level, by interpolate 2 at most) and a "
                  "traced ray carries no pixel footprint to choose a level from");
  refuseUnnormalizedNormal(scene, "POV-Ray export",
                           "POV-Ray normalises a smooth triangle's interpolated normal before any pigment or "
                           "finish sees it");
  std::filesystem::create_directories(dir);
  PovExport ex;
  ex.dir = dir;
  ex.pov = dir / "scene.pov";
  ex.ini = dir / "scene.ini";
  ex.output_name = output_name;
  ex.grid = grid;

  if (native) checkNativeScene(scene);
  const SceneMeshes sm = sceneMeshes(scene);
  const std::vector<TriangleMesh>& meshes = sm.meshes;
  if (scene.shading == ShadingMode::Phong) refuseFlatTrianglesOffFace(scene, sm);
  // One texture, pigment tree and finish per material slot (export_common.h):
  // slot 0, the scene's, keeps the plain names (XvalMaterial, texture.png).
  const MaterialSlots slots = materialSlots(scene);
  const bool several = hasObjectMaterials(scene);
  std::vector<std::optional<Texture>> textures(slots.materials.size());
  for (size_t k = 0; k < slots.materials.size(); ++k)
    if (slots.used[k])
      textures[k] = exportTexture(*slots.materials[k], dir, exportedTextureName(k),
                                  k == 0 ? "material" : "objects[" + std::to_string(k - 1) + "].material");
  auto suffix = [](size_t k) { return k == 0 ? std::string() : "_object" + std::to_string(k - 1); };

  std::ostringstream o;
  o << "// Generated by xval export pov. Scene: " << commentSafe(scene.name) << "\n"
    << "// Render from this folder: povray scene.ini (see README.txt).\n"
    << "#version 3.7;\n"
    << "global_settings { assumed_gamma 1.0 max_trace_level 1"
    << (native ? " ambient_light rgb " + vec(nativeLights(scene).ambient_light) : std::string()) << " }\n"
    << "background { rgbt <0, 0, 0, 1> }\n";
  CameraRays cam(scene.camera);
  o << "camera { perspective location " << vec(cam.origin) << "\n  direction " << vec(cam.forward)
    << "\n  right " << vec(cam.right * (2.0 * cam.tan_half_fov * cam.aspect)) << "\n  up "
    << vec(cam.up * (2.0 * cam.tan_half_fov)) << " }\n";

  // Per slot: the finish's specular light sources. With several materials
  // their colours differ per material (course: C Lc, YIQ: Y(Lc)), so each
  // object is a light_group of its own material's light sources with
  // global_lights off; with one material they are the scene's.
  std::vector<Specular> sps(slots.materials.size());
  if (native) {
    // POV-Ray's own finish (pov_native.h): the light sources once, and per
    // material its pigment (the texture or the base colour) and finish.
    o << "// Native tier: POV-Ray's own finish (xval docs/povray-export.md, \"Native tier\").\n";
    for (const auto& ls : nativeLights(scene).sources) o << lightSourceSdl(ls) << "\n";
    for (size_t k = 0; k < slots.materials.size(); ++k) {
      if (!slots.used[k]) continue;
      const Material& mat = *slots.materials[k];
      const std::string pigment =
          textures[k] ? "uv_mapping pigment { image_map { png \"" + exportedTextureName(k) + "\" gamma 1.0" +
                            (mat.texture->filter == TextureFilter::Bilinear ? " interpolate 2" : "") + " } }"
                      : "pigment { rgb " + vec(mat.base_color) + " }";
      o << "#declare XvalMaterial" << suffix(k) << " = texture { " << pigment << "\n  "
        << nativeFinishSdl(nativeFinish(mat)) << " }\n";
    }
  } else if (scene.shading == ShadingMode::Gouraud) {
    // Colours computed per vertex by the reference shader; POV-Ray
    // interpolates them across each triangle.
    o << "// Gouraud: per-vertex colours, interpolated by POV-Ray.\n";
  } else {
    for (size_t k = 0; k < slots.materials.size(); ++k) {
      if (!slots.used[k]) continue;
      const Material& mat = *slots.materials[k];
      const std::string sx = suffix(k), tex_fn = "XvalTexture" + sx;
      if (several) o << "// The material of " << (k == 0 ? std::string("the scene") : "objects[" + std::to_string(k - 1) + "]") << ".\n";
      if (textures[k])
        o << "#declare " << tex_fn << " = function { pigment { image_map { png \"" << exportedTextureName(k)
          << "\" gamma 1.0" << (mat.texture->filter == TextureFilter::Bilinear ? " interpolate 2" : "")
          << " } } }\n";
      const PovShading shading = povShading(scene, mat);
      Specular& sp = sps[k];
      sp = shading.specular;
      if (!several)
        for (const auto& ls : sp.light_sources) o << lightSourceSdl(ls) << "\n";
      o << "#declare XvalEmission" << sx << " =\n" << toSdl(shading.emission, 1, tex_fn) << "\n";
      // The texture colour as a filter layer on top (pov_shading.h), if any.
      std::string top;
      if (shading.texture_filter_layer) {
        o << "#declare XvalFilter" << sx << " = texture {\n"
          << filterLayerSdl(*affine(glm::dmat3(1.0), dvec3(0.0)), 1, tex_fn)
          << "\n  finish { ambient 0 diffuse 0 emission 0 }\n}\n";
        top = " texture { XvalFilter" + sx + " }";
      }
      if (sp.att_texture_map) {
        // texture_map entries cannot be layered in place: declared layers.
        o << "#declare XvalLayer0" << sx << " = texture { pigment { XvalEmission" << sx << " } " << finish(0, 0)
          << " }" << top << "\n#declare XvalLayer1" << sx << " = texture { pigment { XvalEmission" << sx
          << " } " << finish(sp.ks, sp.shininess, sp.blinn) << " }" << top << "\n#declare XvalMaterial" << sx
          << " = texture { " << patternSdl(*sp.att_texture_map) << "\n  texture_map { [0 XvalLayer0" << sx
          << "] [1 XvalLayer1" << sx << "] }\n}\n";
      } else {
        o << "#declare XvalMaterial" << sx << " = texture { pigment { XvalEmission" << sx << " } "
          << finish(sp.ks, sp.shininess, sp.blinn) << " }" << top << "\n";
      }
    }
  }
  for (size_t k = 0; k < meshes.size(); ++k) {
    const TriangleMesh& m = meshes[k];
    const size_t slot = slots.object_slot[sm.object[k]];
    const Material& mat = *slots.materials[slot];
    const Texture* texture = textures[slot] ? &*textures[slot] : nullptr;
    if (scene.shading == ShadingMode::Gouraud) {
      Shader<double> shader(mat, scene.lights);
      SurfaceColour<double> sc(mat, texture);
      GouraudImage g = gouraudImage(m, gouraudVertexColours(shader, m, sc, cam.origin));
      const std::string name = "XvalGouraud" + std::to_string(k);
      o << gouraudPigment(gouraudCodes(g), dir, "gouraud_" + std::to_string(k), name);
      writeMesh(o, m, scene, texture != nullptr, &g, name, "", false);
    } else if (native) {
      writeMesh(o, m, scene, texture != nullptr, nullptr, "", "XvalMaterial" + suffix(slot), false);
    } else {
      if (several) {
        o << "light_group {\n";
        for (const auto& ls : sps[slot].light_sources) o << lightSourceSdl(ls) << "\n";
      }
      writeMesh(o, m, scene, texture != nullptr, nullptr, "", "XvalMaterial" + suffix(slot),
                sps[slot].doubleIlluminate());
      if (several) o << "global_lights off\n}\n";
    }
  }
  writeFileAtomically(ex.pov, o.str());
  {
    std::ostringstream f;
    f << "; POV-Ray 3.7 options for scene.pov. Run from this folder: povray scene.ini\n"
      << "Input_File_Name=scene.pov\nOutput_File_Name=" << ex.output_name << "\n"
      << "Width=" << grid.width << "\nHeight=" << grid.height << "\n"
      << "; one sample through each pixel centre"
      << (grid.n > 1 ? ": " + std::to_string(grid.n) + " x " + std::to_string(grid.n) +
                           " sub-pixels of each scene pixel (render.spp = " + std::to_string(scene.render.spp) +
                           "), box-filtered afterwards"
                     : std::string())
      << "\nAntialias=Off\n"
      << "; 16-bit PNG, linear (no transfer function), alpha = hit mask\n"
      << "Output_File_Type=N\nBits_Per_Color=16\nFile_Gamma=1.0\nOutput_Alpha=On\n"
      << "Display=Off\nPause_When_Done=Off\nVerbose=Off\n";
    writeFileAtomically(ex.ini, f.str());
  }
  {
    std::ostringstream f;
    f << "Exported by xval from scene: " << commentSafe(scene.name) << "\n\n"
      << "Render with POV-Ray 3.7 from this folder:\n\n    povray scene.ini\n\n"
      << "or, equivalently:\n\n    povray +Iscene.pov +O" << ex.output_name << " +W"
      << grid.width << " +H" << grid.height
      << " -A +FN16 +UA File_Gamma=1.0 -D\n\n"
      << "The output holds the model's values linearly (round(v * 65535)), alpha = hit mask.\n";
    if (grid.n > 1)
      f << "\nThe scene asks for " << scene.render.spp << " samples per pixel (render.spp): the output is\n"
        << grid.width << "x" << grid.height << ", " << grid.n << " x " << grid.n << " samples for each of the scene's "
        << scene.camera.width << "x" << scene.camera.height << " pixels,\none through each sub-pixel centre. "
        << "The scene's image is the mean of each " << grid.n << " x " << grid.n << " block\n"
        << "(colour and alpha; the PNG already holds each sample clipped to [0, 1]).\n";
    writeFileAtomically(dir / "README.txt", f.str());
  }
  return ex;
}

}  // namespace xval
