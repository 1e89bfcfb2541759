// The renderer registry: the one place that knows every renderer.
//
// Every command takes its renderer list and its dispatch from here:
// `render --renderer`, `crosscheck --renderer`, `bench --renderers`,
// `validate` (one job per scene and every-scene renderer, the pairs, who
// deviates), `xval renderers`, and the keys of a scene file's `tolerances`.
// The registry's order is the order of jobs, pairs and listings.
//
// The built-in renderers are added when the registry is first used
// (registry.cpp: one line each); more can be added at run time with add()
// (before anything renders: the registry is not locked against a
// concurrent add).
//
//   #include "renderers/registry.h"
//   const auto& r = xval::renderers::registry().at("povray");
//   Image img = r.render(scene, {work_dir, timeout, {}}, &info);
#pragma once

#include <cstddef>
#include <deque>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "renderers/renderer.h"

namespace xval::renderers {

// How long a version probe may take before it is killed (seconds).
inline constexpr double kVersionTimeoutSeconds = 60.0;

struct Availability {
  bool available = false;
  std::string reason;  // why not (what is missing or failing); empty when available
};

class Registry {
 public:
  // Adds a renderer at the end. Throws std::invalid_argument for an id
  // that is empty, not [a-z0-9-]+, or already registered, for a second
  // reference renderer, or for a renderer without a render function.
  void add(Renderer renderer);

  // Every renderer, in registry order (references stay valid across add()).
  const std::deque<Renderer>& all() const { return entries_; }
  size_t size() const { return entries_.size(); }
  // Null when no renderer has this id.
  const Renderer* find(std::string_view id) const;
  // Throws std::runtime_error naming the id and listing the registered ones.
  const Renderer& at(std::string_view id) const;
  // The renderer the others are compared against; throws if none is registered.
  const Renderer& reference() const;

  // Ids in registry order: all of them; all but the reference (what a
  // crosscheck and a scene's `tolerances` name); the every-scene ones
  // (what validate renders and compares, and bench times by default).
  std::vector<std::string> ids() const;
  std::vector<std::string> comparedIds() const;
  std::vector<std::string> everySceneIds() const;
  std::vector<const Renderer*> everySceneRenderers() const;
  // What `xval validate` runs by default, in registry order: the
  // every-scene renderers and the geometry checks (Renderer::
  // geometry_passes: blender-import), which validate runs on every scene
  // and records as not expressible, with the reason, where they cannot
  // take it.
  std::vector<std::string> validateIds() const;

  // The version line of the renderer's outside tool (kXvalVersion when it
  // runs none), probed once with a time-out and cached; "unavailable (...)"
  // or "unknown" when the probe fails or prints no version line.
  std::string version(std::string_view id) const;
  // Whether it can render on this machine and, if not, why. Cached.
  Availability availability(std::string_view id) const;

 private:
  std::deque<Renderer> entries_;
  mutable std::mutex cache_lock_;
  mutable std::map<std::string, std::string, std::less<>> versions_;
  mutable std::map<std::string, Availability, std::less<>> availability_;
};

// The process's registry, with the built-in renderers.
Registry& registry();

// "a, b and c" (the ", " and " and " joins of a listing; "a" alone).
std::string joinNames(const std::vector<std::string>& names);

// Whether a scene whose `renderers` field is `scene_renderers` (empty:
// every renderer) is meant for `renderer`: the field names it, or names the
// renderer whose stored images it reads (Renderer::images_of: `golden` for
// a scene meant for the reference renderer, as its golden images are that
// renderer's images).
// The precision model a comparison uses for `r`: its own, or for a golden
// set the model of the renderer whose images it stores.
const PrecisionModel& precisionOf(const Renderer& r);

bool meantFor(const std::vector<std::string>& scene_renderers, const Renderer& renderer);

// An unordered pair of renderers, a before b in registry order.
struct RendererPair {
  size_t a = 0, b = 0;  // indices into the list the pairs were made from
};
// Every unordered pair of n renderers, in registry order: (0,1), (0,2),
// ..., (0,n-1), (1,2), ... (for reference, povray, blender:
// reference-povray, reference-blender, povray-blender).
std::vector<RendererPair> unorderedPairs(size_t n);
// "reference-povray": how results.json and the diff images name a pair
// (the ids of its renderers, a before b in registry order, joined by '-').
std::string pairKey(const std::string& a, const std::string& b);
std::string pairKey(const Renderer& a, const Renderer& b);
// Ids contain '-' too (blender-import, a user's mutant-shininess), so two
// pairs of `ids` may join to one key: reference + m-n and reference-m + n
// are both "reference-m-n" (one heat map, one JUnit test for two pairs).
// The first such clash among the pairs of `ids` (unorderedPairs order), as
// its two pairs; none when every key is distinct.
struct PairKeyClash {
  RendererPair first, second;
};
std::optional<PairKeyClash> pairKeyClash(const std::vector<std::string>& ids);

// A pair's verdict, as attribute and deviating read them: it passes, it
// fails (hard: a mask disagreement or an unexplained error over the cap,
// or nothing covered: image/pair_failure.h), or it fails only on the
// fraction within tolerance (soft: many small differences under the cap,
// such as rounding). A negative verdict: the pair was not compared.
constexpr int kPairPasses = 1, kPairFails = 0, kPairFailsOnlyOnFraction = 2;

// Who deviates, from the pairwise verdicts of `renderers` (verdicts[k] for
// unorderedPairs(renderers.size())[k], as above).
//   - any pair not compared: "incomplete (a renderer failed)";
//   - every pair passes: "all three agree" ("both agree", "all N agree");
//   - a majority M (more than half of them) agree pairwise and every
//     renderer outside M fails against every member of M (such an M is
//     unique): "X deviates (A and B agree)", "X and Y deviate (...)".
//     M is looked for first with soft failures counted as agreement: a
//     renderer with unexplained differences against the others is named
//     even when the others fail among themselves on the fraction alone,
//     "X deviates (unexplained differences against A and B; A and B fail
//     only on the fraction within tolerance)". When that finds no M and
//     some pair fails hard, nobody is named on soft failures (that would
//     blame a renderer for rounding beside a real fault it is not part
//     of). When every failure is soft, M is looked for with them as
//     failures: "X deviates, only on the fraction within tolerance (A and
//     B agree)";
//   - otherwise the failing pairs: "POV-Ray and Blender disagree (the other
//     pairs agree)" when one pair fails, "A and B disagree; C and D
//     disagree only on the fraction within tolerance" for several, "no two
//     renderers agree" when every pair fails hard ("A and B disagree" for
//     two renderers).
// For three renderers this is the one deviating from the other two.
std::string attribute(const std::vector<const Renderer*>& renderers, const std::vector<int>& verdicts);
// The renderers outside that majority M (indices into the n renderers, in
// order): those attribute names as deviating; empty when every pair passes,
// a pair was not compared, or no majority exists (two renderers never have
// one: neither is to blame on its own).
std::vector<size_t> deviating(size_t n, const std::vector<int>& verdicts);

// The version line an outside tool prints for `argv` (see
// Renderer::version_marker; a 40-character line without spaces, as
// `git rev-parse HEAD` prints, is also taken), waiting at most
// timeout_seconds; "unavailable (<what happened>)" when it cannot run or
// fails, "unknown" when it prints no such line.
std::string probeToolVersion(const std::vector<std::string>& argv, const std::string& marker,
                             double timeout_seconds);

}  // namespace xval::renderers
