// Image: what every renderer returns, in memory.
//
// rgba: the final colour (each sample saturated to [0,1], as the paper's
// render target did, then box-filtered over the pixel's samples) with
// alpha = the fraction of samples that hit geometry; background samples
// are 0, so colour is premultiplied by coverage. Values are the models'
// stored-value encoding: no transfer function is applied on output.
// raw: the same box filter over the unsaturated model colour (for
// diagnosis; empty when a renderer cannot provide it).
#pragma once

#include <array>
#include <cstddef>
#include <filesystem>
#include <vector>

#include "image/channel_sentinels.h"

namespace xval {

struct Image {
  int width = 0, height = 0;
  std::vector<float> rgba;  // 4 floats per pixel, row 0 at the top
  std::vector<float> raw;   // 3 floats per pixel, or empty
  // Diagnostics of the reference renderer (empty for other renderers):
  // depth: distance along the ray to the nearest hit over the pixel's
  // samples (0 where nothing is hit); backfacing: the fraction of the
  // pixel's samples whose shading normal faces away from the eye (N.V < 0);
  // incidence: the smallest |cos| between a sample's ray and the normal of
  // the triangle it hit (small = grazing: float rounding of a hit moves it
  // by ~1/incidence).
  // albedo: the surface colour C (texture or base colour) at the first
  // sample that hit, 3 floats per pixel (0 where nothing is hit); may be
  // empty when the others are not (a golden image keeps only the channels
  // the comparison's classification reads: golden/golden_set.h).
  // texel_edge: over the pixel's samples, the smallest distance of a
  // nearest-filtered texture lookup from the next texel's edge, in float
  // roundings of the uv (texture/texel_edge.h; kFarFromTexelEdge when no
  // sample looks up a nearest-filtered texture). Empty in EXRs written
  // before it existed.
  // triangle_edge: over the pixel's samples that hit, the smallest distance
  // in pixels of a hit from an edge of its triangle, in the image plane
  // (camera/triangle_edge.h; kFarFromTriangleEdge when no sample hits).
  // Empty in EXRs written before it existed.
  // The bounds of what other renderers' rounding may change (constants and
  // math: render/precision_probe.h); each empty in EXRs written before it
  // existed, 0 where nothing is hit:
  // edge_fraction: the fraction of the pixel's n x n samples whose image-
  // plane point lies within kTriangleEdgePixels of the projected boundary
  // of a triangle hit by a sample of this pixel or of its 8 neighbours (a
  // rasteriser's rounding may give the sample another first hit).
  // backfacing_flip: the largest channel difference between rgba's colour
  // and the colour with every backfacing sample (N.V < 0) shaded with -N
  // (as POV-Ray turns such normals); 0 where no sample is backfacing.
  // precision_position: the box filter (sum / n^2) over the hit samples of
  // the largest channel change of the saturated colour when the hit moves
  // by kPositionStepPixels along the image's x or y on its triangle.
  // precision_uv: the same for the texture coordinate moved by
  // kUvStepTexels texels along u or v (and a trilinear texture's level of
  // detail by its 2x2-quad estimate's difference, at least kLodStep).
  // precision_normal: the same for the shading normal turned by
  // kNormalStepRadians (0 for Gouraud shading).
  std::vector<float> depth, backfacing, incidence, albedo, texel_edge, triangle_edge;
  std::vector<float> edge_fraction, backfacing_flip, precision_position, precision_uv, precision_normal;
  // False for an image read from a file without an alpha channel (an RGB
  // PNG from elsewhere): readImage then sets alpha = 1 everywhere, so every
  // pixel counts as covered.
  bool has_alpha = true;

