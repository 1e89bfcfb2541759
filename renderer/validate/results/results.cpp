// results.json as C++ types: the one reader and the one writer (results.h).
#include "validate/results/results.h"

#include <cmath>
#include <set>
#include <stdexcept>

#include "files/atomic_write.h"
#include "image/metric_criteria.h"
#include "scene/json_reader.h"
#include "scene_file/scene_loader.h"
#include "validate/results/results_shape.h"

namespace xval::results {

namespace {

constexpr PairVerdict kPairVerdicts[] = {PairVerdict::Pass, PairVerdict::Fail, PairVerdict::Error,
                                         PairVerdict::NotExpressible, PairVerdict::Finding};

// The members of one object, read with errors naming the field; whatever
// is not taken is its remainder.
class Fields {
 public:
  // `top`: the file's top level, whose fields read "FILE: cases", not "FILE.cases".
  Fields(const Json& obj, std::string where, bool top = false) : obj_(obj), where_(std::move(where)), sep_(top ? ": " : ".") {
    if (!obj_.is_object()) throw std::runtime_error(where_ + ": expected an object");
  }

  std::string at(const char* key) const { return where_ + sep_ + key; }
  bool has(const char* key) const { return obj_.contains(key); }

  const Json& take(const char* key) {
    if (!obj_.contains(key)) throw std::runtime_error(where_ + ": no \"" + key + "\" field");
    taken_.insert(key);
    return obj_[key];
  }
  const Json* takeOptional(const char* key) { return has(key) ? &take(key) : nullptr; }

  std::string str(const char* key) { return asString(take(key), at(key)); }
  double num(const char* key) { return asNumber(take(key), at(key)); }
  long long integer(const char* key) { return asInteger(take(key), at(key)); }
  bool boolean(const char* key) {
    const Json& v = take(key);
    if (!v.is_boolean()) throw std::runtime_error(at(key) + ": " + v.dump() + ": expected true or false");
    return v.get<bool>();
  }
  std::optional<std::string> optStr(const char* key) {
    return has(key) ? std::optional<std::string>(str(key)) : std::nullopt;
  }
  std::optional<double> optNum(const char* key) { return has(key) ? std::optional<double>(num(key)) : std::nullopt; }
  // A number or null (null: none).
  std::optional<double> numOrNull(const char* key) {
    const Json& v = take(key);
    return v.is_null() ? std::nullopt : std::optional<double>(asNumber(v, at(key)));
  }
  Json json(const char* key) { return has(key) ? take(key) : Json(); }

  // The members not taken, in file order.
  Json rest() const {
    Json out = Json::object();
    for (auto it = obj_.begin(); it != obj_.end(); ++it)
      if (!taken_.count(it.key())) out[it.key()] = it.value();
    return out;
  }

  static std::string asString(const Json& v, const std::string& where) {
    if (!v.is_string()) throw std::runtime_error(where + ": " + v.dump(-1, ' ', false, Json::error_handler_t::replace) + ": expected a string");
    return v.get<std::string>();
  }
  static long long asInteger(const Json& v, const std::string& where) {
    if (v.is_number_integer()) return v.get<long long>();
    // A float that is a whole number in range (the schema's "integer").
    const double d = v.is_number_float() ? v.get<double>() : 0.5;
    if (!(std::fabs(d) < 9.0e18) || std::trunc(d) != d)
      throw std::runtime_error(where + ": " + v.dump(-1, ' ', false, Json::error_handler_t::replace) + ": expected an integer");
    return static_cast<long long>(d);
  }
  static double asNumber(const Json& v, const std::string& where) {
    if (!v.is_number()) throw std::runtime_error(where + ": " + v.dump(-1, ' ', false, Json::error_handler_t::replace) + ": expected a number");
    return v.get<double>();
  }

