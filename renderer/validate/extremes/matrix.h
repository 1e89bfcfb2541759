// The extremes matrix (`xval extremes`, the spec; run.h runs it): scenes at
// the edges of every model's domain, each rendered by the reference
// renderer in float and in double, and by POV-Ray and Blender where they
// can render it.
//
// What is measured per case (measure.h, docs/extremes.md):
//   - NaN/Inf: pixels with a non-finite value in the final RGBA, and in the
//     unsaturated raw.R/G/B, of the reference render in each precision (the
//     final colour is saturated per sample and saturate maps NaN to 0, so
//     the raw channels are where a NaN would show);
//   - float vs double: the error of the float render against the double one
//     (the reference), per pixel the largest channel difference of the final
//     colour over the pixels both cover: max, p99.9, RMSE, mask
//     disagreements, and a heat map (the report's scale: log from 1/65535 to
//     4096/65535, grey where neither render covers the pixel);
//   - each external renderer against the double reference, the same metrics
//     and map, or its status: "not renderable by X: why" (the exporter
//     refused the scene, with its reason) or an error (the tool failed: an
//     error, never a pass).
//
// Matrix parameters (MatrixOptions) and their defaults:
//   size = 160   image side in pixels of every case (a few use size + 1,
//                odd, so that a pixel centre lies on the image's centre line)
// Everything else of a case is fixed in extremesMatrix() (extremes.cpp),
// which says for each case what is extreme and why the scene is built so.
//
// Files (`writeCaseScenes`): DIR/scenes/<case>.json, complete scene files
// (every one loads with loadScene and renders with `xval render`), and
// DIR/scenes/palette.png, the 1x8 texture of the colour cases.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>


namespace xval::extremes {

struct MatrixOptions {
  int size = 160;  // pixels per side
};

struct Case {
  std::string name;   // file and folder name: [a-z0-9_]
  std::string group;  // e.g. "specular power", "N.L", "light distance"
  std::string what;   // one sentence: the extreme, and what it exercises
  nlohmann::ordered_json scene;  // the scene file's content
};

// The matrix, in report order.
std::vector<Case> extremesMatrix(const MatrixOptions& options = {});

// The palette texture of the colour cases, top row first: white, black,
// red, green, blue, cyan, magenta, yellow (8-bit codes 0 or 255).
inline constexpr const char* kPaletteFile = "palette.png";
void writePaletteTexture(const std::filesystem::path& file);

// Writes every case's scene file, and the palette, into scenes_dir; returns
// the scene files in matrix order.
std::vector<std::filesystem::path> writeCaseScenes(const std::vector<Case>& cases,
                                                   const std::filesystem::path& scenes_dir);

// The cases `only` names (comma-separated; empty: all), in matrix order.
// Throws std::runtime_error naming an unknown case and listing the cases.
std::vector<Case> selectCases(const std::vector<Case>& all, const std::string& only);

}  // namespace xval::extremes
