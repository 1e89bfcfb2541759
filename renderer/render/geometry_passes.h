// Geometry passes: what a camera ray through each pixel centre first hits,
// without shading: the hit mask, the depth, the uv and the object. The
// Blender-import check (blender/model_import.h) compares Blender's passes
// of the user's original model files with these, made from the triangles
// the reference renderer traces (geometry/scene_meshes.h), so a defect of
// our model loader (a node transform, a v flip, a skipped primitive) shows.
//
// Per pixel (i, j), one ray through the centre (i + 0.5, j + 0.5) by the
// camera convention of camera/camera.h, traced on the double-precision path
// (render/accel.h), first hit at distance t along the unit ray d:
//   hit     1 or 0
//   depth   t (d . forward): the distance along the camera's view axis
//           (Cycles' Depth pass is that, not t: docs/model-files.md)
//   u, v    b0 uv0 + b1 uv1 + b2 uv2 in the scene's uv convention (v down);
//           0 where the primitive has no uv (has_uv 0)
//   object  the index of the scene object hit (-1: none)
//   edge    the smallest barycentric coordinate of the hit (0 on an edge
//           of the triangle: where a uv seam may lie)
#pragma once

#include <cstdint>
#include <vector>

#include "image/image.h"
#include "scene/scene.h"

namespace xval {

struct GeometryPasses {
  int width = 0, height = 0;
  std::vector<float> hit, depth, u, v, has_uv, edge;
  std::vector<int32_t> object;

  GeometryPasses() = default;
  GeometryPasses(int w, int h)
      : width(w), height(h), hit(size_t(w) * h, 0.0f), depth(size_t(w) * h, 0.0f), u(size_t(w) * h, 0.0f),
        v(size_t(w) * h, 0.0f), has_uv(size_t(w) * h, 0.0f), edge(size_t(w) * h, 1.0f), object(size_t(w) * h, -1) {}
  size_t size() const { return size_t(width) * height; }
};

// The reference renderer's passes of the scene (see above), at the camera's
// resolution whatever render.spp says.
GeometryPasses referenceGeometryPasses(const Scene& scene);

// As an Image (for the files every renderer writes): rgba = (u, v, depth,
// hit), raw = (object + 1, has_uv, edge). fromImage reads that back and
// throws std::runtime_error when the image has no raw channels.
Image toImage(const GeometryPasses& passes);
GeometryPasses geometryPassesFromImage(const Image& image);

// A picture of the passes for a report (validate's preview PNG of a
// geometry check's job). Blue shows the hit mask and the depth, so the
// shape shows even where the uv is 0 everywhere (Blender's UV pass of a
// model without uvs, an STL: uv alone made such a picture all black):
//   red     u, wrapped to [0, 1) (a repeating uv stays visible); 0 where
//           the primitive has no uvs;
//   green   v, likewise;
//   blue    nearness: 1 at the nearest hit, falling linearly with the depth
//           to 0.25 at the farthest (1 when every hit is at one depth);
//   black   no hit (alpha = hit).
// kPassesPreviewLegend says so in a line for the report's caption.
Image passesPreview(const GeometryPasses& passes);
inline constexpr const char* kPassesPreviewLegend =
    "red = u, green = v (wrapped to [0, 1); 0 without uvs), blue = nearness (1 nearest, 0.25 farthest), "
    "black = no hit";

}  // namespace xval