 private:
  const Json& obj_;
  std::string where_;
  const char* sep_;
  std::set<std::string> taken_;
};

// An object modelled whole: a member the types do not name is refused,
// never dropped.
void refuseRest(const Fields& f) {
  if (!f.rest().empty()) throw std::runtime_error(f.at(f.rest().begin().key().c_str()) + ": not a field here");
}

const Json& asArray(const Json& v, const std::string& where) {
  if (!v.is_array()) throw std::runtime_error(where + ": expected an array");
  return v;
}

template <class T, class Read>
Named<T> named(const Json& v, const std::string& where, Read read) {
  if (!v.is_object()) throw std::runtime_error(where + ": expected an object");
  Named<T> out;
  for (auto it = v.begin(); it != v.end(); ++it) out.emplace_back(it.key(), read(it.value(), where + "." + it.key()));
  return out;
}

std::string index(const std::string& where, size_t i) { return where + "[" + std::to_string(i) + "]"; }

// A number, or null for none.
std::optional<double> numberOrNone(const Json& v, const std::string& where) {
  return v.is_null() ? std::nullopt : std::optional<double>(Fields::asNumber(v, where));
}

Render readRender(const Json& j, const std::string& where) {
  Fields f(j, where);
  Render r;
  r.seconds = f.num("seconds");
  r.render_seconds = f.optNum("render_seconds");
  r.process_seconds = f.optNum("process_seconds");
  r.parse_seconds = f.optNum("parse_seconds");
  r.image = f.optStr("image");
  r.error = f.optStr("error");
  r.not_expressible = f.optStr("not_expressible");
  r.rest = f.rest();
  return r;
}

PairMetrics readMetrics(const Json& j, const std::string& where) {
  Fields f(j, where);
  PairMetrics m;
  m.width = f.integer("width");
  m.height = f.integer("height");
  m.max_abs_16bit = f.num("max_abs_16bit");
  m.p999_abs_16bit = f.num("p999_abs_16bit");
  m.rmse_16bit = f.num("rmse_16bit");
  m.fraction_within = f.num("fraction_within");
  m.psnr_db = f.numOrNull("psnr_db");
  m.mask_disagree = f.integer("mask_disagree");
  m.mask_disagree_explained = f.integer("mask_disagree_explained");
  m.max_unexplained_16bit = f.numOrNull("max_unexplained_16bit");
  m.over_tolerance = named<long long>(f.take("over_tolerance"), f.at("over_tolerance"), Fields::asInteger);
  m.over_tolerance_max_16bit =
      named<std::optional<double>>(f.take("over_tolerance_max_16bit"), f.at("over_tolerance_max_16bit"), numberOrNone);
  Fields t(f.take("tolerance"), f.at("tolerance"));
  m.tolerance.max_abs_16bit = t.num("max_abs_16bit");
  m.tolerance.fraction = t.num("fraction");
  m.tolerance.exclude_backfacing = t.boolean("exclude_backfacing");
  m.tolerance.max_unexplained_16bit = t.num("max_unexplained_16bit");
  if (const Json* criteria = t.takeOptional("metrics")) {
    // Read as a tolerance file's: ids of the table, each under its better
    // direction's key (image/metric_criteria.h).
    const nlohmann::json holder = {{"metrics", nlohmann::json(*criteria)}};
    JsonReader r(holder, "", f.at("tolerance"));
    m.tolerance.metrics = readMetricCriteria(r, "metrics");
  }
  refuseRest(t);
  m.tolerance_reason = f.has("tolerance_reason") ? f.str("tolerance_reason") : std::string();
  if (const Json* values = f.takeOptional("values"))
    m.values = named<std::optional<double>>(*values, f.at("values"), numberOrNone);
  m.rest = f.rest();
  return m;
}

std::vector<std::string> strings(const Json& v, const std::string& where) {
  asArray(v, where);
  std::vector<std::string> out;
  for (size_t i = 0; i < v.size(); ++i) out.push_back(Fields::asString(v[i], index(where, i)));
  return out;
}

// Two or four integers (a pixel, a window).
std::vector<long long> integers(const Json& v, size_t n, const std::string& where) {
  if (!v.is_array() || v.size() != n)
    throw std::runtime_error(where + ": expected " + std::to_string(n) + " integers");
  std::vector<long long> out;
  for (size_t i = 0; i < n; ++i) out.push_back(Fields::asInteger(v[i], index(where, i)));
  return out;
}

ShownPixel readShown(const Json& j, const std::string& where) {
  Fields f(j, where);
  ShownPixel s;
  const std::vector<long long> xy = integers(f.take("pixel"), 2, f.at("pixel"));
  s.x = xy[0], s.y = xy[1];
  s.error_16bit = f.numOrNull("error_16bit");
  s.pixel_class = f.str("class");
  const std::vector<long long> w = integers(f.take("window"), 4, f.at("window"));
  s.window_x = w[0], s.window_y = w[1], s.window_width = w[2], s.window_height = w[3];
  s.heat_map = f.str("heat_map");
  s.renders = named<std::string>(f.take("renders"), f.at("renders"), Fields::asString);
  refuseRest(f);
  return s;
}

// The verdict a pair's fields imply: what a file without a stored one means.
PairVerdict impliedVerdict(const Pair& p) {
  if (p.error) return PairVerdict::Error;
  if (p.not_expressible) return PairVerdict::NotExpressible;
  if (p.pass && p.finding) return *p.pass ? PairVerdict::Fail : PairVerdict::Finding;
  if (p.pass) return *p.pass ? PairVerdict::Pass : PairVerdict::Fail;
  return PairVerdict::Error;
}

Pair readPair(const Json& j, const std::string& where) {
  Fields f(j, where);
  Pair p;
  p.pair = f.str("pair");
  p.error = f.optStr("error");
  p.not_expressible = f.optStr("not_expressible");
  p.heat_map = f.optStr("heat_map");
  p.bound_map = f.optStr("bound_map");
  if (const Json* crops = f.takeOptional("crops")) {
    Fields cf(*crops, f.at("crops"));
    PairCrops pc;
    if (const Json* s = cf.takeOptional("worst_unexplained")) pc.worst_unexplained = readShown(*s, cf.at("worst_unexplained"));
    if (const Json* s = cf.takeOptional("worst_explained")) pc.worst_explained = readShown(*s, cf.at("worst_explained"));
    refuseRest(cf);
    p.crops = pc;
  }
  if (const Json* m = f.takeOptional("metrics")) p.metrics = readMetrics(*m, f.at("metrics"));
  if (f.has("pass")) p.pass = f.boolean("pass");
  if (const Json* failed = f.takeOptional("failed")) p.failed = failedFromJson(*failed, f.at("failed"));
  if (const Json* finding = f.takeOptional("finding")) {
    Fields ff(*finding, f.at("finding"));
    p.finding = PairFinding{ff.str("renderer"), ff.str("why")};
    refuseRest(ff);
    if (!p.pass) throw std::runtime_error(f.at("finding") + ": only a compared pair (with \"pass\") holds a finding");
  }
  p.classification = f.json("classification");
  const PairVerdict implied = impliedVerdict(p);
  if (f.has("verdict")) {
    p.verdict = parsePairVerdict(f.str("verdict"), f.at("verdict"));
    if (p.verdict != implied)
      throw std::runtime_error(f.at("verdict") + ": \"" + pairVerdictName(p.verdict) + "\" but the pair's fields say \"" +
                               pairVerdictName(implied) + "\"");
  } else {
    p.verdict = implied;  // a file from before pairs carried their verdict
  }
  if ((p.verdict == PairVerdict::Pass || p.verdict == PairVerdict::Fail || p.verdict == PairVerdict::Finding) &&
      !p.metrics)
    throw std::runtime_error(where + ": no \"metrics\" field (a compared pair has them)");
  p.rest = f.rest();
  return p;
}

GeometryCheck readCheck(const Json& j, const std::string& where) {
  Fields f(j, where);
  GeometryCheck g;
  g.renderer = f.str("renderer");
  g.against = f.str("against");
  g.verdict = parsePairVerdict(f.str("verdict"), f.at("verdict"));
  if (g.verdict == PairVerdict::Finding)
    throw std::runtime_error(f.at("verdict") + ": \"finding\": a verdict of image pairs, not of geometry checks");
  g.reason = f.optStr("reason");
  if (const Json* mj = f.takeOptional("metrics")) {
    Fields m(*mj, f.at("metrics"));
    GeometryCheckMetrics gm;
    gm.covered = m.integer("covered");
    gm.mask_disagree = m.integer("mask_disagree");
    gm.mask_disagree_silhouette = m.integer("mask_disagree_silhouette");
    gm.compared = m.integer("compared");
    gm.max_depth_rel = m.num("max_depth_rel");
    gm.max_depth_rel_all = m.num("max_depth_rel_all");
    gm.uv_compared = m.integer("uv_compared");
    gm.max_uv = m.num("max_uv");
    gm.max_uv_all = m.num("max_uv_all");
    gm.depth_edges = m.integer("depth_edges");
    gm.edge_over = m.integer("edge_over");
    refuseRest(m);
    g.metrics = gm;
  }
  if (const Json* bj = f.takeOptional("bounds")) {
    Fields b(*bj, f.at("bounds"));
    g.bounds = GeometryCheckBounds{b.num("max_silhouette_fraction"), b.num("max_depth_rel"), b.num("max_uv"),
                                   b.num("max_edge_fraction"), b.str("reason")};
    refuseRest(b);
  }
  const bool compared = g.verdict == PairVerdict::Pass || g.verdict == PairVerdict::Fail;
  if (compared != (g.metrics && g.bounds))
    throw std::runtime_error(where + ": a " + (compared ? "compared" : "not compared") + " check " +
                             (compared ? "needs" : "has no") + " \"metrics\" and \"bounds\"");
  g.rest = f.rest();
  return g;
}

Case readCase(const Json& j, const std::string& where) {
  Fields f(j, where);
  Case c;
  c.scene = f.str("scene");
  // The pairs are read first: a results file without them is named as such.
  const Json& pairs = asArray(f.take("pairs"), f.at("pairs"));
  c.file = f.has("file") ? f.str("file") : std::string();
  c.reproduce = f.optStr("reproduce");
  c.renders = named<Render>(f.take("renders"), f.at("renders"), readRender);
  if (const Json* l = f.takeOptional("left_out"))
    c.left_out = named<std::string>(*l, f.at("left_out"), Fields::asString);
  if (const Json* ws = f.takeOptional("warnings")) {
    asArray(*ws, f.at("warnings"));
    for (size_t i = 0; i < ws->size(); ++i) {
      Fields w((*ws)[i], index(f.at("warnings"), i));
      c.warnings.push_back({w.str("code"), w.str("subject"), w.str("message")});
      refuseRest(w);
    }
  }
  for (size_t i = 0; i < pairs.size(); ++i) c.pairs.push_back(readPair(pairs[i], index(f.at("pairs"), i)));
  if (const Json* cs = f.takeOptional("colour_stats")) {
    Fields s(*cs, f.at("colour_stats"));
    c.colour_stats = ColourStats{s.integer("lit_pixels"), s.num("mean_chroma"), s.num("mean_albedo_chroma"),
                                 s.num("grey_fraction"), s.num("hue_error_deg")};
    refuseRest(s);
  }
  if (const Json* gs = f.takeOptional("geometry_checks")) {
    asArray(*gs, f.at("geometry_checks"));
    for (size_t i = 0; i < gs->size(); ++i)
      c.geometry_checks.push_back(readCheck((*gs)[i], index(f.at("geometry_checks"), i)));
  }
  c.attribution = f.has("attribution") ? f.str("attribution") : std::string();
  if (const Json* d = f.takeOptional("deviating")) c.deviating = strings(*d, f.at("deviating"));
  if (f.has("verdict")) c.verdict = validation::parseCaseVerdict(f.str("verdict"), f.at("verdict"));
  c.pass = f.has("pass") ? f.boolean("pass") : false;
  if (c.verdict && c.pass != (*c.verdict == validation::CaseVerdict::Pass))
    throw std::runtime_error(f.at("pass") + ": " + (c.pass ? "true" : "false") + " but the verdict is \"" +
                             validation::verdictName(*c.verdict) + "\"");
  c.rest = f.rest();
  return c;
}

Json renderJson(const Render& r) {
  Json j;
  j["seconds"] = r.seconds;
  if (r.not_expressible) j["not_expressible"] = *r.not_expressible;
  if (r.image) j["image"] = *r.image;
  if (r.render_seconds) j["render_seconds"] = *r.render_seconds;
  if (r.process_seconds) j["process_seconds"] = *r.process_seconds;
  if (r.parse_seconds) j["parse_seconds"] = *r.parse_seconds;
  if (r.error) j["error"] = *r.error;
  j.update(r.rest);
  return j;
}

Json numberOrNull(const std::optional<double>& v) { return v ? Json(*v) : Json(nullptr); }

Json metricsJson(const PairMetrics& m) {
  Json j;
  j["width"] = m.width;
  j["height"] = m.height;
  j["max_abs_16bit"] = m.max_abs_16bit;
  j["p999_abs_16bit"] = m.p999_abs_16bit;
  j["rmse_16bit"] = m.rmse_16bit;
  j["psnr_db"] = numberOrNull(m.psnr_db);
  j["fraction_within"] = m.fraction_within;
  j["mask_disagree"] = m.mask_disagree;
  j["mask_disagree_explained"] = m.mask_disagree_explained;
  j["max_unexplained_16bit"] = numberOrNull(m.max_unexplained_16bit);
  j["over_tolerance"] = Json::object();
  for (const auto& [k, n] : m.over_tolerance) j["over_tolerance"][k] = n;
  j["over_tolerance_max_16bit"] = Json::object();
  for (const auto& [k, v] : m.over_tolerance_max_16bit) j["over_tolerance_max_16bit"][k] = numberOrNull(v);
  j["tolerance"] = {{"max_abs_16bit", m.tolerance.max_abs_16bit},
                    {"fraction", m.tolerance.fraction},
                    {"exclude_backfacing", m.tolerance.exclude_backfacing},
                    {"max_unexplained_16bit", m.tolerance.max_unexplained_16bit}};
  if (!m.tolerance.metrics.empty()) j["tolerance"]["metrics"] = metricCriteriaJson(m.tolerance.metrics);
  j["tolerance_reason"] = m.tolerance_reason;
  if (m.values) {
    j["values"] = Json::object();
    for (const auto& [id, v] : *m.values) j["values"][id] = numberOrNull(v);
  }
  j.update(m.rest);
  return j;
}

Json shownJson(const ShownPixel& s) {
  Json j;
  j["pixel"] = {s.x, s.y};
  j["error_16bit"] = numberOrNull(s.error_16bit);
  j["class"] = s.pixel_class;
  j["window"] = {s.window_x, s.window_y, s.window_width, s.window_height};
  j["heat_map"] = s.heat_map;
  j["renders"] = Json::object();
  for (const auto& [id, crop] : s.renders) j["renders"][id] = crop;
  return j;
}

Json pairJson(const Pair& p) {
  Json j;
  j["pair"] = p.pair;
  j["verdict"] = pairVerdictName(p.verdict);
  if (p.error) j["error"] = *p.error;
  if (p.not_expressible) j["not_expressible"] = *p.not_expressible;
  if (p.heat_map) j["heat_map"] = *p.heat_map;
  if (p.bound_map) j["bound_map"] = *p.bound_map;
  if (p.crops) {
    j["crops"] = Json::object();
    if (p.crops->worst_unexplained) j["crops"]["worst_unexplained"] = shownJson(*p.crops->worst_unexplained);
    if (p.crops->worst_explained) j["crops"]["worst_explained"] = shownJson(*p.crops->worst_explained);
  }
  if (p.metrics) j["metrics"] = metricsJson(*p.metrics);
  if (p.pass) j["pass"] = *p.pass;
  if (p.pass || !p.failed.empty()) j["failed"] = Json::parse(failedJson(p.failed).dump());
  if (p.finding) j["finding"] = {{"renderer", p.finding->renderer}, {"why", p.finding->why}};
  if (!p.classification.is_null()) j["classification"] = p.classification;
  j.update(p.rest);
  return j;
}

Json checkJson(const GeometryCheck& g) {
  Json j;
  j["renderer"] = g.renderer;
  j["against"] = g.against;
  j["verdict"] = pairVerdictName(g.verdict);
  if (g.reason) j["reason"] = *g.reason;
  if (const auto& m = g.metrics)
    j["metrics"] = {{"covered", m->covered},
                    {"mask_disagree", m->mask_disagree},
                    {"mask_disagree_silhouette", m->mask_disagree_silhouette},
                    {"compared", m->compared},
                    {"max_depth_rel", m->max_depth_rel},
                    {"max_depth_rel_all", m->max_depth_rel_all},
                    {"uv_compared", m->uv_compared},
                    {"max_uv", m->max_uv},
                    {"max_uv_all", m->max_uv_all},
                    {"depth_edges", m->depth_edges},
                    {"edge_over", m->edge_over}};
  if (const auto& b = g.bounds)
    j["bounds"] = {{"max_silhouette_fraction", b->max_silhouette_fraction},
                   {"max_depth_rel", b->max_depth_rel},
                   {"max_uv", b->max_uv},
                   {"max_edge_fraction", b->max_edge_fraction},
                   {"reason", b->reason}};
  j.update(g.rest);
  return j;
}

Json caseJson(const Case& c) {
  Json j;
  j["scene"] = c.scene;
  j["file"] = c.file;
  if (c.reproduce) j["reproduce"] = *c.reproduce;
  j["renders"] = Json::object();
  for (const auto& [id, r] : c.renders) j["renders"][id] = renderJson(r);
  if (!c.left_out.empty()) {
    j["left_out"] = Json::object();
    for (const auto& [id, why] : c.left_out) j["left_out"][id] = why;
  }
  for (const Warning& w : c.warnings)
    j["warnings"].push_back({{"code", w.code}, {"subject", w.subject}, {"message", w.message}});
  j["pairs"] = Json::array();
  for (const Pair& p : c.pairs) j["pairs"].push_back(pairJson(p));
  if (const auto& s = c.colour_stats)
    j["colour_stats"] = {{"lit_pixels", s->lit_pixels},
                         {"mean_chroma", s->mean_chroma},
                         {"mean_albedo_chroma", s->mean_albedo_chroma},
                         {"grey_fraction", s->grey_fraction},
                         {"hue_error_deg", s->hue_error_deg}};
  for (const GeometryCheck& g : c.geometry_checks) j["geometry_checks"].push_back(checkJson(g));
  j["attribution"] = c.attribution;
  if (!c.deviating.empty()) j["deviating"] = c.deviating;
  if (c.verdict) j["verdict"] = validation::verdictName(*c.verdict);
  j["pass"] = c.pass;
  j.update(c.rest);
  return j;
}

}  // namespace

const char* pairVerdictName(PairVerdict v) {
  switch (v) {
    case PairVerdict::Pass: return "pass";
    case PairVerdict::Fail: return "fail";
    case PairVerdict::Error: return "error";
    case PairVerdict::NotExpressible: return "not_expressible";
    case PairVerdict::Finding: return "finding";
  }
  throw std::logic_error("pairVerdictName: not a PairVerdict");
}

PairVerdict parsePairVerdict(const std::string& word, const std::string& where) {
  for (PairVerdict v : kPairVerdicts)
    if (word == pairVerdictName(v)) return v;
  throw std::runtime_error(where + ": \"" + word + "\": expected pass, fail, error, not_expressible or finding");
}

const Render* Case::render(const std::string& id) const {
  for (const auto& [rid, r] : renders)
    if (rid == id) return &r;
  return nullptr;
}

const Pair* Case::findPair(const std::string& key) const {
  for (const Pair& p : pairs)
    if (p.pair == key) return &p;
  return nullptr;
}

Results resultsFromJson(const Json& j, const std::string& where) {
  if (!j.is_object()) throw std::runtime_error(where + ": expected an object");
  Fields f(j, where, true);
  Results r;
  // The cases first: a file that is no results file is named by its cases.
  const Json& cases = asArray(f.take("cases"), f.at("cases"));
  for (size_t i = 0; i < cases.size(); ++i) r.cases.push_back(readCase(cases[i], where + ": " + index("cases", i)));
  r.format = f.has("format") ? f.str("format") : std::string();
  if (const Json* p = f.takeOptional("provenance"))
    r.provenance = named<std::string>(*p, f.at("provenance"), Fields::asString);
  r.wall_seconds = f.has("wall_seconds") ? f.num("wall_seconds") : 0.0;
  if (const Json* rs = f.takeOptional("renderers")) r.renderers = strings(*rs, f.at("renderers"));
  if (const Json* pc = f.takeOptional("paper_claims")) {
    Fields pf(*pc, f.at("paper_claims"));
    PaperClaims claims;
    claims.scenes = strings(pf.take("scenes"), pf.at("scenes"));
    const Json& list = asArray(pf.take("claims"), pf.at("claims"));
    for (size_t i = 0; i < list.size(); ++i) {
      Fields cf(list[i], index(pf.at("claims"), i));
      claims.claims.push_back({cf.str("claim"), cf.str("condition"), cf.str("measured"), cf.boolean("holds")});
      refuseRest(cf);
    }
    refuseRest(pf);
    r.paper_claims = claims;
  }
  if (const Json* s = f.takeOptional("sections")) {
    Fields sf(*s, f.at("sections"));
    r.extremes_section = sf.optStr("extremes");
    r.tradeoff_section = sf.optStr("tradeoff");
    refuseRest(sf);
  }
  r.rest = f.rest();
  return r;
}

Pair pairFromJson(const Json& j, const std::string& where) { return readPair(j, where); }

Json toJson(const Pair& p) { return pairJson(p); }
Json toJson(const GeometryCheck& g) { return checkJson(g); }

Results readResults(const std::filesystem::path& file) {
  const Json j = parseOrderedJsonText(readJsonFile(file, "results file"), file.string());
  checkResultsShape(j, file.string());
  return resultsFromJson(j, file.string());
}

Json toJson(const Results& r) {
  Json j;
  j["format"] = r.format;
  j["provenance"] = Json::object();
  for (const auto& [k, v] : r.provenance) j["provenance"][k] = v;
  j["wall_seconds"] = r.wall_seconds;
  if (!r.renderers.empty()) j["renderers"] = r.renderers;
  j["cases"] = Json::array();
  for (const Case& c : r.cases) j["cases"].push_back(caseJson(c));
  if (r.paper_claims) {
    j["paper_claims"] = {{"scenes", r.paper_claims->scenes}, {"claims", Json::array()}};
    for (const PaperClaim& c : r.paper_claims->claims)
      j["paper_claims"]["claims"].push_back(
          {{"claim", c.claim}, {"condition", c.condition}, {"measured", c.measured}, {"holds", c.holds}});
  }
  if (r.extremes_section || r.tradeoff_section) {
    j["sections"] = Json::object();
    if (r.extremes_section) j["sections"]["extremes"] = *r.extremes_section;
    if (r.tradeoff_section) j["sections"]["tradeoff"] = *r.tradeoff_section;
  }
  j.update(r.rest);
  return j;
}

void writeResults(const std::filesystem::path& file, const Results& r) {
  // Errors quote tools' logs and files' names, which are bytes: any that
  // are not UTF-8 are written as U+FFFD, never a file that cannot be written.
  writeFileAtomically(file, toJson(r).dump(2, ' ', false, Json::error_handler_t::replace) + "\n");
}

}  // namespace xval::results
