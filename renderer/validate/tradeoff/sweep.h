// Speed/accuracy trade-off of the reference renderer's knobs: the sweep of
// configurations, the converged reference, the error of an image against
// it and the Pareto front. Pure logic (no rendering, no files); the run
// (validate/tradeoff/run.h) renders, times and writes.
//
// Knobs (a Config), each with its accurate end:
//   spp                  samples per pixel, a perfect square in [1, 256]
//                        (n x n stratified grid, box filter)        -> many
//   tessellation_factor  multiplies segments_along/segments_around of
//                        every torus knot and segments_longitude/
//                        segments_latitude of every sphere (rounded,
//                        at least the loader's minimum); 1 = the scene's
//                        own tessellation; planes are exact            -> fine
//   precision            float (fast path) or double (reference path) -> double
//   shading              flat, gouraud or phong                        -> phong
//   texture_filter       nearest or bilinear (textured scenes only)    -> bilinear
//
// The sweep (sweepConfigs), from the scene's own settings ("base"):
//   base                     the scene as it is;
//   spp=N                    N in {1, 4, 16, 64} other than the base's;
//   tess=F                   F in {0.25, 0.5, 2} (tessellated shapes only);
//   precision=P              the other precision;
//   shading=S                the two other shading modes;
//   filter=F                 the other texture filter (textured only);
//   corner:fast              float, 1 spp, tess 0.5, nearest, the base's
//                            shading;
//   corner:fast-gouraud      the same with gouraud shading;
//   corner:float-4spp        float, 4 spp, the scene's tessellation;
//   corner:float-16spp       float, 16 spp;
//   corner:accurate          double, 16 spp, tess 2, phong, bilinear;
//   converged                the converged reference's own configuration
//                            (its error is 0 by construction when the
//                            renderer is deterministic: a check).
// Every one-knot row keeps the base's other knots. A row whose knobs equal
// an earlier row's is dropped. With `quick`, spp=64, tess=2 and
// corner:accurate are left out.
//
// The converged reference (convergedConfig): double, reference_spp (default
// 64 = 8 x 8) samples, reference_tessellation (default 4) times the scene's
// segments each way, phong shading, bilinear filter. There is no analytic
// tube to intersect, so "converged" is checked, not assumed: the reference
// is compared with one step finer in each direction (convergenceChecks:
// tessellation x2 at the same spp, which cancels the sampling exactly as
// the stratified grid is the same; and spp (2n)^2 at the same
// tessellation), and those residuals are reported next to the errors; an
// error below them does not mean anything.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "image/image.h"
#include "image/metric_table.h"
#include "scene/scene.h"
#include "scene_file/scene_budget.h"

namespace xval {

struct TradeoffConfig {
  std::string id;      // "base", "spp=4", "tess=0.5", "corner:fast", ... (stable; used as labels)
  std::string group;   // "base", "spp", "tessellation", "precision", "shading", "filter", "corner", "converged"
  int spp = 1;
  double tessellation_factor = 1.0;  // times the scene's segments
  Precision precision = Precision::Double;
  ShadingMode shading = ShadingMode::Phong;
  std::optional<TextureFilter> texture_filter;  // none: the scene is untextured
  bool sameKnobs(const TradeoffConfig& o) const;
};

struct SweepSettings {
  int reference_spp = 64;              // perfect square in [1, 256]
  double reference_tessellation = 4.0; // times the scene's segments, > 0
  bool quick = false;
};

// True when n is a perfect square in [1, 256].
bool validSpp(int n);

// The scene's own settings.
TradeoffConfig baseConfig(const Scene& scene);
TradeoffConfig convergedConfig(const Scene& scene, const SweepSettings& s);
// The sweep, in order (documented above); the last row is "converged".
std::vector<TradeoffConfig> sweepConfigs(const Scene& scene, const SweepSettings& s);
// The two one-step-finer configurations the reference is compared with:
// "tess x2" and "spp=(2n)^2" (capped at 256; left out when that is not
// finer than the reference).
std::vector<TradeoffConfig> convergenceChecks(const Scene& scene, const SweepSettings& s);

// Whether the scene has anything the tessellation factor changes.
bool hasTessellatedShapes(const Scene& scene);
// segments * factor, rounded, at least `minimum`.
int scaledSegments(int segments, double factor, int minimum);
// The scene with the configuration's knobs applied, validated again by the
// scene loader (so a factor that makes a mesh too large is an error naming
// the scene, the field and the value).
Scene applyConfig(const Scene& scene, const TradeoffConfig& c, const Budget& budget = Budget{});

// Error of `img` against `reference` over the pixels either image covers
// (alpha > 0; the colour is premultiplied by coverage, over black, so a
// pixel covered by one image only counts with its whole difference). A
// pixel's error is its largest RGB channel difference. The pair is
// measured once over those pixels (image/metric_table.h: measurePair of
// eitherCovered), and `metrics` holds every entry of the metric table by
// id; the named fields are the table's max, p999, rmse, ciede2000 and
// ciede2000_max, kept as the JSON fields of tradeoff.json that the tables
// and the report read.
struct TradeoffError {
  long long pixels = 0;         // covered by either image
  double max_16bit = 0.0;       // largest pixel error, in 1/65535
  double p999_16bit = 0.0;      // 99.9th percentile (nearest rank) of the pixel error, in 1/65535
  double rmse_16bit = 0.0;      // over the pixels and the 3 channels, in 1/65535
  double ciede2000_mean = 0.0;  // CIEDE2000 (image/perceptual.h: colours as sRGB-coded), mean over the pixels
  double ciede2000_max = 0.0;
  std::map<std::string, double> metrics;  // the metric table's values, by id (image/metric_table.h)
};
// Throws std::runtime_error when the sizes differ.
TradeoffError tradeoffError(const Image& img, const Image& reference);

// The error on the Pareto plot's axis: an entry of the metric table whose
// better direction is lower (image/metric_table.h: metricIds(true); the
// default "rmse"). Throws std::runtime_error naming the metric and the
// choices, or when `e` has no value for it (a tradeoff.json written before
// the metric table had only max, p999, rmse and ciede2000).
double errorMetric(const TradeoffError& e, const std::string& metric);
// Throws unless `metric` is an error of the metric table (as above).
const MetricInfo& tradeoffAxis(const std::string& metric);

// A point to minimise in both coordinates.
struct ParetoPoint {
  double seconds = 0.0;
  double error = 0.0;
};
// Indices of the Pareto-optimal points, by increasing seconds (ties by
// increasing error, then index). Point j dominates point i when
//   seconds_j <= seconds_i and error_j <= error_i + error_tolerance, and
//   (seconds_j < seconds_i or error_j < error_i - error_tolerance);
// a point is optimal when no other dominates it. With error_tolerance = 0
// that is plain Pareto dominance (equal points are all optimal); a
// tolerance > 0 says errors closer than it are not resolved (`xval
// tradeoff` passes the converged reference's own residual), so a faster
// point within it dominates a slower one. Dominance stays acyclic, so the
// front of a non-empty set of finite points is never empty. Points with a
// non-finite coordinate are never optimal and dominate nothing.
std::vector<size_t> paretoFront(const std::vector<ParetoPoint>& points, double error_tolerance = 0.0);

}  // namespace xval
