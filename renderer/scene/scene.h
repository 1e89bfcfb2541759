// Scene: the plain description every renderer and exporter reads.
//
// Loaded and validated from JSON by scene_loader.h (docs/scene-format.md
// documents every field, unit and default). Conventions, fixed here once:
//  - world space is right-handed, +y up (as glTF); lengths in scene units;
//  - angles in the JSON are degrees and are named *_deg;
//  - colours are in the texture's stored encoding (display-referred values
//    in [0,1] for 8-bit images), never linearised: the lighting models work
//    on stored values, as the paper's shader did.
#pragma once

#include <glm/glm.hpp>

#include "colour/luma_only.h"
#include "shading/model/registry.h"
#include "scene/metric_criterion.h"

#include <array>
#include <concepts>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace xval {

using dvec3 = glm::dvec3;
using dvec2 = glm::dvec2;

struct Camera {
  dvec3 position{0.0, 0.0, 4.2};
  dvec3 target{0.0, 0.0, 0.0};
  dvec3 up{0.0, 1.0, 0.0};
  double fov_y_deg = 45.0;  // full vertical field of view
  int width = 256;          // pixels
  int height = 256;         // pixels
};

// --- geometry -----------------------------------------------------------
// A p-q torus knot on a torus of radii (major_radius, minor_radius), swept
// as a tube of radius tube_radius. Centre line (t in [0, 2 pi)):
//   c(t) = ((R + r cos(q t)) cos(p t), (R + r cos(q t)) sin(p t), r sin(q t))
struct TorusKnot {
  int p = 2;
  int q = 3;
  double major_radius = 1.0;
  double minor_radius = 0.45;
  double tube_radius = 0.22;
  int segments_along = 768;  // 768 x 40 -> 61,440 triangles, 31,529 vertices
  int segments_around = 40;
  dvec2 uv_repeat{12.0, 2.0};  // texture repeats along / around the tube
  dvec3 center{0.0};
};

// A latitude-longitude sphere mesh (poles on +-y).
struct UvSphere {
  dvec3 center{0.0};
  double radius = 1.0;
  int segments_longitude = 64;
  int segments_latitude = 32;
  dvec2 uv_repeat{1.0, 1.0};
};

// A rectangle centred at `center`, facing `normal`. Its in-plane u axis is
// normalize(cross(up_hint, normal)) with up_hint = +y, or -z when the normal
// is (anti)parallel to y; its v axis is cross(normal, u_axis) negated so v
// runs "down" the image, as glTF uv does.
struct Plane {
  dvec3 center{0.0};
  dvec3 normal{0.0, 0.0, 1.0};
  dvec2 size{2.0, 2.0};
  dvec2 uv_repeat{1.0, 1.0};
};

struct Model;  // geometry/model_file.h

// A mesh read from a model file (OBJ, PLY, STL, OFF, glTF, GLB;
// docs/model-files.md): every primitive of the file, node transforms
// applied, in doubles. Read once, when the scene is loaded.
struct MeshFile {
  std::filesystem::path path;          // resolved against the scene file
  std::shared_ptr<const Model> model;  // never null in a loaded scene
};

using Shape = std::variant<TorusKnot, UvSphere, Plane, MeshFile>;

// An object's "transform": scale, then rotate, then translate,
//   p' = R (S p) + t   (geometry/transform.h states the math and the
// rule for normals and mirroring).
struct Rotation {
  dvec3 axis{0.0, 1.0, 0.0};  // any non-zero length
  double angle_deg = 0.0;     // right-handed about the axis
};

struct ObjectTransform {
  dvec3 scale{1.0};
  Rotation rotate;
  dvec3 translate{0.0};
  // The identity: no object mesh is mapped (so its bits stay as tessellated).
  bool isIdentity() const {
    return scale == dvec3(1.0) && rotate.angle_deg == 0.0 && translate == dvec3(0.0);
  }
};

// --- texture ------------------------------------------------------------
// Trilinear: the paper's listing's sampler MIN_MAG_MIP_LINEAR, bilinear
// lookups in the two mip levels around the pixel footprint's level
// (texture/mip_chain.h states the chain, the level and the blend).
enum class TextureFilter { Nearest, Bilinear, Trilinear };

// Source::Model: each primitive of the object's model file is textured
// with the base-colour texture its own material assigns (geometry/
// model_file.h); a primitive whose material assigns none has the
// material's base_color. Only a "mesh" object may use it. The renderers
// never see it: geometry/model_textures.h turns such an object into one
// object per primitive with a Source::Image texture (or none).
struct TextureSpec {
  enum class Source { Brick, Image, Model };
  Source source = Source::Brick;
  // Source::Image: the image file, resolved against the scene file; for an
  // image embedded in a model file, that model file (for messages only).
  std::filesystem::path path;
  TextureFilter filter = TextureFilter::Bilinear;
  // Source::Image from an image embedded in a model file: its encoded
  // bytes (PNG, JPEG, ...), decoded instead of reading `path`.
  std::shared_ptr<const std::vector<std::uint8_t>> embedded;
};

