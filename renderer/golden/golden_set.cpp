// Golden images: paths, hashes and the manifest (golden/golden_set.h).
#include "golden/golden_set.h"


#include <algorithm>

#include <fstream>
#include <limits>
#include <memory>
#include <stdexcept>
#include <vector>

#include "files/atomic_write.h"
#include "image/exr_file.h"
#include "files/sha256.h"
#include "image/image_header.h"
#include "image/pixel_classes.h"
#include "scene/json_reader.h"
#include "scene_file/scene_loader.h"

namespace xval::golden {

namespace fs = std::filesystem;

namespace {

std::string field(const nlohmann::json& j, const char* key, const fs::path& file, const std::string& where) {
  if (!j.contains(key) || !j.at(key).is_string())
    throw std::runtime_error(file.string() + ": " + where + key + ": expected a string");
  return j.at(key).get<std::string>();
}

}  // namespace

fs::path goldenFolder(const fs::path& scene_file, const std::string& renderer) {
  return (fs::absolute(scene_file).lexically_normal().parent_path().parent_path() / "golden" / renderer)
      .lexically_normal();
}

namespace {

// A distance channel as stored in 16-bit floats: infinity ("far") beyond
// kGoldenEdgeMargin times the class's bound (the class compares with the
// bound only, and far values would only cost space), and a value above the
// bound never below bound (1 + 2^-10), so that rounding to 16 bits (11
// significant bits, monotone) cannot bring it onto the bound: the bounds
// are powers of two, exact in 16 bits, and a value at or below one stays
// at or below it. The stored channel classifies every pixel as the
// render's does.
float storedDistance(float v, float bound) {
  if (!(v <= kGoldenEdgeMargin * bound)) return std::numeric_limits<float>::infinity();
  return v <= bound ? v : std::max(v, bound * (1.0f + 1.0f / 1024.0f));
}

}  // namespace

void writeGoldenImage(const Image& img, const fs::path& file) {
  const size_t n = size_t(img.width) * size_t(img.height);
  const bool diag = img.depth.size() == n && img.backfacing.size() == n && img.incidence.size() == n;
  const bool texel = diag && img.texel_edge.size() == n;
  const bool edge = diag && img.triangle_edge.size() == n;
  if (file.has_parent_path()) fs::create_directories(file.parent_path());
  // Colour in float, the diagnostics in half (what the classification
  // needs of them), the edge distances as storedDistance keeps them.
  std::vector<float> texel_stored, edge_stored;
  if (texel)
    for (float v : img.texel_edge) texel_stored.push_back(storedDistance(v, kTexelEdgeRoundings));
  if (edge)
    for (float v : img.triangle_edge) edge_stored.push_back(storedDistance(v, kTriangleEdgePixels));
  const size_t w = size_t(img.width);
  std::vector<ExrChannel> channels;
  const char* rgba[] = {"R", "G", "B", "A"};
  for (size_t c = 0; c < 4; ++c) channels.push_back({rgba[c], img.rgba.data() + c, 4, w * 4});
  auto half = [&](const char* name, const std::vector<float>& v) { channels.push_back({name, v.data(), 1, w, true}); };
  if (diag) {
    half("Z", img.depth);
    half("backfacing", img.backfacing);
    half("incidence", img.incidence);
    if (texel) half("texel_edge", texel_stored);
    if (edge) half("triangle_edge", edge_stored);
    for (const DiagnosticsChannel& c : kProbeChannels)
      if ((img.*c.member).size() == n) half(c.name, img.*c.member);
  }
  writeFileAtomically(file, [&](const fs::path& tmp) {
    // The encoding attribute as every image xval writes (image/image.h).
    writeExrFile(tmp, img.width, img.height, channels, "zip", {{"xval:encoding", kColourEncoding}});
    requireDecodable(tmp, img.width, img.height);
    return true;
  });
}

nlohmann::json settingsOf(const std::string& renderer, int spp, const std::string& precision) {
  nlohmann::json s = {{"renderer", renderer}};
  if (spp > 0) {
    s["spp"] = spp;
    s["precision"] = precision;
    s["cull_back_faces"] = true;
    s["diagnostics"] = true;
  }
  return s;
}

std::string settingsHash(const nlohmann::json& settings) { return sha256Text(settings.dump()); }

Manifest readManifest(const fs::path& folder, const std::string& renderer) {
  Manifest m;
  m.renderer = renderer;
  const fs::path file = folder / "manifest.json";
  if (!fs::exists(file)) return m;
  // The one strict reader (scene/json_reader.h): a key given twice is an
  // error naming the field, never the last value silently.
  const nlohmann::json j = parseJsonText(readJsonFile(file, "golden manifest"), file.string());
  if (!j.is_object()) throw std::runtime_error(file.string() + ": expected a JSON object");
  if (field(j, "format", file, "") != kManifestFormat)
    throw std::runtime_error(file.string() + ": format: expected \"" + kManifestFormat + "\"");
  if (const std::string r = field(j, "renderer", file, ""); r != renderer)
    throw std::runtime_error(file.string() + ": renderer: \"" + r + "\", expected \"" + renderer + "\"");
  if (!j.contains("entries") || !j.at("entries").is_object())
    throw std::runtime_error(file.string() + ": entries: expected an object");
  for (const auto& [stem, e] : j.at("entries").items()) {
    const std::string where = "entries." + stem + ".";
    if (!e.is_object()) throw std::runtime_error(file.string() + ": " + where + ": expected an object");
    Entry x;
    x.scene_file = field(e, "scene_file", file, where);
    x.scene_sha256 = field(e, "scene_sha256", file, where);
    if (!e.contains("settings") || !e.at("settings").is_object())
      throw std::runtime_error(file.string() + ": " + where + "settings: expected an object");
    x.settings = e.at("settings");
    x.settings_sha256 = field(e, "settings_sha256", file, where);
    x.image = field(e, "image", file, where);
    // The image is a plain file name in the manifest's folder: nothing else
    // is ever opened through a manifest.
    if (x.image.empty() || x.image.find('/') != std::string::npos || x.image.find('\\') != std::string::npos ||
        x.image == "." || x.image == "..")
      throw std::runtime_error(file.string() + ": " + where + "image: \"" + x.image +
                               "\": expected a file name in the manifest's folder");
    x.image_sha256 = field(e, "image_sha256", file, where);
    x.renderer_version = field(e, "renderer_version", file, where);
    x.git_commit = field(e, "git_commit", file, where);
    x.date_utc = field(e, "date_utc", file, where);
    m.entries.emplace(stem, std::move(x));
  }
  return m;
}

void writeManifest(const fs::path& folder, const Manifest& m) {
  nlohmann::ordered_json j;
  j["format"] = kManifestFormat;
  j["renderer"] = m.renderer;
  j["entries"] = nlohmann::ordered_json::object();
  for (const auto& [stem, e] : m.entries)
    j["entries"][stem] = {{"scene_file", e.scene_file},     {"scene_sha256", e.scene_sha256},
                          {"settings", e.settings},         {"settings_sha256", e.settings_sha256},
                          {"image", e.image},               {"image_sha256", e.image_sha256},
                          {"renderer_version", e.renderer_version}, {"git_commit", e.git_commit},
                          {"date_utc", e.date_utc}};
  writeFileAtomically(folder / "manifest.json", j.dump(2) + "\n");
}

std::string goldenProblem(const fs::path& folder, const Manifest& m, const fs::path& scene_file,
                          const std::string& update_command) {
  const std::string stem = scene_file.stem().string();
  const fs::path manifest = folder / "manifest.json";
  const auto it = m.entries.find(stem);
  if (it == m.entries.end())
    return "no golden image of " + stem + " in " + manifest.string() + " (" + update_command + " stores one)";
  const Entry& e = it->second;
  const std::string now = sha256File(scene_file);
  if (now != e.scene_sha256)
    return "the scene file " + scene_file.string() + " changed since its golden image was stored (SHA-256 " +
           now + ", stored for " + e.scene_sha256 + " in " + manifest.string() + ")";
  const fs::path image = folder / e.image;
  if (!fs::is_regular_file(image)) return "the golden image " + image.string() + " is missing";
  // Read no more than an image of its header's size can hold: 4 bytes per
  // channel and pixel (32-bit floats, the most it stores), twice over for
  // OpenEXR's offsets and blocks stored uncompressed, and 1 MiB of header.
  // A sparse file of terabytes behind a valid header is refused, not read.
  std::string h;
  try {
    const ImageHeader header = readImageHeader(image);
    if (const std::string problem = imageHeaderProblem(header, readImageLimits()); !problem.empty())
      return "the golden image " + image.string() + " " + problem;
    const std::uintmax_t bound =
        2 * std::uintmax_t(header.width) * std::uintmax_t(header.height) * std::uintmax_t(header.channels) * 4 +
        (std::uintmax_t(1) << 20);
    h = sha256File(image, bound);
  } catch (const std::exception& err) {
    return "the golden image " + image.string() + " cannot be used: " + err.what();
  }
  if (h != e.image_sha256)
    return "the golden image " + image.string() + " changed since it was stored (SHA-256 " + h + ", manifest " +
           e.image_sha256 + ")";
  return "";
}

}  // namespace xval::golden
