#include "validate/report.h"
#include "validate/report_metrics.h"

#include "files/atomic_write.h"
#include "image/heat_map.h"

#include <glm/glm.hpp>
#include <map>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>

#include "image/image.h"
#include "image/pair_failure.h"
#include "process/run_process.h"
#include "render/geometry_passes.h"
#include "renderers/registry.h"
#include "scene/json_reader.h"
#include "scene_file/scene_loader.h"
#include "text/number_text.h"
#include "validate/extremes/report_section.h"
#include "validate/report_pixels.h"
#include "validate/results/results.h"
#include "validate/tolerances.h"
#include "validate/tradeoff/report_section.h"
#include "validate/results/case_verdict.h"
#include "validate/results/geometry_checks.h"

namespace xval {

namespace fs = std::filesystem;
using J = nlohmann::ordered_json;

std::string htmlEscape(const std::string& s) {
  std::string o;
  for (char c : s) {
    switch (c) {
      case '&': o += "&amp;"; break;
      case '<': o += "&lt;"; break;
      case '>': o += "&gt;"; break;
      case '"': o += "&quot;"; break;
      case '\'': o += "&#39;"; break;
      default: o += c;
    }
  }
  return o;
}

namespace {

// The cases as the report lists them (pointers into the results read).
using Cases = std::vector<const results::Case*>;

// Heat maps: at full resolution up to this size; larger ones reduced by
// their block maximum (image/heat_map.h maxDownscaled).

// gnuplot string: only [A-Za-z0-9_.-] of a name, the rest '_'.
std::string gnuplotSafe(const std::string& n) {
  std::string safe;
  for (char ch : n) safe += (std::isalnum(static_cast<unsigned char>(ch)) || ch == '_' || ch == '-' || ch == '.') ? ch : '_';
  return safe;
}

// The run's renderers in their one order: results.json `renderers` (the
// registry's order when validate ran: the built-in renderers, then the
// users' by name, renderers/renderer_file.h), then -- for a results.json
// without it -- any other renderer of the cases' renders, in the order of
// its first appearance. The summary, the plot and each case's renders
// follow it, so two runs of the same renderers show them in the same order
// whatever the order of the command line or of the cases' verdicts.
std::vector<std::string> runRenderers(const results::Results& results) {
  std::vector<std::string> ids;
  auto add = [&ids](const std::string& id) {
    if (std::find(ids.begin(), ids.end(), id) == ids.end()) ids.push_back(id);
  };
  for (const std::string& id : results.renderers) add(id);
  for (const results::Case& c : results.cases)
    for (const auto& [id, render] : c.renders) add(id);
  return ids;
}

// The image pairs of the run and the renderers they pair.
struct RunPairs {
  std::vector<std::string> ids;        // pair keys: every unordered pair of the run's renderers some case has
  std::vector<std::string> renderers;  // the renderers of those pairs, in the run's order
};

// In the order of renderers::unorderedPairs over the run's renderers, then
// any pair no two of them name (a results.json written by hand), in the
// order of its first appearance.
RunPairs runPairs(const Cases& cases, const std::vector<std::string>& renderers) {
  std::vector<std::string> present;
  for (const results::Case* c : cases)
    for (const results::Pair& p : c->pairs) present.push_back(p.pair);
  auto has = [](const std::vector<std::string>& v, const std::string& x) {
    return std::find(v.begin(), v.end(), x) != v.end();
  };
  RunPairs out;
  std::vector<bool> paired(renderers.size(), false);
  for (const renderers::RendererPair& rp : renderers::unorderedPairs(renderers.size())) {
    const std::string key = renderers::pairKey(renderers[rp.a], renderers[rp.b]);
    if (!has(present, key) || has(out.ids, key)) continue;
    out.ids.push_back(key);
    paired[rp.a] = paired[rp.b] = true;
  }
  for (size_t i = 0; i < renderers.size(); ++i)
    if (paired[i]) out.renderers.push_back(renderers[i]);
  for (const std::string& key : present)
    if (!has(out.ids, key)) out.ids.push_back(key);
  return out;
}

// A case's geometry checks (validate/results/geometry_checks.h) as
// "verdict" with a space for the underscore, as the pairs' verdicts read.
std::string checkVerdict(const results::GeometryCheck& g) { return verdictWords(g.verdict); }

std::string checkName(const results::GeometryCheck& g) { return validation::geometryCheckName(g.against, g.renderer); }

// The geometry checks of the run, by name, in the order of their first appearance.
std::vector<std::string> checkIds(const Cases& cases) {
  std::vector<std::string> ids;
  for (const results::Case* c : cases)
    for (const results::GeometryCheck& g : c->geometry_checks)
      if (std::find(ids.begin(), ids.end(), checkName(g)) == ids.end()) ids.push_back(checkName(g));
  return ids;
}

const results::GeometryCheck* findCheck(const results::Case& c, const std::string& name) {
  for (const results::GeometryCheck& g : c.geometry_checks)
    if (checkName(g) == name) return &g;
  return nullptr;
}

// A small number in two significant digits ("3.3e-06", "0.84").
std::string twoDigits(double v) { return fmt::format("{:.2g}", v); }

// The p99.9 error of every pair of every case, as a gnuplot bar chart.
void writePlot(const Cases& cases, const std::vector<std::string>& pairs, const std::filesystem::path& dir) {
  const std::filesystem::path dat = dir / "p999.dat", gp = dir / "p999.gp";
  {
    std::ostringstream d;
    d << "# case";
    for (const auto& id : pairs) d << " " << gnuplotSafe(id);
    d << " (p99.9 error, 1/65535)\n";
    int i = 0;
    for (const results::Case* c : cases) {
      d << i++;
      for (const auto& id : pairs) {
        const results::Pair* p = c->findPair(id);
        d << " " << (p && p->metrics ? std::max(0.01, p->metrics->p999_abs_16bit) : 0.01);
      }
      d << "\n";
    }
    writeFileAtomically(dat, d.str());
  }
  std::ostringstream g;
  g << "set terminal pngcairo size 1100,460 font ',9' noenhanced\nset output 'p999.png'\n"
       "set logscale y\nset yrange [0.01:*]\nset ylabel 'p99.9 error (1/65535)'\n"
       "set style data histogram\nset style histogram cluster gap 1\n"
       "set style fill solid 0.8 border -1\nset boxwidth 0.9\nset key outside top center horizontal\n"
       "set xtics rotate by -45 scale 0\nset grid ytics\n";
  g << "set xtics (";
  int i = 0;
  for (const results::Case* c : cases) {
    g << (i ? ", " : "") << "'" << gnuplotSafe(c->scene) << "' " << i;
    ++i;
  }
  g << ")\n";
  std::string plot = "plot ";
  for (size_t k = 0; k < pairs.size(); ++k)
    plot += std::string(k ? ", '' " : "'p999.dat' ") + "using " + std::to_string(k + 2) + " title '" +
            gnuplotSafe(pairs[k]) + "'";
  plot += "\n";
  writeFileAtomically(gp, g.str() + plot);  // the script as a user would rerun it
  // gnuplot (no shell: process/run_process.h) runs a copy that writes the
  // plot into the private folder of writeFileAtomically (a name relative to
  // the output folder, its working folder); the plot is renamed into place
  // once whole.
  writeFileAtomically(dir / "p999.png", [&](const std::filesystem::path& tmp_png) {
    const std::filesystem::path rel = tmp_png.lexically_relative(dir);
    std::string script = g.str();
    script.replace(script.find("set output 'p999.png'"), std::string("set output 'p999.png'").size(),
                   "set output '" + rel.string() + "'");
    writeFileAtomically(tmp_png.parent_path() / "p999.gp", script + plot);
    const ProcessResult r =
        runProcess({"gnuplot", (rel.parent_path() / "p999.gp").string()}, dir, dir / "p999.log", 120.0);
    if (!r.ok() || !std::filesystem::exists(tmp_png))
      throw std::runtime_error("gnuplot " + gp.string() + ": " +
                               (r.started ? r.describe() : "not found (Debian package gnuplot-nox)") + "; see " +
                               (dir / "p999.log").string());
    requireDecodable(tmp_png, 1100, 460);
    return true;
  });
}

// A pixel class's entry (its key, image/pixel_classes.h) of a pair's
// per-class counts or maxima; null when the file has none for it.
template <class T>
const T* ofClass(const results::Named<T>& per_class, const std::string& key) {
  for (const auto& [k, v] : per_class)
    if (k == key) return &v;
  return nullptr;
}

// A verdict's table cell, from its class attribute on: "class="l pass">PASS".
std::string verdictCell(const std::string& v) {
  const char* cls = v == "pass" ? "pass" : v == "fail" ? "fail" : v == "error" ? "err" : "nexp";
  std::string upper;
  for (char ch : v) upper += char(std::toupper(static_cast<unsigned char>(ch)));
  return std::string("class=\"l ") + cls + "\">" + upper;
}

// A pair's summary (report.h pairSummary) as a table cell's class attribute
// on: "class="l fail">FAIL fraction 99.81% &lt; 99.9%".
std::string pairCell(const results::Pair& p) {
  if (p.verdict == results::PairVerdict::NotExpressible) return "class=\"l nexp\">not expressible";
  const std::string cell = verdictCell(pairVerdict(p));
  return cell.substr(0, cell.find('>') + 1) + htmlEscape(pairSummary(p));
}

// How bad a pair's verdict is: error, fail, pass, not expressible.
int severity(const results::Pair& p) {
  const std::string v = pairVerdict(p);
  return v == "error" ? 3 : v == "fail" ? 2 : v == "pass" ? 1 : 0;
}

double maxUnexplained(const results::Pair& p) {
  return p.metrics && p.metrics->max_unexplained_16bit ? *p.metrics->max_unexplained_16bit : 0.0;
}

// A case's worst pair: the most severe verdict, then the largest max
// unexplained error, then the first in the run's order; null when the
// case has no pair.
const results::Pair* worstPair(const results::Case& c, const std::vector<std::string>& pairs) {
  const results::Pair* worst = nullptr;
  for (const std::string& id : pairs) {
    const results::Pair* p = c.findPair(id);
    if (!p) continue;
    if (!worst || severity(*p) > severity(*worst) ||
        (severity(*p) == severity(*worst) && maxUnexplained(*p) > maxUnexplained(*worst)))
      worst = p;
  }
  return worst;
}

// A case's pairs in the summary: one cell however many renderers the run
// has (its width does not grow with the pairs: 15 pairs of 6 renderers fit
// a 1280 px window), the count of each verdict, opening onto the
// renderers x renderers matrix of the pairs' verdicts (row before column
// in the run's order; a pair the case does not have is empty).
std::string pairsCell(const results::Case& c, const RunPairs& run) {
  std::map<std::string, int> count;
  int n = 0;
  for (const std::string& id : run.ids)
    if (const results::Pair* p = c.findPair(id)) ++count[pairVerdict(*p)], ++n;
  if (n == 0) return "<td class=\"l\">no pairs</td>";
  std::ostringstream h;
  h << "<td class=\"l\"><details class=\"pairs\"><summary>" << n << (n == 1 ? " pair" : " pairs") << ":";
  const char* sep = " ";
  for (const char* v : {"error", "fail", "pass", "not expressible"})
    if (count[v]) h << sep << count[v] << " " << v, sep = ", ";
  h << "</summary><table class=\"matrix\"><tr><th></th>";
  const std::vector<std::string>& rs = run.renderers;
  for (size_t j = 1; j < rs.size(); ++j) h << "<th>" << htmlEscape(rs[j]) << "</th>";
  h << "</tr>";
  for (size_t i = 0; i + 1 < rs.size(); ++i) {
    h << "<tr><th class=\"l\">" << htmlEscape(rs[i]) << "</th>";
    for (size_t j = 1; j < rs.size(); ++j) {
      const std::string key = renderers::pairKey(rs[i], rs[j]);
      const results::Pair* p = j > i ? c.findPair(key) : nullptr;
      if (!p) {
        h << "<td></td>";
        continue;
      }
      h << "<td title=\"" << htmlEscape(key) << "\" " << pairCell(*p) << "</td>";
    }
    h << "</tr>";
  }
  h << "</table></details></td>";
  return h.str();
}

// Whether a case's render is a geometry check's: a picture of its passes
// (render/geometry_passes.h passesPreview), not a render.
bool isGeometryCheck(const results::Case& c, const std::string& renderer) {
  for (const results::GeometryCheck& g : c.geometry_checks)
    if (g.renderer == renderer) return true;
  return false;
}

std::string geometryCheckCaption() {
  return std::string("not a render: its geometry passes (") + kPassesPreviewLegend +
         "), compared with the reference's passes of our loaded triangles (the geometry check below)";
}

// A case's geometry checks: per check, each metric beside the bound it is
// held to (validate/geometry_check.h), the verdict and its reason.
std::string geometryChecksTable(const results::Case& c) {
  if (c.geometry_checks.empty()) return "";
  std::ostringstream h;
  h << "<table class=\"geometry\"><tr><th class=\"l\">geometry check</th><th>verdict</th><th>covered</th>"
       "<th>hit/object off the silhouette (bound)</th><th>on the silhouette (bound)</th>"
       "<th>max depth rel. error (bound; all pixels)</th><th>uv pixels</th><th>max uv error (bound; all pixels)</th>"
       "<th>edge pixels over (bound)</th></tr>\n";
  for (const results::GeometryCheck& g : c.geometry_checks) {
    h << "<tr><td class=\"l\">" << htmlEscape(checkName(g)) << "</td>";
    if (!g.metrics) {
      const bool nx = g.verdict == results::PairVerdict::NotExpressible;
      h << "<td class=\"" << (nx ? "nexp" : "err") << "\" colspan=\"8\">" << (nx ? "not expressible: " : "error: ")
        << htmlEscape(g.reason.value_or("")) << "</td></tr>\n";
      continue;
    }
    const results::GeometryCheckMetrics& m = *g.metrics;  // a compared check has both (results/results.h)
    const results::GeometryCheckBounds& b = *g.bounds;
    const double covered = double(m.covered);
    const long long off = m.mask_disagree - m.mask_disagree_silhouette;
    h << "<td " << verdictCell(checkVerdict(g)) << "</td><td>" << m.covered << "</td><td>" << off << " (0)</td><td>"
      << m.mask_disagree_silhouette << " (" << static_cast<long long>(std::floor(b.max_silhouette_fraction * covered))
      << ")</td><td>" << twoDigits(m.max_depth_rel) << " (" << twoDigits(b.max_depth_rel) << "; "
      << twoDigits(m.max_depth_rel_all) << ")</td><td>" << m.uv_compared << "</td><td>" << twoDigits(m.max_uv) << " ("
      << twoDigits(b.max_uv) << "; " << twoDigits(m.max_uv_all) << ")</td><td>" << m.edge_over << " ("
      << static_cast<long long>(std::floor(b.max_edge_fraction * covered)) << ")</td></tr>\n";
    if (g.reason)
      h << "<tr><td class=\"l\"></td><td class=\"l fail\" colspan=\"8\">" << htmlEscape(*g.reason)
        << "</td></tr>\n";
  }
  h << "</table>\n";
  return h.str();
}

const results::ColourStats* findColourStats(const Cases& cases, const std::string& name) {
  for (const results::Case* c : cases)
    if (c->scene == name && c->colour_stats) return &*c->colour_stats;
  return nullptr;
}

// The paper's Figure 1 claims as results.json states them (`paper_claims`,
// judged by the compare step: validate/paper_claims.h), with the colour
// statistics of the scenes they are judged on.
std::string paperClaimsSection(const results::Results& results, const Cases& cases) {
  if (!results.paper_claims) return "";  // not in this run
  const results::PaperClaims& pc = *results.paper_claims;
  std::ostringstream h;
  h << "<h2>The paper's Figure 1 claims, measured</h2>\n<p>On the reference renders of the "
       "Figure 1 scenes, over lit pixels (luma &gt; 0.02), colours as sRGB-coded CIELAB: mean "
       "chroma C*, the share of grey pixels (C* &lt; 5), and the mean hue error against the "
       "texture colour at the same pixel (where both have C* &ge; 5). See docs/paper-claims.md.</p>\n"
       "<table><tr><th class=\"l\">scene</th><th>lit pixels</th><th>mean C*</th><th>texture mean C*</th>"
       "<th>grey share</th><th>hue error (deg)</th></tr>\n";
  for (const std::string& name : pc.scenes) {
    const results::ColourStats* st = findColourStats(cases, name);
    h << "<tr><td class=\"l\">" << htmlEscape(name) << "</td>";
    if (!st) {
      h << "<td class=\"err\" colspan=\"5\">no colour statistics in results.json</td></tr>\n";
      continue;
    }
    h << "<td>" << st->lit_pixels << "</td><td>" << fixed(st->mean_chroma, 2) << "</td><td>"
      << fixed(st->mean_albedo_chroma, 2) << "</td><td>" << fixed(100 * st->grey_fraction, 1) << "%</td><td>"
      << fixed(st->hue_error_deg, 2) << "</td></tr>\n";
  }
  h << "</table>\n<table><tr><th class=\"l\">claim (paper, section 4)</th><th class=\"l\">condition</th>"
       "<th>measured</th><th>verdict</th></tr>\n";
  for (const results::PaperClaim& c : pc.claims)
    h << "<tr><td class=\"l\">" << htmlEscape(c.claim) << "</td><td class=\"l\">" << htmlEscape(c.condition)
      << "</td><td>" << htmlEscape(c.measured) << "</td><td class=\"" << (c.holds ? "pass\">holds" : "fail\">does not hold")
      << "</td></tr>\n";
  h << "</table>\n";
  return h.str();
}

// The folder of an extremes or trade-off section: the one given, else the
// one results.json names (relative to its folder), else none.
std::optional<fs::path> sectionFolder(const std::optional<std::string>& named, const std::optional<fs::path>& given,
                                      const fs::path& dir) {
  if (given) return *given;
  if (named) return dir / *named;
  return std::nullopt;
}

std::string relativeHref(const fs::path& folder, const fs::path& html_dir) {
  const fs::path rel = fs::absolute(folder).lexically_normal().lexically_relative(
      fs::absolute(html_dir).lexically_normal());
  std::string href = rel.empty() ? std::string(".") : rel.generic_string();
  while (href.size() > 1 && href.back() == '/') href.pop_back();
  return href;
}

void requireSectionFile(const fs::path& folder, const char* file, const char* what) {
  if (!fs::is_regular_file(folder / file))
    throw std::runtime_error((folder / file).string() + ": no " + what + " results there (expected the folder of `xval " +
                             what + " -o DIR`)");
}

}  // namespace

std::string pairSummary(const results::Pair& p) {
  std::string text;
  for (char ch : pairVerdict(p)) text += char(std::toupper(static_cast<unsigned char>(ch)));
  if (!p.failed.empty()) return text + " " + p.failed[0].brief;
  if (p.metrics) text += " " + fixed(p.metrics->max_unexplained_16bit, 2);
  return text;
}

nlohmann::ordered_json sectionsJson(const ReportSections& sections, const fs::path& results_dir) {
  J j = J::object();
  if (sections.extremes) {
    requireSectionFile(*sections.extremes, "extremes.json", "extremes");
    j["extremes"] = relativeHref(*sections.extremes, results_dir);
  }
  if (sections.tradeoff) {
    requireSectionFile(*sections.tradeoff, "tradeoff.json", "tradeoff");
    j["tradeoff"] = relativeHref(*sections.tradeoff, results_dir);
  }
  return j;
}

void writeReport(const std::filesystem::path& results_json, const std::filesystem::path& html,
                 const ReportSections& sections) {
  // The one reader (results/results.h): a key given twice, a field the
  // schema does not allow where it is, a stored verdict its fields
  // contradict: an error naming the file and the field before a line of
  // the report is written.
  const results::Results r = results::readResults(results_json);
  const std::filesystem::path dir = results_json.parent_path().empty() ? "." : results_json.parent_path();
  const fs::path html_dir = html.parent_path().empty() ? "." : html.parent_path();
  Cases in_order;
  for (const results::Case& c : r.cases) in_order.push_back(&c);
  Cases cases = in_order;
  // Failures (and errors) first, then by name.
  std::stable_sort(cases.begin(), cases.end(),
                   [](const results::Case* a, const results::Case* b) { return a->pass < b->pass; });
  const std::vector<std::string> run_renderers = runRenderers(r);
  const RunPairs run_pairs = runPairs(in_order, run_renderers);
  const std::vector<std::string>& pairs = run_pairs.ids;
  const std::optional<fs::path> extremes_dir = sectionFolder(r.extremes_section, sections.extremes, dir);
  const std::optional<fs::path> tradeoff_dir = sectionFolder(r.tradeoff_section, sections.tradeoff, dir);
  if (extremes_dir) requireSectionFile(*extremes_dir, "extremes.json", "extremes");
  if (tradeoff_dir) requireSectionFile(*tradeoff_dir, "tradeoff.json", "tradeoff");
  writeHeatScalePng(dir / "heat_scale.png");
  // No image pair at all (a run of the reference and a geometry check
  // only): nothing to plot.
  if (!pairs.empty()) writePlot(cases, pairs, dir);

  // A case: the verdict the compare step decided and stored (validation/
  // case_verdict.h; the schema requires it of every results.json case), as
  // the pairs' verdicts read ("not compared").
  auto caseVerdict = [](const results::Case* c) -> std::string {
    std::string v = validation::verdictName(*c->verdict);
    std::replace(v.begin(), v.end(), '_', ' ');
    return v;
  };
  int pass = 0, fail = 0, nexp = 0, err = 0, nexp_pairs = 0;
  std::map<std::string, int> checks;  // geometry checks by verdict
  const std::vector<std::string> check_ids = checkIds(cases);
  for (const results::Case* c : cases) {
    for (const results::Pair& p : c->pairs) nexp_pairs += p.verdict == results::PairVerdict::NotExpressible;
    for (const results::GeometryCheck& g : c->geometry_checks) ++checks[checkVerdict(g)];
    const std::string v = caseVerdict(c);
    (v == "error" ? err : v == "fail" ? fail : v == "pass" ? pass : nexp)++;
  }
  const std::string doc_href =
      relativeHref(toolkitToleranceFile().parent_path().parent_path() / kPixelClassDoc, html_dir);
  std::ostringstream h;
  h << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n"
    << "<title>xval report</title>\n<style>\n"
    << "body{font-family:sans-serif;margin:1.5em;color:#222}table{border-collapse:collapse;margin:.5em 0}"
    << "td,th{border:1px solid #bbb;padding:2px 6px;font-size:13px;text-align:right}"
    << "th{background:#eee}td.l,th.l{text-align:left}.pass{color:#070;font-weight:bold}"
    << ".fail{color:#b00;font-weight:bold}.err{color:#b60;font-weight:bold}.nexp{color:#558;font-weight:bold}.warn{color:#960}"
    << ".marked{position:relative;display:inline-block;line-height:0}.marked img{width:100%;border:0}"
    << ".heat,.swap,.crop{image-rendering:pixelated}.mark{position:absolute;box-sizing:border-box;"
    << "border:2px solid #f0f;pointer-events:none}.mark.worst_unexplained{border-color:#f00}"
    << ".mark.worst_explained{border-color:#08f}.crops .mark{border-width:1px;border-color:#f0f}"
    << ".crops p{font-size:12px;margin:.6em 0 .2em}.viewer{margin:.5em 0}.viewer img{border:1px solid #999}"
    << ".swapbar button{margin:0 4px 4px 0}.swapbar button.on{background:#333;color:#fff}"
    << ".case{border-top:2px solid #888;margin-top:1.5em;padding-top:.5em}"
    << ".imgs{display:flex;flex-wrap:wrap;gap:10px}.imgs figure{margin:0}"
    << ".imgs>figure>img{width:256px;image-rendering:pixelated;border:1px solid #999}"
    << "figcaption{font-size:12px;text-align:center}.reason{font-size:12px;color:#444;max-width:900px}"
    << ".imgs>figure{max-width:258px}.noimage{box-sizing:border-box;width:256px;min-height:64px;padding:4px;"
    << "border:1px solid #b60;font-size:12px;white-space:pre-wrap;overflow-wrap:anywhere}"
    << "td.deviates{max-width:22em}.pairname{font-weight:normal;color:#444;font-size:11px}"
    << "details.pairs summary{cursor:pointer;white-space:nowrap}.matrix{margin:.3em 0 0}"
    << ".matrix td,.matrix th{font-size:11px;padding:1px 3px;white-space:nowrap}"
    << "</style></head><body>\n";
  h << "<h1>xval cross-validation report</h1>\n";
  h << "<p>" << cases.size() << " scenes: <span class=\"pass\">" << pass << " pass</span>, "
    << "<span class=\"fail\">" << fail << " fail</span>, <span class=\"err\">" << err
    << " errors</span>, <span class=\"nexp\">" << nexp << " not compared</span> (" << nexp_pairs
    << " pairs not expressible by a renderer, not compared). Wall time " << fixed(r.wall_seconds, 1)
    << " s. Failures are listed first. Errors are in 1/65535 of the full scale. A pair passes when its "
       "pixels are within the tolerance on the declared fraction and no pixel that no known cause explains "
       "differs by more than the cap on unexplained error (max_unexplained_16bit).</p>\n";
  if (!check_ids.empty())
    h << "<p>Geometry checks (" << htmlEscape(renderers::joinNames(check_ids))
      << "; docs/model-files.md, \"The Blender-import check\"): <span class=\"pass\">" << checks["pass"]
      << " pass</span>, <span class=\"fail\">" << checks["fail"] << " fail</span>, <span class=\"err\">"
      << checks["error"] << " errors</span>, <span class=\"nexp\">" << checks["not expressible"]
      << " not expressible</span>. Blender imports the scene's original model files itself; its hit mask, "
         "object, depth and uv at the pixel centres are compared with the reference renderer's of our loaded "
         "triangles, within the check's own bounds (not the image tolerances). A failing check fails its case.</p>\n";
  h << "<table><tr><th class=\"l\">provenance</th><th class=\"l\"></th></tr>";
  for (const auto& [key, value] : r.provenance)
    h << "<tr><td class=\"l\">" << htmlEscape(key) << "</td><td class=\"l\">" << htmlEscape(value) << "</td></tr>";
  h << "</table>\n";
  h << "<h2>Summary</h2>\n<table id=\"summary\"><tr><th class=\"l\">scene</th><th class=\"l\">verdict</th>"
       "<th class=\"l\">who deviates</th>";
  if (!pairs.empty())
    h << "<th class=\"l\">worst pair<br>verdict: the first criterion it fails, or its max unexplained</th><th class=\"l\">pairs<br>(" << pairs.size()
      << "; open for the renderers x renderers matrix)</th>";
  for (const auto& g : check_ids) h << "<th>" << htmlEscape(g) << "<br>verdict</th>";
  h << "</tr>\n";
  for (const results::Case* c : cases) {
    const std::string id = htmlEscape(c->scene);
    h << "<tr><td class=\"l\"><a href=\"#" << id << "\">" << id << "</a></td><td "
      << verdictCell(caseVerdict(c)) << "</td><td class=\"l deviates\">" << htmlEscape(c->attribution) << "</td>";
    if (!pairs.empty()) {
      if (const results::Pair* w = worstPair(*c, pairs))
        h << "<td " << pairCell(*w) << "<br><span class=\"pairname\">" << htmlEscape(w->pair) << "</span></td>";
      else
        h << "<td></td>";  // this case has no pair
      h << pairsCell(*c, run_pairs);
    }
    for (const auto& id : check_ids) {
      const results::GeometryCheck* g = findCheck(*c, id);
      if (!g) h << "<td></td>";
      else if (g->verdict == results::PairVerdict::NotExpressible) h << "<td class=\"nexp\">not expressible</td>";
      else h << "<td " << verdictCell(checkVerdict(*g)) << "</td>";
    }
    h << "</tr>\n";
  }
  h << "</table>\n";
  if (!pairs.empty())
    h << "<figure><img src=\"p999.png\" alt=\"p99.9 error per scene and pair\">"
         "<figcaption>p99.9 error per scene and pair (log scale; gnuplot)</figcaption></figure>\n";

  h << "<h2>Cases</h2>\n<p>Heat maps (full resolution): largest channel difference per pixel, "
       "<img src=\"heat_scale.png\" alt=\"scale\" style=\"width:300px;height:12px;vertical-align:middle\">"
       " from 0 through 1 (first seventh, linear) to 4096/65535 (logarithmic); grey: not covered. Red box: "
       "the pair's worst unexplained pixel, blue box: its worst explained one; the crops below show every "
       "render and the heat map around them, magnified nearest-neighbour. The buttons above each case "
       "swap its renders and heat maps in one place. Over-tolerance pixels are classified by cause:</p>\n"
    << pixelClassLegend(doc_href);
  for (const results::Case* cp : cases) {
    const results::Case& c = *cp;
    const std::string id = htmlEscape(c.scene);
    h << "<div class=\"case\" id=\"" << id << "\"><h3>" << id << " &mdash; <span class=\""
      << verdictCell(caseVerdict(cp)).substr(std::string("class=\"l ").size()) << "</span></h3>\n";
    // The command is the compare step's (validate/validation/next_steps.h
    // reproduceCommand: with the run's renderers, renderer files and
    // tolerance file); results.json files written before it had none: no
    // command rather than one that would not run as the case ran.
    h << "<p>" << htmlEscape(c.attribution) << ".";
    if (c.reproduce) h << " Reproduce: <code>" << htmlEscape(*c.reproduce) << "</code>";
    h << "</p>\n";
    for (const auto& [renderer, why] : c.left_out)
      h << "<p class=\"nexp\">" << htmlEscape(renderer) << " left out: " << htmlEscape(why) << "</p>\n";
    // The scene's warnings (lint/scene_lint.h): beside the verdict, not in it.
    for (const results::Warning& w : c.warnings)
      h << "<p class=\"warn\">warning: " << htmlEscape(w.subject) << ": " << htmlEscape(w.message) << " ["
        << htmlEscape(w.code) << "]</p>\n";
    h << "<div class=\"imgs\">";
    for (const std::string& rid : run_renderers) {
      const results::Render* found = c.render(rid);
      if (!found) continue;
      const results::Render& rr = *found;
      const std::string renderer = htmlEscape(rid);
      if (rr.not_expressible) {
        h << "<figure><figcaption>" << renderer << ": <span class=\"nexp\">not expressible: "
          << htmlEscape(*rr.not_expressible) << "</span></figcaption></figure>";
        continue;
      }
      // A failed render shows its error where its image would be: no
      // <img> of a file that is not there.
      if (renderHasImage(rr, dir))
        h << "<figure><img src=\"" << htmlEscape(*rr.image) << "\" alt=\"" << renderer << "\">";
      else
        h << "<figure><div class=\"noimage err\">"
          << (rr.error ? "error: " + htmlEscape(*rr.error)
                       : "no image: " + htmlEscape(rr.image.value_or("(none named)")) +
                             " (named in results.json) is missing")
          << "</div>";
      h << "<figcaption>" << renderer << ", " << fixed(rr.seconds, 2) << " s";
      if (rr.render_seconds) h << " (render " << fixed(*rr.render_seconds, 2) << " s)";
      if (isGeometryCheck(c, rid)) h << "<br>" << htmlEscape(geometryCheckCaption());
      h << "</figcaption></figure>";
    }
    h << "</div>\n" << casePixels(c, dir);
    h << "<table><tr><th class=\"l\">pair</th><th>verdict</th><th>max unexpl. (cap)</th><th>max</th><th>p99.9</th>"
         "<th>RMSE</th><th>PSNR dB</th><th>within tol.</th><th>tol.</th><th>masks off (silh.)</th>";
    for (const PixelClassInfo& k : kPixelClasses) h << "<th>over tol.: " << k.name << "<br>count (max)</th>";
    h << "</tr>\n";
    for (const results::Pair& p : c.pairs) {
      h << "<tr><td class=\"l\">" << htmlEscape(p.pair) << "</td>";
      if (p.verdict == results::PairVerdict::NotExpressible) {
        h << "<td class=\"nexp\" colspan=\"" << 9 + kPixelClassCount << "\">not expressible, not compared: "
          << htmlEscape(p.not_expressible.value_or("")) << "</td></tr>\n";
        continue;
      }
      if (!p.metrics) {
        h << "<td class=\"err\" colspan=\"" << 9 + kPixelClassCount << "\">" << htmlEscape(p.error.value_or("error"))
          << "</td></tr>\n";
        continue;
      }
      const results::PairMetrics& m = *p.metrics;
      h << "<td " << verdictCell(pairVerdict(p)) << "</td><td>" << fixed(m.max_unexplained_16bit, 2) << " ("
        << fixed(m.tolerance.max_unexplained_16bit, 0) << ")</td><td>" << fixed(m.max_abs_16bit, 2) << "</td><td>"
        << fixed(m.p999_abs_16bit, 2) << "</td><td>" << fixed(m.rmse_16bit, 3) << "</td><td>"
        << (m.psnr_db ? fixed(*m.psnr_db, 1) : std::string("inf")) << "</td><td>" << fixed(100.0 * m.fraction_within, 3)
        << "%</td><td>" << significant(m.tolerance.max_abs_16bit) << " on " << significant(100.0 * m.tolerance.fraction)
        << "%</td><td>" << m.mask_disagree << " (" << m.mask_disagree_explained << ")</td>";
      for (const PixelClassInfo& k : kPixelClasses) {
        const long long* count = ofClass(m.over_tolerance, k.key);
        const std::optional<double>* max = ofClass(m.over_tolerance_max_16bit, k.key);
        h << "<td>" << (count ? std::to_string(*count) : std::string("n/a"));
        if (max && count && *count > 0) h << " (" << fixed(*max, 1) << ")";
        h << "</td>";
      }
      h << "</tr>\n";
    }
    h << "</table>\n";
    // Every metric of the table (image/metric_table.h), a column each.
    h << pairMetricsTable(c.pairs);
    h << geometryChecksTable(c);
    // Why each failing pair fails: every criterion, with its numbers.
    for (const results::Pair& p : c.pairs)
      if (!p.failed.empty())
        h << "<p class=\"reason\"><b>" << htmlEscape(p.pair) << " fails:</b> " << htmlEscape(failedText(p.failed))
          << "</p>\n";
    for (const results::Pair& p : c.pairs)
      if (p.metrics && !p.metrics->tolerance_reason.empty())
        h << "<p class=\"reason\"><b>" << htmlEscape(p.pair) << " tolerance:</b> "
          << htmlEscape(p.metrics->tolerance_reason) << "</p>\n";
    h << "</div>\n";
  }
  // After the cases: the paper's claims, the extremes and the trade-off.
  h << paperClaimsSection(r, cases);
  if (extremes_dir) h << extremes::reportSection(*extremes_dir, relativeHref(*extremes_dir, html_dir));
  if (tradeoff_dir) h << tradeoffReportSection(*tradeoff_dir, relativeHref(*tradeoff_dir, html_dir));
  h << "<script>\n" << swapScript() << "window.addEventListener('load', function () {\n"
       "  var bad = [], imgs = document.images;\n"
       "  for (var i = 0; i < imgs.length; i++)\n"
       "    if (!imgs[i].complete || imgs[i].naturalWidth === 0) bad.push(imgs[i].getAttribute('src'));\n"
       "  document.title = bad.length ? 'xval report: BROKEN ' + bad.join(' ')\n"
       "                              : 'xval report: ' + imgs.length + ' images OK';\n"
       "});\n</script>\n</body></html>\n";
  writeFileAtomically(html, h.str());
}

}  // namespace xval