  Image() = default;
  Image(int w, int h, bool with_raw)
      : width(w), height(h), rgba(size_t(w) * h * 4, 0.0f),
        raw(with_raw ? size_t(w) * h * 3 : 0, 0.0f),
        depth(with_raw ? size_t(w) * h : 0, 0.0f),
        backfacing(with_raw ? size_t(w) * h : 0, 0.0f),
        incidence(with_raw ? size_t(w) * h : 0, 0.0f),
        albedo(with_raw ? size_t(w) * h * 3 : 0, 0.0f),
        texel_edge(with_raw ? size_t(w) * h : 0, kFarFromTexelEdge),
        triangle_edge(with_raw ? size_t(w) * h : 0, kFarFromTriangleEdge),
        edge_fraction(with_raw ? size_t(w) * h : 0, 0.0f),
        backfacing_flip(with_raw ? size_t(w) * h : 0, 0.0f),
        precision_position(with_raw ? size_t(w) * h : 0, 0.0f),
        precision_uv(with_raw ? size_t(w) * h : 0, 0.0f),
        precision_normal(with_raw ? size_t(w) * h : 0, 0.0f) {}
  float* pixel(int x, int y) { return &rgba[(size_t(y) * width + x) * 4]; }
  const float* pixel(int x, int y) const { return &rgba[(size_t(y) * width + x) * 4]; }
};

// A one-float-per-pixel diagnostics channel: its EXR channel name and where
// Image keeps it.
struct DiagnosticsChannel {
  const char* name;
  std::vector<float> Image::*member;
};
// The channels of the precision probes (render/precision_probe.h), in the
// order an EXR stores them (after triangle_edge); each optional (empty in
// older files, and read only with Z, backfacing and incidence).
inline constexpr std::array<DiagnosticsChannel, 5> kProbeChannels = {{
    {"edge_fraction", &Image::edge_fraction},
    {"backfacing_flip", &Image::backfacing_flip},
    {"precision.position", &Image::precision_position},
    {"precision.uv", &Image::precision_uv},
    {"precision.normal", &Image::precision_normal},
}};

// Gives `to` (another renderer's image of the same scene and size) the
// diagnostics of `from` (the reference's): depth, backfacing, incidence,
// texel_edge, triangle_edge and kProbeChannels, which the comparison's
// classification reads from its first image. Colour, raw and albedo stay.
void copyDiagnostics(const Image& from, Image& to);

// What the colour channels of every image xval writes hold (the files'
// "xval:encoding" attribute).
inline constexpr const char* kColourEncoding =
    "display-referred code values: no transfer function applied (docs/scene-format.md)";

// How the files xval writes are compressed: every codec below is lossless
// (the pixels read back bit for bit: tests/unit/image_io_test.cpp), so the
// choice trades file size for CPU only. zlib's default level 6 made
// compression the largest CPU cost of a validate run (about a quarter of
// the reference set's CPU, under perf); the choices and their measured
// costs are in docs/performance.md ("What xval's own files cost").
//   kRenderExrCompression      renders' EXRs (up to 20 float channels):
//                              run-length: on the Table 2 knot's 17
//                              channels 178 ms of CPU for the write and
//                              its read-back against zip:1's 387 ms, the
//                              file 19.0 MB against 12.2 MB (the noisy
//                              float channels barely deflate; the
//                              background and constant channels run)
//   kDifferenceExrCompression  difference EXRs (4 float channels): PIZ, a
//                              third less CPU than zip on them
//   kPngZlibLevel, kPngFilter  every PNG (renders, previews, heat maps,
//                              exported textures): zlib level 1, and no
//                              row filter (libpng's PNG_FILTER_NONE; its
//                              default tries all five on every row): a
//                              720x720 heat map in a quarter of the CPU
//                              of the defaults, 5% larger
// (tests/bench/image_files_bench.cpp measures each against the defaults.)
inline constexpr const char* kRenderExrCompression = "rle";
inline constexpr const char* kDifferenceExrCompression = "piz";
inline constexpr int kPngZlibLevel = 1;
inline constexpr int kPngFilter = 8;  // PNG_FILTER_NONE

// OpenEXR (32-bit float; channels R,G,B,A and, when present, raw.R, raw.G,
// raw.B, Z, backfacing, incidence, albedo.R/G/B (only when present),
// texel_edge, triangle_edge and kProbeChannels (each only when present); its colour
// encoding in the attribute xval:encoding, since OpenEXR has no attribute
// for a transfer function) or, by extension
// .png, a 16-bit RGBA PNG: alpha = coverage, colour unassociated as PNG
// defines it (premultiplied colour / alpha), round(v * 65535) of the
// clamped values, no gamma. An EXR (written by OpenEXR: image/exr_file.h)
// is compressed with exr_compression (kRenderExrCompression or
// kDifferenceExrCompression), a PNG (libpng: image/png_file.h) at
// kPngZlibLevel. Every image is decoded again before it is renamed into
// place: an EXR from the file (requireDecodable), a PNG from the bytes just
// encoded, which are then written with every write checked
// (requirePngDecodable); with read_back, that decoding is readImage's and
// its image is stored there (what readImage(file) returns, without
// decoding the file again). Throws std::runtime_error naming the file.
void writeImage(const Image& img, const std::filesystem::path& file,
                const char* exr_compression = kRenderExrCompression, Image* read_back = nullptr);
// An 8-bit RGB PNG for looking at (reports): the clamped colour over black,
// box-filtered down by the smallest integer factor that brings the larger
// side to at most max_side pixels.
void writePreviewPng(const Image& img, const std::filesystem::path& file, int max_side);
// Throws std::runtime_error unless `file` (an EXR or a PNG) decodes whole as
// a width x height image: a writer that reports success for a file a full
// disk left short is caught before the file is renamed into place
// (files/atomic_write.h). An EXR's channels are decoded a row at a time
// into one reused row, never a copy of the image.
void requireDecodable(const std::filesystem::path& file, int width, int height);
// Images read back (from the external renderers, by `xval compare` and
// `xval validate`): at most the largest image xval renders (kMaxImageSide,
// kMaxImagePixels: scene/scene_limits.h) and this many channels (xval's EXRs
// have up to 20, a Blender multilayer EXR a few dozen); checked on the header
// before any pixel is allocated (image/image_header.h).
inline constexpr int kMaxReadImageChannels = 64;

struct ImageHeader;
struct ImageLimits;
// The size and channel count a file's header claims (no pixel is read);
// throws std::runtime_error naming the file if it is not a regular file or
// not an image.
ImageHeader readImageHeader(const std::filesystem::path& file);
ImageLimits readImageLimits(int expect_width = 0, int expect_height = 0);

// Reads R,G,B,A (and raw.* when present) from an EXR (OpenEXR), a PNG
// (libpng) or any other format OpenImageIO reads (image/other_formats.h:
// its module is loaded for such a file only); integer codes c as
// c x (1 / (2^bits - 1)) in float.
// The colour comes back premultiplied by alpha (as EXR stores it): a file
// with unassociated alpha (PNG) is read as stored and multiplied here.
// A non-regular file (FIFO, device, folder) is refused before it is opened.
// The header must be within readImageLimits(); with expect_width > 0 it must
// also be exactly expect_width x expect_height (an external renderer's
// image of a scene: a header claiming more costs nothing).
Image readImage(const std::filesystem::path& file, int expect_width = 0, int expect_height = 0);

}  // namespace xval
