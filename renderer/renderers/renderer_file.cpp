// A renderer defined by a file (renderers/renderer_file.h).
#include "renderers/renderer_file.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <optional>

#include "files/atomic_write.h"
#include "gltf/gltf_exporter.h"
#include "image/image_header.h"
#include "povray/pov_exporter.h"
#include "process/run_process.h"
#include "renderers/export_cache.h"
#include "renderers/registry.h"
#include "scene/json_reader.h"
#include "scene_file/scene_loader.h"
#include "scene_file/scene_writer.h"
#include "shader_file/shader_definition.h"

namespace xval::renderers {

namespace fs = std::filesystem;

namespace {

constexpr const char* kPlaceholders[] = {"input", "scene", "output", "work", "width", "height", "spp"};

// Throws unless every {...} in `word` is a known placeholder.
void checkPlaceholders(const JsonReader& r, const char* key, const std::string& word) {
  for (size_t open = word.find('{'); open != std::string::npos; open = word.find('{', open + 1)) {
    const size_t close = word.find('}', open);
    const std::string name = close == std::string::npos ? "" : word.substr(open + 1, close - open - 1);
    if (std::find(std::begin(kPlaceholders), std::end(kPlaceholders), name) == std::end(kPlaceholders))
      r.fail(key, "\"" + word + "\": unknown placeholder \"" + word.substr(open, close == std::string::npos
                                                                                  ? std::string::npos
                                                                                  : close - open + 1) +
                      "\" (expected {input}, {scene}, {output}, {work}, {width}, {height} or {spp})");
  }
}

std::string substitute(const std::string& word, const std::map<std::string, std::string>& values) {
  std::string out;
  for (size_t k = 0; k < word.size();) {
    if (word[k] == '{') {
      const size_t close = word.find('}', k);
      if (close != std::string::npos)
        if (auto it = values.find(word.substr(k + 1, close - k - 1)); it != values.end()) {
          out += it->second;
          k = close + 1;
          continue;
        }
    }
    out += word[k++];
  }
  return out;
}

// A program with a '/' is relative to the definition file's folder.
std::string programPath(const std::string& program, const fs::path& definition) {
  if (program.find('/') == std::string::npos) return program;
  const fs::path p(program);
  return (p.is_absolute() ? p : fs::absolute(definition).parent_path() / p).lexically_normal().string();
}

// Why `program` cannot run ("" when it can).
std::string programProblem(const std::string& program, const fs::path& definition) {
  if (!findOnPath(program).empty()) return "";
  return "the program '" + program + "' of " + definition.string() + " is not " +
         (program.find('/') == std::string::npos ? "on PATH" : "an executable file");
}

struct Definition {
  std::string name, input;
  std::vector<std::string> command;
  double timeout_s = 0.0;  // 0: the request's
  fs::path file;
};

// The export of input "gltf" or "pov" (nullopt for "scene"): the same
// files under the same cache name as the blender and povray renderers'
// exports, in the work folder's gltf/ or pov/.
std::optional<RendererExport> definedExport(const std::string& input) {
  if (input == "gltf")
    return RendererExport{"gltf", {}, [](const Scene& s, const fs::path& dir) { exportGltf(s, dir); }, "gltf"};
  if (input == "pov")
    return RendererExport{"pov", {}, [](const Scene& s, const fs::path& dir) { exportPov(s, dir); }, "pov"};
  return std::nullopt;
}

Image renderDefined(const Definition& d, const Scene& scene, const RenderRequest& request, RenderInfo* info) {
  if (request.work_dir.empty()) throw std::runtime_error(d.name + ": no work folder given");
  const fs::path work = fs::absolute(request.work_dir).lexically_normal();
  fs::create_directories(work / "scratch");
  const std::string token = attemptToken();
  // The resolved scene (paths absolute) for {scene} and input "scene",
  // without the fields of comparisons (`tolerances`, `renderers`,
  // `findings`): they name renderers the program's own reader need not
  // know (a scene meant for this renderer names it), and say nothing about
  // what to draw.
  const fs::path scene_json = work / "scene.json";
  Scene drawn = scene;
  drawn.tolerances.clear();
  drawn.renderers.clear();
  drawn.findings.clear();
  writeFileAtomically(scene_json, sceneToJson(drawn).dump(2) + "\n");
  fs::path input = scene_json;
  if (const std::optional<RendererExport> ex = definedExport(d.input)) {
    // The export refuseOrExport wrote (request.exported), else the cache's or a new one.
    const fs::path dir = work / ex->folder;
    exportThrough(request.exported ? exportedAlready() : cachedExport(ex->name, request.export_key), dir,
                  [&](const fs::path& to) { ex->write(scene, to); });
    input = d.input == "gltf" ? dir / kGltfFileName : dir;
  }
  // A name no earlier attempt used: an image left by one is never taken.
  const fs::path output = work / ("output-" + token + ".exr");
  const int w = scene.camera.width, h = scene.camera.height;
  const std::map<std::string, std::string> values = {
      {"input", input.string()},     {"scene", scene_json.string()},   {"output", output.string()},
      {"work", (work / "scratch").string()}, {"width", std::to_string(w)}, {"height", std::to_string(h)},
      {"spp", std::to_string(scene.render.spp)}};
  std::vector<std::string> argv;
  for (const std::string& word : d.command) argv.push_back(substitute(word, values));
  argv.front() = programPath(argv.front(), d.file);
  if (const std::string problem = programProblem(argv.front(), d.file); !problem.empty())
    throw ExternalToolError(d.name + ": " + problem);
  const fs::path log = work / (d.name + ".log");
  const double timeout = d.timeout_s > 0 ? d.timeout_s : request.timeout_seconds;
  const ProcessResult r = runProcess(argv, work, log, timeout);
  if (info) {
    info->seconds = r.seconds;
    info->log = log;
  }
  const std::string tool = d.name + " (defined by " + d.file.string() + ")";
  requireToolOutput(tool, input, r, output);
  const std::string tail = "\nlast lines of " + log.string() + ":\n" + tailOfFile(log);
  try {
    const ImageHeader header = readImageHeader(output);
    if (header.channels < 3)
      throw ExternalToolError(output.string() + " has " + std::to_string(header.channels) +
                              " channel(s), expected at least 3 (R, G, B and, optionally, A)");
    Image img = readImage(output, w, h);
    requireFinite(tool, img);
    return img;
  } catch (const std::exception& e) {
    throw ExternalToolError(tool + ": " + e.what() + tail);
  }
}

}  // namespace

Renderer loadRendererFile(const fs::path& file) {
  const nlohmann::json doc = parseJsonText(readJsonFile(file, "renderer file"), file.string());
  JsonReader r(doc, "", file.string());
  const std::string format = r.requireString("format");
  if (format != kRendererFileFormat && format != shaderfile::kShaderFileFormat)
    r.failValue("format", std::string("\"") + kRendererFileFormat + "\" (a program) or \"" +
                              shaderfile::kShaderFileFormat + "\" (a shader, docs/shaders.md)");
  Definition d;
  d.file = fs::absolute(file).lexically_normal();
  d.name = r.requireString("name");
  // The names xval defines stay its own: a file named golden-mine beside
  // one named mine would take over mine's golden set, one named povray
  // the built-in renderer's place.
  if (isGoldenSetId(d.name))
    r.fail("name", "\"" + d.name + "\": golden and the prefix golden- are reserved for the golden sets xval "
                   "defines (golden-<renderer> holds a renderer's stored images); choose another name");
  if (const Renderer* built_in = registry().find(d.name); built_in && built_in->definition_file.empty())
    r.fail("name", "\"" + d.name + "\": the id of a renderer built into xval (" + built_in->display_name +
                       "); choose another name");
  if (format == shaderfile::kShaderFileFormat) return shaderFileRenderer(file, doc);
  d.input = r.requireChoice("input", {"scene", "gltf", "pov"});
  d.command = r.stringArray("command", true);
  std::vector<std::string> version = r.stringArray("version_command", true);
  if (r.has("timeout_s")) d.timeout_s = r.requireNumber("timeout_s", Range::openClosed(0.0, 7 * 24 * 3600.0));
  // One line that says what the renderer is (`xval renderers` shows it).
  std::string description;
  if (r.has("description")) {
    description = r.requireString("description");
    if (description.empty() || description.size() > kMaxRendererDescriptionBytes ||
        std::any_of(description.begin(), description.end(), [](char c) { return (unsigned char)c < 0x20; }))
      r.failValue("description", "one line of 1 to " + std::to_string(kMaxRendererDescriptionBytes) +
                                     " bytes without control characters");
  }
  // How far its arithmetic may be off (image/precision_bound.h); absent:
  // a float32 GPU-like renderer's (float32Precision).
  PrecisionModel precision = float32Precision();
  if (std::optional<JsonReader> p = r.object("precision")) {
    const Range steps = Range::closed(0.0, 1e6);
    precision.position_steps = p->requireNumber("position_steps", steps);
    precision.uv_steps = p->requireNumber("uv_steps", steps);
    precision.normal_steps = p->requireNumber("normal_steps", steps);
    precision.relative = p->requireNumber("relative", Range::closed(0.0, 1.0));
    precision.quantum_16bit = p->requireNumber("quantum_16bit", Range::closed(0.0, 65535.0));
    precision.basis = p->requireString("basis");
    if (precision.basis.empty() || precision.basis.size() > kMaxRendererDescriptionBytes ||
        std::any_of(precision.basis.begin(), precision.basis.end(), [](char c) { return (unsigned char)c < 0x20; }))
      p->failValue("basis", "one line of 1 to " + std::to_string(kMaxRendererDescriptionBytes) +
                                " bytes without control characters saying where the numbers come from");
    p->finish();
  }
  r.finish();
  if (d.command.empty() || d.command.front().empty()) r.fail("command", "expected the program and its arguments");
  if (version.empty() || version.front().empty())
    r.fail("version_command", "expected the program and its arguments");
  for (const std::string& w : d.command) checkPlaceholders(r, "command", w);
  for (const std::string& w : version)
    if (w.find('{') != std::string::npos) r.fail("version_command", "\"" + w + "\": no placeholders here");
  version.front() = programPath(version.front(), d.file);

  Renderer out;
  out.id = d.name;
  out.display_name = d.name;
  out.summary = (description.empty() ? "" : description + "; ") + "defined by " + d.file.string() + " (input " +
                d.input + ")";
  out.version_command = version;
  out.precision = precision;
  out.version_marker = d.name;
  out.definition_file = fs::absolute(d.file).lexically_normal();
  const std::string program = programPath(d.command.front(), d.file);
  out.missing = [program, file = d.file] { return programProblem(program, file); };
  out.exporter = definedExport(d.input);
  if (out.exporter) out.cannot_express = [ex = *out.exporter](const Scene& s) { return refusalOf(ex, s); };
  out.render = [d](const Scene& scene, const RenderRequest& request, RenderInfo* info) {
    return renderDefined(d, scene, request, info);
  };
  return out;
}

void registerRendererFiles(const std::vector<std::string>& files) {
  Registry& reg = registry();
  std::vector<std::pair<Renderer, std::string>> loaded;  // each renderer and its file
  for (const std::string& f : files) loaded.emplace_back(loadRendererFile(f), f);
  std::stable_sort(loaded.begin(), loaded.end(), [](const auto& a, const auto& b) { return a.first.id < b.first.id; });
  for (auto& [r, f] : loaded) {
    try {
      reg.add(std::move(r));
    } catch (const std::invalid_argument& e) {
      throw std::runtime_error(f + ": name: " + e.what());
    }
  }
  addGoldenSets(reg);
  // Pair names are the renderers' ids joined by '-', which ids contain
  // too: names whose pairs would share a name (m-n beside reference-m and
  // n) are refused, naming the files that define them.
  const std::vector<std::string> ids = reg.ids();
  if (const std::optional<PairKeyClash> clash = pairKeyClash(ids)) {
    std::vector<std::string> defined;  // "FILE: name \"ID\"" of each renderer file involved
    for (size_t i : {clash->first.a, clash->first.b, clash->second.a, clash->second.b}) {
      const Renderer* r = &reg.at(ids[i]);
      if (!r->images_of.empty()) r = &reg.at(r->images_of);  // a golden set: its renderer's file
      const std::string d = r->definition_file.string() + ": name \"" + r->id + "\"";
      if (!r->definition_file.empty() && std::find(defined.begin(), defined.end(), d) == defined.end())
        defined.push_back(d);
    }
    std::string files;
    for (const std::string& d : defined) files += (files.empty() ? "" : ", ") + d;
    auto named = [&ids](const RendererPair& p) { return ids[p.a] + " + " + ids[p.b]; };
    throw std::runtime_error(files + ": the pairs " + named(clash->first) + " and " + named(clash->second) +
                             " would both be named \"" + pairKey(ids[clash->first.a], ids[clash->first.b]) +
                             "\" (pair names join the renderers' names with '-'; results.json, the heat maps "
                             "and JUnit name each pair once): rename one of these renderers");
  }
}

}  // namespace xval::renderers
