// Golden images: a renderer's images of a scene set, stored beside it so a
// later render (of the same renderer after a change, or of another one) can
// be compared with them without running the renderer that made them.
//
// Where: for the scene file DIR/scenes/x.json rendered by renderer R,
//   DIR/golden/R/x.exr         the image (writeGoldenImage: zip-compressed
//                              EXR, R, G, B, A as 32-bit floats, exact) and,
//                              from the reference renderer, the diagnostics
//                              the comparison's classification of pixels
//                              over the tolerance reads (Z, backfacing,
//                              incidence, texel_edge, triangle_edge and
//                              the probes' kProbeChannels as 16-bit
//                              floats)
//   DIR/golden/R/manifest.json one entry per stored image (below)
// i.e. the folder `golden` beside the scene file's folder; the scene set
// reference/scenes stores into reference/golden.
//
// The manifest ("format": "xval-golden/1", "renderer": R) holds, per scene
// file stem:
//   scene_file       the scene file relative to the manifest's folder
//   scene_sha256     SHA-256 of the scene file's bytes when it was stored
//   settings         how it was rendered (settingsOf below), and
//   settings_sha256  SHA-256 of their compact JSON text
//   image, image_sha256   the image file (in the manifest's folder), its hash
//   renderer_version the renderer's version line
//   git_commit, date_utc  the toolkit's commit and the time it was stored
//
// A stored image is only used for the scene it was made from: a scene file
// whose hash differs is refused (goldenProblem).
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <string>

#include <nlohmann/json.hpp>

#include "files/sha256.h"
#include "image/image.h"

namespace xval::golden {

inline constexpr const char* kManifestFormat = "xval-golden/1";

// DIR/golden/<renderer> for the scene file DIR/scenes/x.json (any folder
// name in place of `scenes`): absolute, lexically normal.
std::filesystem::path goldenFolder(const std::filesystem::path& scene_file, const std::string& renderer);

struct Entry {
  std::string scene_file;  // relative to the manifest's folder
  std::string scene_sha256;
  nlohmann::json settings;
  std::string settings_sha256;
  std::string image;  // file name in the manifest's folder
  std::string image_sha256;
  std::string renderer_version;
  std::string git_commit;
  std::string date_utc;
};

struct Manifest {
  std::string renderer;
  std::map<std::string, Entry> entries;  // by scene file stem
};

// Writes the image as stored (whole or not at all): colour and coverage
// exact (32-bit float), and the diagnostics the comparison's
// classification reads (image/compare.h) as 16-bit floats: backfacing (a
// fraction k / n^2, n^2 <= 256: exact), Z and incidence (relative error
// <= 2^-11, against the classification's thresholds of a 5% depth jump and
// |cos| < 0.1), texel_edge and triangle_edge (relative error <= 2^-11,
// only where within kGoldenEdgeMargin times their class's bound,
// image/pixel_classes.h, elsewhere infinity, "far": the class compares
// with the bound only, and the far values, most pixels, would cost space;
// a value above the bound is kept above it, so every pixel's class is the
// render's), and kProbeChannels (image/image.h; edge_fraction, k / n^2, is
// exact; the colour bounds keep relative error <= 2^-11). The unsaturated raw colour and the albedo, for
// diagnosis only, are left out. Measured on reference/scenes: 21.0 MB
// (du -sb), against 47 MB for every channel in 32-bit floats.
inline constexpr float kGoldenEdgeMargin = 16.0f;
void writeGoldenImage(const Image& img, const std::filesystem::path& file);

// The settings a render of `renderer` used, as stored and hashed: for
// every renderer {"renderer": id}; the reference renderer adds its
// RenderOptions that change pixels (spp, precision, cull_back_faces,
// diagnostics) as the golden update renders them.
nlohmann::json settingsOf(const std::string& renderer, int spp, const std::string& precision);
std::string settingsHash(const nlohmann::json& settings);

// Reads DIR/manifest.json; an absent file is an empty manifest for
// `renderer`. Throws std::runtime_error naming the file and field when it
// is malformed or made for another renderer.
Manifest readManifest(const std::filesystem::path& folder, const std::string& renderer);
// Writes it whole or not at all (files/atomic_write.h), entries sorted.
void writeManifest(const std::filesystem::path& folder, const Manifest& m);

// Why the stored image of `scene_file` in `folder` cannot stand for it
// ("" when it can): no manifest entry, the image missing, or the scene file
// changed since it was stored (both hashes quoted) or the image file did.
// `update_command` is the command that stores one (quoted when there is no
// entry; renderers::goldenUpdateCommand builds it from the registry, which
// sits above this module).
std::string goldenProblem(const std::filesystem::path& folder, const Manifest& m,
                          const std::filesystem::path& scene_file, const std::string& update_command);

}  // namespace xval::golden
