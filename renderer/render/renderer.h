// The reference renderer: a ray caster, local illumination only (no
// shadows, as the paper's shader), through Embree (render/accel.h).
//
// Per sample: the camera ray (camera/camera.h) finds the closest triangle;
// the surface is then shaded by the scene's shading mode:
//   flat:    the triangle's geometric normal (oriented to agree with its
//            vertex normals); position, eye vector and texture per sample;
//   gouraud: the model evaluated at the three vertices (vertex position,
//            vertex normal, texture at the vertex uv), and the resulting
//            unsaturated colours interpolated with the hit's barycentrics;
//   phong:   normal = normalize(b0 n0 + b1 n1 + b2 n2) (renormalised, unlike
//            the listing), uv interpolated, model per sample.
// Each sample's colour is saturated, then samples are box-filtered over an
// n x n stratified grid at ((i + (sx + 0.5)/n), (j + (sy + 0.5)/n)); for
// n = 1 that is the pixel centre.
//
// Two paths, one set of formulas:
//   double (the reference): double-precision watertight intersection
//     (Embree user geometry) and double shading, one ray at a time;
//   float (the fast path): float shading; visibility rasterised
//     (render/raster.h: the same first hits as the camera rays, found by a
//     watertight z-buffer in bands of rows) when the whole scene is in front
//     of the camera, else Embree's float triangles traced as coherent
//     16-ray packets (4 x 4 pixels at the same sub-sample offset).
//     RenderStats::visibility says which. The raster skips the back faces
//     of closed meshes seen from outside (geometry/front_faces.h), which
//     are never a first hit.
// Work is split into 8 x 8-pixel tiles (ray paths) or 16-row bands (raster)
// handed out to the threads in order.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "geometry/mesh.h"
#include "image/image.h"
#include "scene/scene.h"

namespace xval {

struct RenderOptions {
  int spp = 1;
  Precision precision = Precision::Double;
  int threads = 0;  // 0: every hardware thread
  bool progress = false;  // progress lines on stderr
  // Fill the diagnostic channels (raw, depth, backfacing, incidence,
  // albedo, texel_edge, triangle_edge, kProbeChannels) when the image has them allocated (Image(w, h, true)).
  // renderScene allocates them only when this is set.
  bool diagnostics = true;
  // With diagnostics: also run the precision probes (render/precision_probe.h:
  // edge_fraction, backfacing_flip, precision.*). False leaves those channels
  // 0, which no comparison may read as bounds: for timing what the probes
  // cost (`xval bench`), never for an image that is compared.
  bool precision_probes = true;
  // Float path only: rasterise visibility when applicable (false: always
  // trace Embree packets; tests compare the two).
  bool rasterise = true;
  // Skip the back faces of meshes whose first hits are always front faces
  // (geometry/front_faces.h; the image is the same, tests compare): the
  // raster per frame; the ray paths' BVH when renderScene prepares it.
  bool cull_back_faces = true;
  // Rasterised float path without diagnostics: shade with the SIMD kernel
  // when it covers the scene (shading/batch_shader.h; bit-identical to one
  // hit at a time, which false forces: tests compare).
  bool batch_shading = true;
};

// Options from the scene's render settings.
RenderOptions defaultOptions(const Scene& scene);

struct RenderStats {
  double setup_seconds = 0.0;   // tessellation, texture, BVH build, per-vertex data
  double trace_seconds = 0.0;   // visibility and shading
  double edge_fraction_seconds = 0.0;  // of trace_seconds: the edge-fraction pass (diagnostics)
  const char* visibility = "";  // how first hits were found
  size_t culled_triangles = 0;  // back faces skipped: by the raster, or left out of the BVH
  std::string shading = "one hit at a time";  // or "SIMD, <instruction set>" (batch_shading)
};

// stats.visibility, the number of back faces skipped when any were, and
// how the hits were shaded.
std::string describeVisibility(const RenderStats& stats);

// A scene made ready to render many frames: tessellated, its texture
// loaded, its BVH built for one precision. Rendering does not modify it.
class PreparedScene {
 public:
  // cull_back_faces: leave out of the BVH the back faces that no camera ray
  // can hit first (as RenderOptions::cull_back_faces does for the raster;
  // decided here because the BVH is built here). False: no face is culled
  // by either path, whatever RenderOptions says, and the conditions of
  // geometry/front_faces.h are not checked (a model mesh's closed-surface
  // check, about 1.7 s of CPU per million triangles, is not paid).
  PreparedScene(const Scene& scene, Precision precision, bool cull_back_faces = true);
  ~PreparedScene();
  PreparedScene(const PreparedScene&) = delete;
  PreparedScene& operator=(const PreparedScene&) = delete;

  Precision precision() const;
  double setupSeconds() const;
  size_t triangleCount() const;
  // The meshes the renderer traces (geometry/scene_meshes.h: per object, one
  // per primitive of a model file).
  const std::vector<TriangleMesh>& meshes() const;

  // Renders one frame into img, which must be camera-sized; diagnostic
  // channels are written when allocated and options.diagnostics is set.
  // options.precision must equal the prepared precision.
  void render(const RenderOptions& options, Image& img, RenderStats* stats = nullptr) const;

  // The probes' own check (render/precision_probe.h): the sample at image
  // point (x, y), traced alone, with the frame's shading at spp samples
  // per pixel: its saturated colour and that of a probe that changes
  // nothing (which must be the same bits).
  struct ProbeCheck {
    bool hit = false;
    glm::dvec3 colour{0}, unperturbed{0};
  };
  ProbeCheck checkProbe(double x, double y, int spp) const;

  struct Impl;

 private:
  std::unique_ptr<Impl> impl_;
};

// PreparedScene + one frame.
Image renderScene(const Scene& scene, const RenderOptions& options, RenderStats* stats = nullptr);

}  // namespace xval
