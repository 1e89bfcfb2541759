#include "povray/pov_exporter.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <fstream>
#include <optional>
#include <sstream>

#include "camera/camera.h"
#include "geometry/mesh.h"
#include "image/image.h"
#include "povray/pigment_tree.h"
#include "povray/pov_shading.h"
#include "povray/sdl.h"
#include "shading/models.h"
#include "shading/shader.h"
#include "shading/surface_colour.h"
#include "texture/texture.h"

namespace xval {

using namespace pov;
using glm::dvec3;

namespace {

std::string finish(double ks, double n) {
  std::string f = "finish { ambient 0 diffuse 0 emission 1";
  if (ks != 0.0) f += " phong " + num(ks) + " phong_size " + num(n);
  return f + " }";
}

// Gouraud in POV-Ray: an image holding, per triangle, a 2x2 texel block
// (c0, c1 / c2, c1 + c2 - c0) and uv at the three texel centres of c0, c1,
// c2. Bilinear interpolation (`interpolate 2`) over such a block is the
// affine function c0 + s (c1 - c0) + t (c2 - c0), and POV-Ray's mesh uv is
// barycentric, so the colour is the exact barycentric interpolation of the
// vertex colours. Measured alternatives: a mesh2 texture_list is up to
// 230/65535 off along triangle edges (POV-Ray weights three textures with
// single-precision smooth-triangle distances); an OpenEXR image_map is read
// as half floats (up to 16/65535 off). So the colours go into two 16-bit
// PNGs, coarse and fine: c = lo + range (hi16 + lo16 / 65535) / 65535 per
// channel, exact to ~1e-9.
struct GouraudImage {
  int width = 0, height = 0;
  std::vector<float> rgb;
  std::vector<glm::dvec2> uvs;  // 3 per triangle, POV-Ray's v (bottom-up)
};

GouraudImage gouraudImage(const TriangleMesh& m, const std::vector<dvec3>& colours) {
  GouraudImage g;
  const size_t n = m.triangles.size();
  const int cols = std::max(1, int(std::ceil(std::sqrt(double(n)))));
  const int rows = int((n + cols - 1) / cols);
  g.width = 2 * cols, g.height = 2 * rows;
  g.rgb.assign(size_t(g.width) * g.height * 3, 0.0f);
  auto put = [&g](int x, int y, dvec3 c) {
    for (int k = 0; k < 3; ++k) g.rgb[(size_t(y) * g.width + x) * 3 + k] = float(c[k]);
  };
  auto centre = [&g](int x, int y) {
    return glm::dvec2((x + 0.5) / g.width, 1.0 - (y + 0.5) / g.height);
  };
  for (size_t t = 0; t < n; ++t) {
    const int x = 2 * int(t % cols), y = 2 * int(t / cols);
    const dvec3 c0 = colours[m.triangles[t][0]], c1 = colours[m.triangles[t][1]],
                c2 = colours[m.triangles[t][2]];
    put(x, y, c0), put(x + 1, y, c1), put(x, y + 1, c2), put(x + 1, y + 1, c1 + c2 - c0);
    g.uvs.push_back(centre(x, y));
    g.uvs.push_back(centre(x + 1, y));
    g.uvs.push_back(centre(x, y + 1));
  }
  return g;
}

// Writes the two PNGs of a GouraudImage and returns SDL declaring the
// pigment `name` that reads them back as the colours.
std::string gouraudPigment(const GouraudImage& g, const std::filesystem::path& dir,
                           const std::string& stem, const std::string& name) {
  dvec3 lo(std::numeric_limits<double>::infinity()), hi(-lo);
  for (size_t i = 0; i < g.rgb.size(); ++i) {
    lo[i % 3] = std::min(lo[i % 3], double(g.rgb[i]));
    hi[i % 3] = std::max(hi[i % 3], double(g.rgb[i]));
  }
  dvec3 range = hi - lo;
  for (int c = 0; c < 3; ++c)
    if (!(range[c] > 0)) range[c] = 1.0;
  Image coarse(g.width, g.height, false), fine(g.width, g.height, false);
  for (size_t i = 0; i < size_t(g.width) * g.height; ++i) {
    for (int c = 0; c < 3; ++c) {
      double q = std::clamp((double(g.rgb[i * 3 + c]) - lo[c]) / range[c], 0.0, 1.0) * 65535.0;
      double a = std::min(std::floor(q), 65535.0);
      double b = std::round((q - a) * 65535.0);
      coarse.rgba[i * 4 + c] = float(a / 65535.0);
      fine.rgba[i * 4 + c] = float(b / 65535.0);
    }
    coarse.rgba[i * 4 + 3] = fine.rgba[i * 4 + 3] = 1.0f;
  }
  writeImage(coarse, dir / (stem + "_coarse.png"));
  writeImage(fine, dir / (stem + "_fine.png"));
  std::ostringstream o;
  o << "#declare " << name << "Coarse = function { pigment { image_map { png \"" << stem
    << "_coarse.png\" gamma 1.0 interpolate 2 } } }\n"
    << "#declare " << name << "Fine = function { pigment { image_map { png \"" << stem
    << "_fine.png\" gamma 1.0 interpolate 2 } } }\n"
    << "#declare " << name << " = pigment { average pigment_map {\n"
    << "  [1 rgb " << vec(lo * 7.0) << "]\n";
  static const char* ch[3] = {"red", "green", "blue"};
  for (int c = 0; c < 3; ++c) {
    dvec3 e(0.0);
    e[c] = 7.0 * range[c];
    o << "  [1 function { " << name << "Coarse(x, y, z)." << ch[c] << " } colour_map { [0 rgb 0] [1 rgb "
      << vec(e) << "] }]\n";
    o << "  [1 function { " << name << "Fine(x, y, z)." << ch[c] << " } colour_map { [0 rgb 0] [1 rgb "
      << vec(e / 65535.0) << "] }]\n";
  }
  o << "} }\n";
  return o.str();
}

void writeMesh(std::ostream& o, const TriangleMesh& m, const Scene& s, bool textured,
               const GouraudImage* gouraud, const std::string& gouraud_file,
               bool double_illuminate) {
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
    o << "  texture { XvalMaterial }\n";
  }
  o << "  no_shadow\n";
  if (double_illuminate) o << "  double_illuminate\n";
  o << "}\n";
}

}  // namespace

