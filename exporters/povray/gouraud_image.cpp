#include "povray/gouraud_image.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "image/image.h"
#include "povray/sdl.h"

namespace xval::pov {

using glm::dvec3;

GouraudImage gouraudImage(const TriangleMesh& m, const std::vector<dvec3>& colours) {
  GouraudImage g;
  const size_t n = m.triangles.size();
  const int cols = std::max(1, int(std::ceil(std::sqrt(double(n)))));
  const int rows = int((n + cols - 1) / cols);
  g.width = 2 * cols, g.height = 2 * rows;
  g.rgb.assign(size_t(g.width) * g.height * 3, 0.0f);
  auto put = [&g](int x, int y, dvec3 c) {
    for (int k = 0; k < 3; ++k) g.rgb[(size_t(y) * g.width + x) * 3 + k] = float(c[k]);
  };
  auto centre = [&g](int x, int y) {
    return glm::dvec2((x + 0.5) / g.width, 1.0 - (y + 0.5) / g.height);
  };
  for (size_t t = 0; t < n; ++t) {
    const int x = 2 * int(t % cols), y = 2 * int(t / cols);
    const dvec3 c0 = colours[m.triangles[t][0]], c1 = colours[m.triangles[t][1]],
                c2 = colours[m.triangles[t][2]];
    put(x, y, c0), put(x + 1, y, c1), put(x, y + 1, c2), put(x + 1, y + 1, c1 + c2 - c0);
    g.uvs.push_back(centre(x, y));
    g.uvs.push_back(centre(x + 1, y));
    g.uvs.push_back(centre(x, y + 1));
  }
  return g;
}

GouraudCodes gouraudCodes(const GouraudImage& g) {
  GouraudCodes out;
  out.width = g.width, out.height = g.height;
  dvec3 lo(std::numeric_limits<double>::infinity()), hi(-lo);
  for (size_t i = 0; i < g.rgb.size(); ++i) {
    lo[i % 3] = std::min(lo[i % 3], double(g.rgb[i]));
    hi[i % 3] = std::max(hi[i % 3], double(g.rgb[i]));
  }
  dvec3 range = hi - lo;
  for (int c = 0; c < 3; ++c)
    if (!(range[c] > 0)) range[c] = 1.0;
  out.lo = lo, out.range = range;
  out.coarse.resize(g.rgb.size());
  out.fine.resize(g.rgb.size());
  for (size_t i = 0; i < g.rgb.size(); ++i) {
    const int c = int(i % 3);
    double q = std::clamp((double(g.rgb[i]) - lo[c]) / range[c], 0.0, 1.0) * 65535.0;
    double a = std::min(std::floor(q), 65535.0);
    double b = std::round((q - a) * 65535.0);
    out.coarse[i] = std::uint16_t(a);
    out.fine[i] = std::uint16_t(b);
  }
  return out;
}

std::string gouraudPigment(const GouraudCodes& g, const std::filesystem::path& dir,
                           const std::string& stem, const std::string& name) {
  Image coarse(g.width, g.height, false), fine(g.width, g.height, false);
  for (size_t i = 0; i < size_t(g.width) * g.height; ++i) {
    for (int c = 0; c < 3; ++c) {
      coarse.rgba[i * 4 + c] = float(g.coarse[i * 3 + c] / 65535.0);
      fine.rgba[i * 4 + c] = float(g.fine[i * 3 + c] / 65535.0);
    }
    coarse.rgba[i * 4 + 3] = fine.rgba[i * 4 + 3] = 1.0f;
  }
  writeImage(coarse, dir / (stem + "_coarse.png"));
  writeImage(fine, dir / (stem + "_fine.png"));
  const dvec3 lo = g.lo, range = g.range;
  std::ostringstream o;
  o << "#declare " << name << "Coarse = function { pigment { image_map { png \"" << stem
    << "_coarse.png\" gamma 1.0 interpolate 2 } } }\n"
    << "#declare " << name << "Fine = function { pigment { image_map { png \"" << stem
    << "_fine.png\" gamma 1.0 interpolate 2 } } }\n"
    << "#declare " << name << " = pigment { average pigment_map {\n"
    << "  [1 rgb " << vec(lo * 7.0) << "]\n";
  static const char* ch[3] = {"red", "green", "blue"};
  for (int c = 0; c < 3; ++c) {
    dvec3 e(0.0);
    e[c] = 7.0 * range[c];
    o << "  [1 function { " << name << "Coarse(x, y, z)." << ch[c] << " } colour_map { [0 rgb 0] [1 rgb "
      << vec(e) << "] }]\n";
    o << "  [1 function { " << name << "Fine(x, y, z)." << ch[c] << " } colour_map { [0 rgb 0] [1 rgb "
      << vec(e / 65535.0) << "] }]\n";
  }
  o << "} }\n";
  return o.str();
}


}  // namespace xval::pov
