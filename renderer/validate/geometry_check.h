// The Blender-import check's comparison: Blender's geometry passes of the
// user's original model files against the reference renderer's passes of
// our loaded triangles (render/geometry_passes.h), pixel by pixel.
//
// Classes, from the reference's passes:
//   silhouette pixel  its 3 x 3 neighbourhood holds a hit and a miss, or
//                     hits of two objects (a ray that grazes an outline may
//                     hit in one float32 ray test and miss in the other)
//   depth edge        along a line of its 3 x 3 block, the second
//                     difference of 1/depth exceeds kDepthEdgeRatio of its
//                     own 1/depth (0 on a plane, where 1/depth is affine in
//                     the image: an occlusion edge inside the silhouette,
//                     where the two tests may hit different surfaces)
//   triangle edge     the hit's smallest barycentric is below
//                     kTriangleEdgeBarycentric (the two tests may hit the
//                     neighbouring triangle, whose uv differs across a seam)
// Verdict (GeometryTolerance, one place: kGeometryTolerance):
//   mask and object disagree on no pixel off the silhouette, and on at most
//   max_silhouette_fraction of the reference's covered pixels on it;
//   depth: |z_b - z_r| / z_r <= max_depth_rel on every pixel both hit with
//   the same object, off the depth edges;
//   uv: max(|u_b - u_r|, |v_b - v_r|) <= max_uv on every such pixel whose
//   primitive has uvs, off the depth edges and the triangle edges;
//   the pixels excluded as depth or triangle edges that exceed the bounds
//   are at most max_edge_fraction of the covered pixels.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "render/geometry_passes.h"

namespace xval::validation {

struct GeometryTolerance {
  double max_silhouette_fraction;
  double max_depth_rel;
  double max_uv;
  double max_edge_fraction;
  const char* reason;
};

inline constexpr double kDepthEdgeRatio = 1e-3;
inline constexpr double kTriangleEdgeBarycentric = 1e-4;

// Measured on the reference mesh scenes (docs/model-files.md, "The
// Blender-import check").
inline constexpr GeometryTolerance kGeometryTolerance{
    0.002, 2e-5, 1e-4, 0.002,
    "float32 ray/triangle tests in Cycles against the reference's double-precision test at the same pixel "
    "centres (docs/model-files.md, \"The Blender-import check\")"};

struct GeometryMetrics {
  long long covered = 0;             // pixels the reference hits
  long long mask_off = 0;            // hit or object disagree
  long long mask_off_silhouette = 0; // of those, on the silhouette
  long long compared = 0;            // both hit, same object
  double max_depth_rel = 0.0;        // off the depth edges
  double max_uv = 0.0;               // off the depth and triangle edges, where there are uvs
  long long uv_compared = 0;
  long long depth_edges = 0;         // compared pixels classed depth edge
  long long edge_over = 0;           // excluded pixels over the depth or uv bound
  double max_depth_rel_all = 0.0, max_uv_all = 0.0;  // over every compared pixel
  bool pass = false;
  std::string why;                   // the first failed condition, "" on a pass
};

// Throws std::runtime_error when the sizes differ.
GeometryMetrics compareGeometry(const GeometryPasses& reference, const GeometryPasses& other,
                                const GeometryTolerance& tol = kGeometryTolerance);

// crosscheck's metrics.json: pass, why, the metrics and, as "tolerance",
// the bounds.
nlohmann::json toJson(const GeometryMetrics& m, const GeometryTolerance& tol);
// The counts and maxima alone (covered, mask_disagree, ..., edge_over), and
// the bounds alone (max_silhouette_fraction, max_depth_rel, max_uv,
// max_edge_fraction, reason): what toJson and validate's results.json
// (validate/results/geometry_checks.h) both say.
nlohmann::json metricsJson(const GeometryMetrics& m);
nlohmann::json boundsJson(const GeometryTolerance& tol);

}  // namespace xval::validation