PovExport exportPov(const Scene& scene, const std::filesystem::path& dir) {
  if (scene.render.spp != 1)
    throw ExportError("render.spp = " + std::to_string(scene.render.spp) +
                      ": POV-Ray's antialiasing averages unsaturated samples and the reference "
                      "renderer saturates each sample; export at spp 1");
  std::filesystem::create_directories(dir);
  PovExport ex;
  ex.dir = dir;
  ex.pov = dir / "scene.pov";
  ex.ini = dir / "scene.ini";

  std::vector<TriangleMesh> meshes;
  for (const auto& o : scene.objects) meshes.push_back(tessellate(o));
  const std::optional<Texture> texture = exportTexture(scene, dir);
  const bool textured = texture.has_value();

  std::ostringstream o;
  o << "// Generated by xval export pov. Scene: " << commentSafe(scene.name) << "\n"
    << "// Render from this folder: povray scene.ini (see README.txt).\n"
    << "#version 3.7;\n"
    << "global_settings { assumed_gamma 1.0 max_trace_level 1 }\n"
    << "background { rgbt <0, 0, 0, 1> }\n";
  CameraRays cam(scene.camera);
  o << "camera { perspective location " << vec(cam.origin) << "\n  direction " << vec(cam.forward)
    << "\n  right " << vec(cam.right * (2.0 * cam.tan_half_fov * cam.aspect)) << "\n  up "
    << vec(cam.up * (2.0 * cam.tan_half_fov)) << " }\n";

  std::optional<std::vector<dvec3>> vc;
  Specular sp;
  if (scene.shading == ShadingMode::Gouraud) {
    // Colours computed per vertex by the reference shader; POV-Ray
    // interpolates them across each triangle.
    o << "// Gouraud: per-vertex colours, interpolated by POV-Ray.\n";
  } else {
    if (textured)
      o << "#declare XvalTexture = function { pigment { image_map { png \"texture.png\" gamma 1.0"
        << (scene.material.texture->filter == TextureFilter::Bilinear ? " interpolate 2" : "")
        << " } } }\n";
    const PovShading shading = povShading(scene);
    sp = shading.specular;
    for (const auto& ls : sp.light_sources) o << lightSourceSdl(ls) << "\n";
    o << "#declare XvalEmission =\n" << toSdl(shading.emission, 1) << "\n";
    if (sp.att_texture_map) {
      o << "#declare XvalMaterial = texture { " << patternSdl(*sp.att_texture_map)
        << "\n  texture_map {\n"
        << "    [0 pigment { XvalEmission } " << finish(0, 0) << "]\n"
        << "    [1 pigment { XvalEmission } " << finish(sp.ks, sp.shininess) << "]\n  }\n}\n";
    } else {
      o << "#declare XvalMaterial = texture { pigment { XvalEmission } "
        << finish(sp.ks, sp.shininess) << " }\n";
    }
  }
  for (size_t k = 0; k < meshes.size(); ++k) {
    const TriangleMesh& m = meshes[k];
    if (scene.shading == ShadingMode::Gouraud) {
      Shader<double> shader(scene.material, scene.lights);
      SurfaceColour<double> sc(scene.material, texture ? &*texture : nullptr);
      GouraudImage g = gouraudImage(m, gouraudVertexColours(shader, m, sc, cam.origin));
      const std::string name = "XvalGouraud" + std::to_string(k);
      o << gouraudPigment(g, dir, "gouraud_" + std::to_string(k), name);
      writeMesh(o, m, scene, textured, &g, name, false);
    } else {
      writeMesh(o, m, scene, textured, nullptr, "", sp.doubleIlluminate());
    }
  }
  {
    std::ofstream f(ex.pov);
    f << o.str();
    if (!f) throw ExportError(ex.pov.string() + ": cannot write");
  }
  {
    std::ofstream f(ex.ini);
    f << "; POV-Ray 3.7 options for scene.pov. Run from this folder: povray scene.ini\n"
      << "Input_File_Name=scene.pov\nOutput_File_Name=" << ex.output_name << "\n"
      << "Width=" << scene.camera.width << "\nHeight=" << scene.camera.height << "\n"
      << "; one sample per pixel, through the pixel centre\nAntialias=Off\n"
      << "; 16-bit PNG, linear (no transfer function), alpha = hit mask\n"
      << "Output_File_Type=N\nBits_Per_Color=16\nFile_Gamma=1.0\nOutput_Alpha=On\n"
      << "Display=Off\nPause_When_Done=Off\nVerbose=Off\n";
    if (!f) throw ExportError(ex.ini.string() + ": cannot write");
  }
  {
    std::ofstream f(dir / "README.txt");
    f << "Exported by xval from scene: " << commentSafe(scene.name) << "\n\n"
      << "Render with POV-Ray 3.7 from this folder:\n\n    povray scene.ini\n\n"
      << "or, equivalently:\n\n    povray +Iscene.pov +O" << ex.output_name << " +W"
      << scene.camera.width << " +H" << scene.camera.height
      << " -A +FN16 +UA File_Gamma=1.0 -D\n\n"
      << "The output holds the model's values linearly (round(v * 65535)), alpha = hit mask.\n";
  }
  return ex;
}

}  // namespace xval
