// The files validate's compare step writes into a case folder OUT/<scene>/
// for each pair of renderers it compares (<pair>: renderers::pairKey,
// "reference-povray"), named here once. The writers take their names from
// here, and a run removes, from each case folder it compares, the files of
// these kinds that the case's results do not name, so that a folder reused
// by a later run holds no comparison output an earlier run left behind:
//   diff_<pair>.exr                    the difference |a - b|, 32-bit float
//   heat_<pair>.png                    its heat map (image/heat_map.h)
//   heat_bound_<pair>.png              the pair's precision bound map
//   crop_<pair>_<pixel>_<of>.png       crops around its worst pixels
//                                      (validate/pixel_crops.h)
// The renders (<renderer>.exr, .png, .job.json) are the render jobs' files,
// not these.
#pragma once

#include <cstddef>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

namespace xval {

std::string diffExrName(const std::string& pair);
std::string heatMapName(const std::string& pair);
std::string boundMapName(const std::string& pair);
// pixel: "worst_unexplained" or "worst_explained"; of: a renderer id, or
// "heat" for the heat map's crop.
std::string cropName(const std::string& pair, const std::string& pixel, const std::string& of);

// Whether a file name (no folder) is of one of the kinds above: its prefix
// (diff_, heat_, crop_) and its extension.
bool isCompareOutputName(const std::string& file_name);

// Removes from case_dir the regular files whose names are of the kinds
// above and not in `named`; nothing else: no folder, no symbolic link
// (removed or followed: validate writes none, so one is the user's), no file
// of another name. Returns the names removed, sorted. Throws
// std::runtime_error naming the folder or file when it cannot be read or a
// file cannot be removed.
std::vector<std::string> removeStaleCompareOutputs(const std::filesystem::path& case_dir,
                                                   const std::set<std::string>& named);

}  // namespace xval
