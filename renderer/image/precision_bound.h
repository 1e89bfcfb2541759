// How far a correct renderer's value may lie from the exact one at a
// pixel: its precision bound B_r(p), in fractions of full scale.
//
// The reference renderer measures, at every pixel, how much the value
// moves when an input a renderer rounds moves by one step
// (render/precision_probe.h; channels in image/image.h):
//   S_pos(p)     the hit point moved by kPositionStepPixels in the image
//                plane (p, N, uv, V, L all follow)
//   S_uv(p)      the texture coordinate moved by kUvStepTexels (and a
//                trilinear level of detail by the GPU's quad estimate)
//   S_n(p)       the shading normal turned by kNormalStepRadians
// each the box filter over the pixel's samples of the largest change of
// the sample's saturated colour, either sign. A renderer declares how many
// steps of each its arithmetic can be off by, and the relative error of
// its shading arithmetic and the quantum of the file it writes
// (PrecisionModel, one per renderer in its registry entry). To first
// order a value moves by the sensitivity times the input's error, so
//   B_r(p) = position_steps S_pos(p) + uv_steps S_uv(p) + normal_steps S_n(p)
//            + relative |v(p)| + quantum_16bit / 65535,
// v(p) the pixel's largest colour channel. A pair's bound is the sum of
// its two renderers' (each may be off by its own bound, in any
// direction). Where a step crosses a discontinuity (a nearest texel's
// edge, a highlight's cut-off) the probe sees the jump itself, so the
// bound holds there too as long as the renderer's error is within its
// declared steps; a renderer declaring more than one step is scaled
// linearly (first order).
//
// docs/precision-models.md gives each built-in renderer's numbers and
// their basis (the tools' sources).
#pragma once

#include <cstddef>
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "image/image.h"

namespace xval {

struct PrecisionModel {
  double position_steps = 0.0;  // of kPositionStepPixels
  double uv_steps = 0.0;        // of kUvStepTexels
  double normal_steps = 0.0;    // of kNormalStepRadians
  double relative = 0.0;        // of the value
  double quantum_16bit = 0.0;   // absolute, in 1/65535
  std::string basis;            // one line: where the numbers come from
};

// A renderer whose arithmetic is float32 throughout and whose sub-pixel,
// texture-weight and normal precision is a GPU's: the default of a
// renderer definition file (docs/renderer-file.md) that declares none.
PrecisionModel float32Precision();
// Exact arithmetic: B = 0 (what compare gives a pair without a model).
inline PrecisionModel exactPrecision() { return {0, 0, 0, 0, 0, "exact (no rounding declared)"}; }

// B_r at pixel (x, y) from the image that carries the reference's
// diagnostics, `value` the pixel's largest colour channel (of either
// image: the larger); only the relative and quantum terms when it has no
// precision channels.
double precisionBound(const Image& diagnostics, int x, int y, double value, const PrecisionModel& m);

// Whether the image carries the channels precisionBound reads.
bool hasPrecisionChannels(const Image& img);

// The JSON form {position_steps, uv_steps, normal_steps, relative,
// quantum_16bit, basis} (a renderer definition file's "precision" field
// has the same fields: renderers/renderer_file.cpp reads it).
nlohmann::json precisionJson(const PrecisionModel& m);

}  // namespace xval
