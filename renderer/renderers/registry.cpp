// The renderer registry (registry.h) and the built-in renderers' list.
#include "renderers/registry.h"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <fstream>
#include <stdexcept>

#include "files/scratch_folder.h"
#include "process/run_process.h"
#include "scene_file/scene_loader.h"

// The built-in renderers, in registry order (the order of validate's jobs,
// of the pairs and of every listing). Adding a renderer: its file
// renderers/<name>.cpp defining `Renderer <name>Renderer()`, and its name
// on this line.
#define XVAL_BUILTIN_RENDERERS(X) X(reference) X(povray) X(povrayNative) X(blender) X(blenderNative) X(blenderImport) X(eevee) X(eeveeNative) X(gl) X(golden)

namespace xval::renderers {

#define XVAL_DECLARE_RENDERER(name) Renderer name##Renderer();
XVAL_BUILTIN_RENDERERS(XVAL_DECLARE_RENDERER)
#undef XVAL_DECLARE_RENDERER

namespace {

bool validId(const std::string& id) {
  if (id.empty() || id.front() == '-') return false;
  return std::all_of(id.begin(), id.end(),
                     [](char c) { return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-'; });
}

// A scene file's `tolerances` may name every renderer compared against the
// reference (scene_file/scene_loader.h); installed before main() runs.
const bool kToleranceKeysInstalled =
    (setToleranceRenderers([] { return registry().comparedIds(); }),
     setSceneRenderers([] { return registry().ids(); }), true);

}  // namespace

void Registry::add(Renderer r) {
  if (!validId(r.id))
    throw std::invalid_argument("renderer id \"" + r.id +
                                "\": expected lower-case letters, digits and '-' (it names files)");
  if (find(r.id)) throw std::invalid_argument("renderer id \"" + r.id + "\": already registered");
  if (r.reference && std::any_of(entries_.begin(), entries_.end(), [](const Renderer& e) { return e.reference; }))
    throw std::invalid_argument("renderer \"" + r.id + "\": a second reference renderer (" +
                                reference().id + " is the reference)");
  if (!r.render) throw std::invalid_argument("renderer \"" + r.id + "\": no render function");
  if (r.display_name.empty()) r.display_name = r.id;
  entries_.push_back(std::move(r));
}

const Renderer* Registry::find(std::string_view id) const {
  if (const std::string alias = goldenAlias(id); !alias.empty()) return find(alias);
  for (const auto& e : entries_)
    if (e.id == id) return &e;
  return nullptr;
}

const Renderer& Registry::at(std::string_view id) const {
  if (const Renderer* r = find(id)) return *r;
  throw std::runtime_error("renderer \"" + std::string(id) + "\": unknown, expected one of " + joinNames(ids()) +
                           " (xval renderers lists them)");
}

const Renderer& Registry::reference() const {
  for (const auto& e : entries_)
    if (e.reference) return e;
  throw std::runtime_error("no reference renderer is registered");
}

std::vector<std::string> Registry::ids() const {
  std::vector<std::string> out;
  for (const auto& e : entries_) out.push_back(e.id);
  return out;
}

std::vector<std::string> Registry::comparedIds() const {
  std::vector<std::string> out;
  for (const auto& e : entries_)
    if (!e.reference) out.push_back(e.id);
  return out;
}

std::vector<std::string> Registry::everySceneIds() const {
  std::vector<std::string> out;
  for (const Renderer* e : everySceneRenderers()) out.push_back(e->id);
  return out;
}

std::vector<const Renderer*> Registry::everySceneRenderers() const {
  std::vector<const Renderer*> out;
  for (const auto& e : entries_)
    if (e.every_scene) out.push_back(&e);
  return out;
}

std::vector<std::string> Registry::validateIds() const {
  std::vector<std::string> out;
  for (const auto& e : entries_)
    if (e.every_scene || e.geometry_passes) out.push_back(e.id);
  return out;
}

std::string Registry::version(std::string_view id) const {
  const Renderer& r = at(id);
  // Cached by what is probed: renderers of one tool (blender, eevee) run
  // its version command once.
  std::string key(id);
  if (r.external()) {
    key = r.version_marker;
    for (const std::string& w : r.version_command) key += '\0' + w;
  }
  {
    std::lock_guard<std::mutex> g(cache_lock_);
    if (auto it = versions_.find(key); it != versions_.end()) return it->second;
  }
  const std::string v = r.external() ? probeToolVersion(r.version_command, r.version_marker, kVersionTimeoutSeconds)
                                     : std::string(kXvalVersion);
  std::lock_guard<std::mutex> g(cache_lock_);
  return versions_.emplace(key, v).first->second;
}

Availability Registry::availability(std::string_view id) const {
  const Renderer& r = at(id);
  {
    std::lock_guard<std::mutex> g(cache_lock_);
    if (auto it = availability_.find(id); it != availability_.end()) return it->second;
  }
  Availability a{true, ""};
  if (r.external() && findOnPath(r.version_command.front()).empty()) {
    const char* path = std::getenv("PATH");
    a = {false, "'" + r.version_command.front() + "' not found on PATH (" + (path ? path : "PATH unset") + ")"};
  }
  if (a.available && r.missing) {
    const std::string m = r.missing();
    if (!m.empty()) a = {false, m};
  }
  if (a.available && r.external()) {
    const std::string v = version(id);
    if (v.rfind("unavailable", 0) == 0) {
      std::string argv;
      for (const auto& w : r.version_command) argv += (argv.empty() ? "" : " ") + w;
      a = {false, "`" + argv + "` failed: " + v};
    }
  }
  std::lock_guard<std::mutex> g(cache_lock_);
  return availability_.emplace(std::string(id), a).first->second;
}

Registry& registry() {
  static Registry* r = [] {
    auto* reg = new Registry;  // never destroyed: renderers may be used by exiting threads
#define XVAL_ADD_RENDERER(name) reg->add(name##Renderer());
    XVAL_BUILTIN_RENDERERS(XVAL_ADD_RENDERER)
#undef XVAL_ADD_RENDERER
    addGoldenSets(*reg);
    return reg;
  }();
  return *r;
}

std::string joinNames(const std::vector<std::string>& names) {
  std::string out;
  for (size_t k = 0; k < names.size(); ++k)
    out += (k == 0 ? "" : k + 1 == names.size() ? " and " : ", ") + names[k];
  return out;
}

const PrecisionModel& precisionOf(const Renderer& r) {
  if (r.images_of.empty()) return r.precision;
  const Renderer* maker = registry().find(r.images_of);
  return maker ? maker->precision : r.precision;
}

bool meantFor(const std::vector<std::string>& scene_renderers, const Renderer& renderer) {
  const auto named = [&](const std::string& id) {
    return std::find(scene_renderers.begin(), scene_renderers.end(), id) != scene_renderers.end();
  };
  return scene_renderers.empty() || named(renderer.id) || (!renderer.images_of.empty() && named(renderer.images_of));
}

std::vector<RendererPair> unorderedPairs(size_t n) {
  std::vector<RendererPair> out;
  for (size_t a = 0; a < n; ++a)
    for (size_t b = a + 1; b < n; ++b) out.push_back({a, b});
  return out;
}

std::string pairKey(const std::string& a, const std::string& b) { return a + "-" + b; }
std::string pairKey(const Renderer& a, const Renderer& b) { return pairKey(a.id, b.id); }

std::optional<PairKeyClash> pairKeyClash(const std::vector<std::string>& ids) {
  std::map<std::string, RendererPair> seen;
  for (const RendererPair& p : unorderedPairs(ids.size())) {
    const auto [it, added] = seen.emplace(pairKey(ids[p.a], ids[p.b]), p);
    if (!added) return PairKeyClash{it->second, p};
  }
  return std::nullopt;
}

namespace {
// No majority: say which pairs fail. "POV-Ray and Blender disagree (the
// other pairs agree)" for one failing pair; "no two renderers agree" when
// every pair fails hard; otherwise the failing pairs, "A and B disagree;
// C and D disagree only on the fraction within tolerance; ...".
std::string failingPairsText(const std::vector<const Renderer*>& rs, const std::vector<RendererPair>& pairs,
                             const std::vector<int>& verdicts) {
  std::vector<std::string> failing;
  size_t hard = 0;
  for (size_t k = 0; k < pairs.size(); ++k)
    if (verdicts[k] == kPairFails || verdicts[k] == kPairFailsOnlyOnFraction) {
      hard += verdicts[k] == kPairFails;
      failing.push_back(rs[pairs[k].a]->sentenceSubject() + " and " + rs[pairs[k].b]->display_name + " disagree" +
                        (verdicts[k] == kPairFails ? "" : " only on the fraction within tolerance"));
    }
  if (hard == pairs.size()) return pairs.size() == 1 ? failing[0] : "no two renderers agree";
  std::string out;
  for (size_t k = 0; k < failing.size(); ++k) out += (k == 0 ? "" : "; ") + failing[k];
  return failing.size() == 1 && pairs.size() > 1 ? out + " (the other pairs agree)" : out;
}

// The majority M of n renderers whose pairs agree (agree[k] for
// unorderedPairs(n)[k]): more than half, agreeing pairwise, every other
// renderer disagreeing with each of M; the renderers outside it, or none.
// Two such sets would share a member (both are over half) and then one's
// outsider would agree with it: M is unique, so the first found is the one.
std::vector<size_t> outsideMajority(size_t n, const std::vector<RendererPair>& pairs, const std::vector<bool>& agree) {
  // pass[a][b]: renderers a and b agree.
  std::vector<std::vector<bool>> pass(n, std::vector<bool>(n, true));
  for (size_t k = 0; k < pairs.size(); ++k) pass[pairs[k].a][pairs[k].b] = pass[pairs[k].b][pairs[k].a] = agree[k];
  for (uint32_t m = 1; n <= 20 && m < (uint32_t(1) << n); ++m) {  // 2^n subsets: not for more
    const size_t size = size_t(std::popcount(m));
    if (2 * size <= n || size == n) continue;
    auto in = [m](size_t k) { return (m >> k) & 1u; };
    bool ok = true;
    for (size_t a = 0; a < n && ok; ++a)
      for (size_t b = a + 1; b < n && ok; ++b)
        if (in(a) && in(b)) ok = pass[a][b];
        else if (in(a) != in(b)) ok = !pass[a][b];
    if (!ok) continue;
    std::vector<size_t> out;
    for (size_t k = 0; k < n; ++k)
      if (!in(k)) out.push_back(k);
    return out;
  }
  return {};
}

// Who deviates (registry.h attribute), and how M was found: with soft
// failures counted as agreement (`lenient`), or as failures.
struct Deviation {
  std::vector<size_t> out;
  bool lenient = false;
};

Deviation deviation(size_t n, const std::vector<int>& verdicts, const char* caller) {
  const std::vector<RendererPair> pairs = unorderedPairs(n);
  if (verdicts.size() != pairs.size())
    throw std::invalid_argument(std::string(caller) + ": " + std::to_string(verdicts.size()) + " verdicts for " +
                                std::to_string(n) + " renderers (expected " + std::to_string(pairs.size()) + ")");
  auto known = [](int v) { return v == kPairPasses || v == kPairFails || v == kPairFailsOnlyOnFraction; };
  if (n < 2 || !std::all_of(verdicts.begin(), verdicts.end(), known) ||
      std::all_of(verdicts.begin(), verdicts.end(), [](int v) { return v == kPairPasses; }))
    return {};
  std::vector<bool> agree_lenient, agree_strict;
  for (int v : verdicts) {
    agree_lenient.push_back(v != kPairFails);
    agree_strict.push_back(v == kPairPasses);
  }
  if (std::vector<size_t> out = outsideMajority(n, pairs, agree_lenient); !out.empty()) return {out, true};
  // A hard failure no majority explains: a majority found on soft failures
  // would blame a renderer for rounding.
  if (std::find(verdicts.begin(), verdicts.end(), kPairFails) != verdicts.end()) return {};
  return {outsideMajority(n, pairs, agree_strict), false};
}
}  // namespace

std::vector<size_t> deviating(size_t n, const std::vector<int>& verdicts) {
  return deviation(n, verdicts, "deviating").out;
}

std::string attribute(const std::vector<const Renderer*>& rs, const std::vector<int>& verdicts) {
  const size_t n = rs.size();
  const std::vector<RendererPair> pairs = unorderedPairs(n);
  const Deviation d = deviation(n, verdicts, "attribute");
  if (n < 2) return "nothing compared (fewer than two renderers)";
  if (std::any_of(verdicts.begin(), verdicts.end(), [](int v) { return v < 0; }))
    return "incomplete (a renderer failed)";
  if (std::all_of(verdicts.begin(), verdicts.end(), [](int v) { return v == kPairPasses; }))
    return n == 2 ? "both agree" : n == 3 ? "all three agree" : "all " + std::to_string(n) + " agree";
  if (!d.out.empty()) {
    auto deviates = [&](size_t k) { return std::find(d.out.begin(), d.out.end(), k) != d.out.end(); };
    std::vector<std::string> deviators, agreeing, soft;
    for (size_t k = 0; k < n; ++k)
      if (deviates(k)) deviators.push_back(rs[k]->sentenceSubject());
      else agreeing.push_back(rs[k]->display_name);
    for (size_t k = 0; k < pairs.size(); ++k)
      if (verdicts[k] == kPairFailsOnlyOnFraction && !deviates(pairs[k].a) && !deviates(pairs[k].b))
        soft.push_back(rs[pairs[k].a]->sentenceSubject() + " and " + rs[pairs[k].b]->display_name);
    const std::string verb = deviators.size() == 1 ? " deviates" : " deviate";
    if (!d.lenient)
      return joinNames(deviators) + verb + ", only on the fraction within tolerance (" + joinNames(agreeing) + " agree)";
    if (soft.empty()) return joinNames(deviators) + verb + " (" + joinNames(agreeing) + " agree)";
    std::string soft_text;
    for (size_t k = 0; k < soft.size(); ++k) soft_text += (k == 0 ? "" : ", ") + soft[k];
    return joinNames(deviators) + verb + " (unexplained differences against " + joinNames(agreeing) + "; " + soft_text +
           " fail only on the fraction within tolerance)";
  }
  return failingPairsText(rs, pairs, verdicts);
}

std::string probeToolVersion(const std::vector<std::string>& argv, const std::string& marker,
                             double timeout_seconds) {
  namespace fs = std::filesystem;
  const ScratchFolder scratch("version");
  const fs::path log = scratch.dir() / "version.log";
  const ProcessResult r = runProcess(argv, fs::current_path(), log, timeout_seconds);
  std::string found = "unknown";
  if (!r.ok()) {
    found = "unavailable (" + r.describe() + ")";
  } else {
    std::ifstream in(log);
    std::string line;
    while (std::getline(in, line))
      if ((!marker.empty() && line.find(marker) != std::string::npos) || line.find("version") != std::string::npos ||
          (line.size() == 40 && line.find(' ') == std::string::npos)) {
        found = line;
        break;
      }
  }
  return found;
}

}  // namespace xval::renderers
