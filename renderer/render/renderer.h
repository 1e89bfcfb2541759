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
#pragma once

#include <cstdio>

#include "image/image.h"
#include "scene/scene.h"

namespace xval {

struct RenderOptions {
  int spp = 1;
  Precision precision = Precision::Double;
  int threads = 0;  // 0: every hardware thread
  bool progress = false;  // progress lines on stderr
};

// Options from the scene's render settings.
RenderOptions defaultOptions(const Scene& scene);

struct RenderStats {
  double setup_seconds = 0.0;   // tessellation, texture, BVH build
  double trace_seconds = 0.0;   // rays and shading
};

Image renderScene(const Scene& scene, const RenderOptions& options, RenderStats* stats = nullptr);

}  // namespace xval
