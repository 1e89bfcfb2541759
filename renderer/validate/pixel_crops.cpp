#include "validate/pixel_crops.h"

#include <algorithm>
#include <cmath>

#include "image/pixel_classes.h"
#include "validate/compare_outputs.h"

namespace xval {

namespace fs = std::filesystem;
using J = nlohmann::ordered_json;

CropWindow cropWindow(int x, int y, int image_width, int image_height) {
  CropWindow w;
  w.width = std::min(kCropSide, image_width);
  w.height = std::min(kCropSide, image_height);
  w.x0 = std::clamp(x - kCropSide / 2, 0, image_width - w.width);
  w.y0 = std::clamp(y - kCropSide / 2, 0, image_height - w.height);
  return w;
}

Image cropImage(const Image& img, const CropWindow& w) {
  Image c(w.width, w.height, false);
  for (int y = 0; y < w.height; ++y)
    for (int x = 0; x < w.width; ++x) std::copy_n(img.pixel(w.x0 + x, w.y0 + y), 4, c.pixel(x, y));
  return c;
}

nlohmann::ordered_json writePairCrops(const Image& a, const Image& b, const std::map<std::string, const Image*>& renders,
                                      const Image& heat, const CompareMetrics& m, const fs::path& results_dir,
                                      const std::string& scene, const std::string& pair) {
  J out = J::object();
  struct Shown {
    const char* key;
    int x, y;
    double error;
    PixelClass cls;
  };
  for (const Shown s : {Shown{"worst_unexplained", m.worst_unexplained_x, m.worst_unexplained_y, m.max_unexplained,
                              PixelClass::Unexplained},
                        Shown{"worst_explained", m.worst_explained_x, m.worst_explained_y, m.max_explained,
                              m.worst_explained_class}}) {
    if (s.x < 0 || s.y < 0 || s.x >= heat.width || s.y >= heat.height) continue;  // none
    const CropWindow w = cropWindow(s.x, s.y, heat.width, heat.height);
    const auto file = [&](const std::string& of) { return scene + "/" + cropName(pair, s.key, of); };
    J j;
    j["pixel"] = {s.x, s.y};
    j["error_16bit"] = std::isfinite(s.error) ? J(s.error * 65535.0) : J(nullptr);
    j["class"] = pixelClassInfo(s.cls).key;
    j["window"] = {w.x0, w.y0, w.width, w.height};
    j["heat_map"] = file("heat");
    writePreviewPng(cropImage(heat, w), results_dir / file("heat"), kCropSide);
    J jr = J::object();
    for (const auto& [id, img] : renders) {
      if (!img || img->width != heat.width || img->height != heat.height) continue;  // a failed render
      jr[id] = file(id);
      writePreviewPng(cropImage(*img, w), results_dir / file(id), kCropSide);
    }
    j["renders"] = jr;
    out[s.key] = j;
  }
  return out;
}

}  // namespace xval
