#include "validate/report/report_pixels.h"

#include <algorithm>
#include <sstream>

#include "image/pixel_classes.h"
#include "text/number_text.h"
#include "validate/report/report.h"

namespace xval {

namespace fs = std::filesystem;
using J = nlohmann::ordered_json;

namespace {

constexpr int kCropZoom = 8;  // crops magnified 8x, nearest-neighbour

// A box around pixel (x, y) of a w x h image shown at any size: `radius`
// pixels on each side of it, in percent of the image.
std::string markStyle(double x, double y, double w, double h, double radius) {
  std::ostringstream s;
  s << "left:" << 100.0 * (x - radius) / w << "%;top:" << 100.0 * (y - radius) / h
    << "%;width:" << 100.0 * (2 * radius + 1) / w << "%;height:" << 100.0 * (2 * radius + 1) / h << "%";
  return s.str();
}

std::string pixelText(const results::ShownPixel& shown) {
  return "(" + std::to_string(shown.x) + ", " + std::to_string(shown.y) + ")";
}

// The crops of one shown pixel: every render and the heat map, magnified.
std::string cropRow(const results::ShownPixel& shown, const char* title, const std::string& pair) {
  const long long x0 = shown.window_x, y0 = shown.window_y, cw = shown.window_width, ch = shown.window_height;
  const double px = double(shown.x - x0), py = double(shown.y - y0);
  const std::string mark = markStyle(px, py, cw, ch, 0.5);
  std::ostringstream h;
  h << "<div class=\"crops\" data-pair=\"" << htmlEscape(pair) << "\" data-which=\"" << title << "\"><p>"
    << htmlEscape(pair) << ", " << (std::string(title) == "worst_unexplained" ? "worst unexplained" : "worst explained")
    << " pixel " << pixelText(shown) << ": " << fixed(shown.error_16bit, 2) << "/65535 ("
    << htmlEscape(shown.pixel_class) << "), " << cw << " x " << ch << " px around it, magnified "
    << kCropZoom << "x</p><div class=\"imgs\">";
  auto figure = [&](const std::string& src, const std::string& caption, const char* cls) {
    h << "<figure><div class=\"marked\" style=\"width:" << cw * kCropZoom << "px\"><img class=\"crop " << cls
      << "\" src=\"" << htmlEscape(src) << "\" alt=\"" << htmlEscape(caption) << "\" data-x=\"" << px
      << "\" data-y=\"" << py << "\"><span class=\"mark\" style=\"" << mark << "\"></span></div><figcaption>"
      << htmlEscape(caption) << "</figcaption></figure>";
  };
  for (const auto& [renderer, crop] : shown.renders) figure(crop, renderer, "render");
  figure(shown.heat_map, "|" + pair + "|", "heat");
  h << "</div></div>\n";
  return h.str();
}

// A pair's shown pixels, by the name results.json gives each: the worst
// unexplained, then the worst explained.
std::vector<std::pair<const char*, const results::ShownPixel*>> shownPixels(const results::PairCrops& crops) {
  std::vector<std::pair<const char*, const results::ShownPixel*>> out;
  if (crops.worst_unexplained) out.emplace_back("worst_unexplained", &*crops.worst_unexplained);
  if (crops.worst_explained) out.emplace_back("worst_explained", &*crops.worst_explained);
  return out;
}

}  // namespace

bool renderHasImage(const results::Render& render, const fs::path& dir) {
  if (render.error || !render.image) return false;
  return fs::is_regular_file(dir / *render.image);
}

std::string verdictWords(results::PairVerdict v) {
  std::string word = results::pairVerdictName(v);
  std::replace(word.begin(), word.end(), '_', ' ');
  return word;
}

std::string pairVerdict(const results::Pair& p) { return verdictWords(p.verdict); }

std::string pixelClassLegend(const std::string& doc_href) {
  std::ostringstream h;
  h << "<table class=\"classes\"><tr><th class=\"l\">pixel class</th><th class=\"l\">what it is</th></tr>\n";
  for (const PixelClassInfo& c : kPixelClasses)
    h << "<tr><td class=\"l\"><a href=\"" << htmlEscape(doc_href) << "#" << c.doc_anchor << "\">" << c.name
      << "</a></td><td class=\"l\">" << htmlEscape(c.explanation) << "</td></tr>\n";
  h << "</table>\n";
  return h.str();
}

std::string casePixels(const results::Case& c, const fs::path& dir) {
  std::ostringstream h;
  long long width = 0, height = 0;  // the scene's, from any pair's metrics
  for (const results::Pair& p : c.pairs)
    if (p.metrics) width = p.metrics->width, height = p.metrics->height;
  // The viewer: one image, a button per render and per heat map.
  std::ostringstream buttons;
  std::string first;
  for (const auto& [id, render] : c.renders) {
    // Only renders with an image: not a failed or a not-expressible one.
    if (!renderHasImage(render, dir)) continue;
    const std::string& src = *render.image;
    if (first.empty()) first = src;
    buttons << "<button type=\"button\" data-src=\"" << htmlEscape(src) << "\">" << htmlEscape(id) << "</button>";
  }
  for (const results::Pair& p : c.pairs) {
    if (p.heat_map)
      buttons << "<button type=\"button\" data-src=\"" << htmlEscape(*p.heat_map) << "\">|" << htmlEscape(p.pair)
              << "|</button>";
    if (p.bound_map)
      buttons << "<button type=\"button\" data-src=\"" << htmlEscape(*p.bound_map) << "\">bound "
              << htmlEscape(p.pair) << "</button>";
  }
  if (!first.empty() && width > 0)
    h << "<div class=\"viewer\" data-viewer><div class=\"swapbar\">show: " << buttons.str()
      << "</div><img class=\"swap\" src=\"" << htmlEscape(first) << "\" alt=\"render\" style=\"width:" << width
      << "px\"></div>\n";
  // The heat maps, full resolution, with the two pixels marked.
  h << "<div class=\"imgs\">";
  for (const results::Pair& p : c.pairs) {
    if (!p.heat_map) continue;
    const std::string& pair = p.pair;
    const std::string& heat = *p.heat_map;
    if (!fs::is_regular_file(dir / heat)) {
      h << "<p class=\"err\">heat map " << htmlEscape(heat) << " (named in results.json) is missing</p>";
      continue;
    }
    h << "<figure><div class=\"marked\" style=\"width:" << width << "px\"><img class=\"heat\" src=\""
      << htmlEscape(heat) << "\" alt=\"heat map " << htmlEscape(pair) << "\">";
    const results::PairCrops crops = p.crops.value_or(results::PairCrops{});
    for (const auto& [which, shown] : shownPixels(crops))
      h << "<span class=\"mark " << which << "\" title=\"" << which << " " << pixelText(*shown) << "\" style=\""
        << markStyle(double(shown->x), double(shown->y), double(width), double(height), 4) << "\"></span>";
    h << "</div><figcaption>|" << htmlEscape(pair) << "|";
    if (crops.worst_unexplained) h << "; red box: worst unexplained";
    if (crops.worst_explained) h << "; blue box: worst explained";
    h << "</figcaption></figure>";
    // The precision bound on the same scale: where |a - b| is brighter than
    // it, only an edge, a backfacing normal or nothing explains the pixel.
    if (p.bound_map) {
      const std::string& bound = *p.bound_map;
      if (!fs::is_regular_file(dir / bound))
        h << "<p class=\"err\">bound map " << htmlEscape(bound) << " (named in results.json) is missing</p>";
      else
        h << "<figure><img class=\"heat\" src=\"" << htmlEscape(bound) << "\" alt=\"precision bound "
          << htmlEscape(pair) << "\" style=\"width:" << width << "px\"><figcaption>precision bound of "
          << htmlEscape(pair) << " (same scale)</figcaption></figure>";
    }
  }
  h << "</div>\n";
  for (const results::Pair& p : c.pairs)
    if (p.crops)
      for (const auto& [which, shown] : shownPixels(*p.crops)) h << cropRow(*shown, which, p.pair);
  return h.str();
}

std::string swapScript() {
  return "document.querySelectorAll('[data-viewer]').forEach(function (v) {\n"
         "  var img = v.querySelector('img.swap'), buttons = v.querySelectorAll('button[data-src]');\n"
         "  buttons.forEach(function (b) {\n"
         "    b.addEventListener('click', function () {\n"
         "      img.src = b.getAttribute('data-src');\n"
         "      buttons.forEach(function (o) { o.classList.toggle('on', o === b); });\n"
         "    });\n"
         "  });\n"
         "  if (buttons.length) buttons[0].classList.add('on');\n"
         "});\n";
}

}  // namespace xval