// --- lighting models ----------------------------------------------------
// LightingModel: one alternative per model, each in its own file
// shading/model/<name>.h, listed once in shading/model/registry.h.

struct Material {
  LightingModel model = ClassicPhong{};
  std::optional<TextureSpec> texture;  // none: every point has base_color
  // Without a texture: the colour of every point; with source model: of
  // the primitives whose material assigns no texture.
  dvec3 base_color{1.0};
  // The luma-only mode (colour/luma_only.h): the model lights only the
  // luma of this space, C's chroma kept. None: the model as it is.
  std::optional<LumaSpace> luma_only;
};

// --- lights -------------------------------------------------------------
// att(d) = 1 / (constant + linear d + quadratic d^2); (1,0,0) = none.
struct Attenuation {
  double constant = 1.0, linear = 0.0, quadratic = 0.0;
  bool isNone() const { return constant == 1.0 && linear == 0.0 && quadratic == 0.0; }
};

struct PointLight { dvec3 position{0.0}; dvec3 color{1.0}; Attenuation attenuation; };
// `direction` is the direction the light travels (any non-zero length;
// normalised where used).
struct DirectionalLight { dvec3 direction{0.0, -1.0, 0.0}; dvec3 color{1.0}; };
// Hard cone: lit where the angle between the spot axis and the direction
// from the light to the point is <= cutoff_deg.
struct SpotLight {
  dvec3 position{0.0};
  dvec3 direction{0.0, -1.0, 0.0};  // any non-zero length
  double cutoff_deg = 30.0;
  dvec3 color{1.0};
  Attenuation attenuation;
};
struct AmbientLight { dvec3 color{0.1}; };

using Light = std::variant<PointLight, DirectionalLight, SpotLight, AmbientLight>;

// --- shading and render settings ----------------------------------------
enum class ShadingMode { Flat, Gouraud, Phong };
enum class Precision { Float, Double };

struct RenderSettings {
  int spp = 1;  // a perfect square: an n x n stratified grid, box filter
  Precision precision = Precision::Double;
};

// A cross-renderer tolerance this scene declares for one external renderer
// ("povray", "blender", "eevee", "gl", ...: any renderer but the reference), over the default of
// reference/tolerances.json. An entry exists to deviate, so it must say why.
struct DeclaredTolerance {
  std::string renderer;
  std::optional<double> max_abs_16bit;  // per-pixel error, in 1/65535
  std::optional<double> fraction;       // share of covered pixels within it
  std::optional<double> max_unexplained_16bit;  // the cap on an unexplained pixel (image/compare.h)
  bool exclude_backfacing = false;
  std::vector<MetricCriterion> metrics;  // each replaces the default's bound on its metric, if any
  std::string reason;
};

// One entry of the scene's "objects": a shape, placed by its transform,
// with its own material or (none) the scene's.
struct SceneObject {
  Shape shape;
  ObjectTransform transform;
  std::optional<Material> material;

  SceneObject() = default;
  // An untransformed object of the scene's material: `objects = {Plane{}}`.
  template <class S>
    requires std::constructible_from<Shape, S>
  SceneObject(S s) : shape(std::move(s)) {}
};

struct Scene {
  std::string name;
  std::filesystem::path source_file;  // for messages and relative paths
  Camera camera;
  std::vector<SceneObject> objects;
  Material material;  // the default of every object without its own
  std::vector<Light> lights;
  ShadingMode shading = ShadingMode::Phong;
  // Phong shading's normal: normalize(sum b_k N_k) (true), or the
  // interpolated sum b_k N_k as it is (false: the paper's listing, which
  // does not re-normalise). Only shading phong may set it false.
  bool normalize_normal = true;
  RenderSettings render;
  std::vector<DeclaredTolerance> tolerances;  // used only by comparisons
  // The renderers the scene is meant for (registry ids); empty: every one.
  // `xval validate` renders it with no other (validate/validation/plan.h).
  std::vector<std::string> renderers;
  // Known differences (`findings`: renderer id -> why, in registry order): the
  // renderer's built-in model is known to differ from the scene's model
  // (a native tier against the textbook), so its pairs with the renderers
  // that declare none are expected to differ: such a pair that fails its
  // tolerance is a finding, measured and shown; one that passes fails
  // ("the finding no longer holds"). Used only by comparisons.
  std::vector<std::pair<std::string, std::string>> findings;
};

// The scene's finding for the renderer (Scene::findings), null when none.
inline const std::string* findingOf(const Scene& s, const std::string& renderer) {
  for (const auto& [id, why] : s.findings)
    if (id == renderer) return &why;
  return nullptr;
}

// The material object k is shaded with: its own, else the scene's.
inline const Material& materialOf(const Scene& s, size_t k) {
  return s.objects[k].material ? *s.objects[k].material : s.material;
}
// True when some object has a material of its own.
inline bool hasObjectMaterials(const Scene& s) {
  for (const auto& o : s.objects)
    if (o.material) return true;
  return false;
}

const char* toString(ShadingMode m);
const char* toString(Precision p);
const char* toString(TextureFilter f);

}  // namespace xval
