// The pixels the report shows of one compared pair: its worst unexplained
// pixel and its worst explained one (image/compare.h), each with a crop of
// kCropSide x kCropSide pixels around it of every render of the case and
// of the pair's heat map, at full resolution, written as PNGs by the
// compare step (which has the EXRs) for the report to magnify
// nearest-neighbour.
#pragma once

#include <filesystem>
#include <map>
#include <string>

#include <nlohmann/json.hpp>

#include "image/compare.h"
#include "image/image.h"

namespace xval {

inline constexpr int kCropSide = 24;

// The crop window around (x, y): kCropSide a side (less in a smaller
// image), inside the image, (x, y) as near its centre as that allows.
struct CropWindow {
  int x0 = 0, y0 = 0, width = 0, height = 0;
};
CropWindow cropWindow(int x, int y, int image_width, int image_height);

// The pixels of `img` in the window, as an image of the window's size.
Image cropImage(const Image& img, const CropWindow& w);

// a, b: the pair's images (with the diagnostics they were compared with);
// renders: every render of the case by renderer id; heat: the pair's heat
// map at full resolution (image/heat_map.h). Writes
// results_dir/<scene>/crop_<pair>_<which>_<renderer or heat>.png
// (validate/compare_outputs.h) and
// returns, per pixel shown (key worst_unexplained, worst_explained; absent
// when the pair has no such pixel): {pixel [x, y], error_16bit, class,
// window [x0, y0, width, height], heat_map, renders {id: png}}, the paths
// relative to results_dir.
nlohmann::ordered_json writePairCrops(const Image& a, const Image& b, const std::map<std::string, const Image*>& renders,
                                      const Image& heat, const CompareMetrics& m,
                                      const std::filesystem::path& results_dir, const std::string& scene,
                                      const std::string& pair);

}  // namespace xval
