#include "validate/report/report.h"
#include "validate/report/report_case.h"
#include "validate/report/report_data.h"
#include "validate/report/report_metrics.h"

#include "files/atomic_write.h"
#include "image/heat_map.h"

#include <glm/glm.hpp>
#include <map>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <vector>

#include <kainjow/mustache.hpp>

#include "image/image.h"
#include "process/run_process.h"
#include "renderers/registry.h"
#include "scene/json_reader.h"
#include "scene_file/scene_loader.h"
#include "text/number_text.h"
#include "validate/common/html_text.h"
#include "validate/extremes/report_section.h"
#include "validate/report/report_page_template.h"
#include "validate/report/report_pixels.h"
#include "validate/results/results.h"
#include "validate/tolerances.h"
#include "validate/tradeoff/report_section.h"

namespace xval {

namespace fs = std::filesystem;
using J = nlohmann::ordered_json;
namespace mu = kainjow::mustache;
using namespace page;


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

// A pair's summary (report.h pairSummary) in a cell: pair, pair_class,
// pair_text ("FAIL fraction 99.81% < 99.9%", escaped by the template).
mu::data pairCell(const results::Pair& p) {
  const bool nexp = p.verdict == results::PairVerdict::NotExpressible;
  mu::data d;
  d.set("pair", p.pair);
  d.set("pair_class", nexp ? std::string("nexp") : verdictClass(pairVerdict(p)));
  d.set("pair_text", nexp ? std::string("not expressible") : pairSummary(p));
  return d;
}

// How bad a pair's verdict is: error, fail, finding, pass, not expressible.
int severity(const results::Pair& p) {
  switch (p.verdict) {
    case results::PairVerdict::Error: return 4;
    case results::PairVerdict::Fail: return 3;
    case results::PairVerdict::Finding: return 2;
    case results::PairVerdict::Pass: return 1;
    case results::PairVerdict::NotExpressible: return 0;
  }
  return 4;
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
// None when the case has no pair ("no pairs"); else one: counts ("3 pairs:
// 1 fail, 2 pass"), columns, rows (renderer, cells: a cell is a pairCell
// or none).
mu::data pairsMatrix(const results::Case& c, const RunPairs& run) {
  std::map<std::string, int> count;
  int n = 0;
  for (const std::string& id : run.ids)
    if (const results::Pair* p = c.findPair(id)) ++count[pairVerdict(*p)], ++n;
  mu::data out = list();
  if (n == 0) return out;
  std::string counts = std::to_string(n) + (n == 1 ? " pair" : " pairs") + ":";
  const char* sep = " ";
  for (const char* v : {"error", "fail", "pass", "not expressible"})
    if (count[v]) counts += sep + std::to_string(count[v]) + " " + v, sep = ", ";
  const std::vector<std::string>& rs = run.renderers;
  mu::data rows = list();
  for (size_t i = 0; i + 1 < rs.size(); ++i) {
    mu::data cells = list();
    for (size_t j = 1; j < rs.size(); ++j) {
      const std::string key = renderers::pairKey(rs[i], rs[j]);
      mu::data cell = list();
      if (const results::Pair* p = j > i ? c.findPair(key) : nullptr) {
        mu::data d = pairCell(*p);
        d.set("pair", key);
        cell << d;
      }
      mu::data e;
      e.set("cell", cell);
      cells << e;
    }
    mu::data row;
    row.set("renderer", rs[i]);
    row.set("cells", cells);
    rows << row;
  }
  mu::data m;
  m.set("counts", counts);
  m.set("columns", strings(std::vector<std::string>(rs.begin() + (rs.empty() ? 0 : 1), rs.end())));
  m.set("rows", rows);
  out << m;
  return out;
}

const results::ColourStats* findColourStats(const Cases& cases, const std::string& name) {
  for (const results::Case* c : cases)
    if (c->scene == name && c->colour_stats) return &*c->colour_stats;
  return nullptr;
}

// The paper's Figure 1 claims as results.json states them (`paper_claims`,
// judged by the compare step: validate/paper_claims.h), with the colour
// statistics of the scenes they are judged on. None when the run has none;
// else one: claim_scenes (scene, stats: none or one of lit, chroma,
// albedo_chroma, grey, hue), claims (claim, condition, measured, holds).
mu::data paperClaimsSection(const results::Results& results, const Cases& cases) {
  mu::data section = list();
  if (!results.paper_claims) return section;  // not in this run
  const results::PaperClaims& pc = *results.paper_claims;
  mu::data scenes = list();
  for (const std::string& name : pc.scenes) {
    mu::data row;
    row.set("scene", name);
    mu::data stats = list();
    if (const results::ColourStats* st = findColourStats(cases, name)) {
      mu::data d;
      d.set("lit", std::to_string(st->lit_pixels));
      d.set("chroma", fixed(st->mean_chroma, 2));
      d.set("albedo_chroma", fixed(st->mean_albedo_chroma, 2));
      d.set("grey", fixed(100 * st->grey_fraction, 1));
      d.set("hue", fixed(st->hue_error_deg, 2));
      stats << d;
    }
    row.set("stats", stats);
    scenes << row;
  }
  mu::data claims = list();
  for (const results::PaperClaim& c : pc.claims) {
    mu::data row;
    row.set("claim", c.claim);
    row.set("condition", c.condition);
    row.set("measured", c.measured);
    row.set("holds", mu::data(c.holds));
    claims << row;
  }
  mu::data d;
  d.set("claim_scenes", scenes);
  d.set("claims", claims);
  section << d;
  return section;
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

// A case's row of the summary: scene, verdict_class, verdict_text,
// attribution, pair_columns (none when the run has no image pair; else
// worst: its worst pair's cell or none, matrix: pairsMatrix), check_cells
// (per geometry check of the run: check_class none or one, check_text).
mu::data summaryRow(const results::Case& c, const RunPairs& run, const std::vector<std::string>& check_ids) {
  const std::string verdict = caseVerdict(c);
  mu::data row;
  row.set("scene", c.scene);
  row.set("verdict_class", verdictClass(verdict));
  row.set("verdict_text", upperCase(verdict));
  row.set("attribution", c.attribution);
  mu::data pair_columns = list();
  if (!run.ids.empty()) {
    mu::data worst = list();
    if (const results::Pair* w = worstPair(c, run.ids)) worst << pairCell(*w);
    mu::data columns;
    columns.set("worst", worst);
    columns.set("matrix", pairsMatrix(c, run));
    pair_columns << columns;
  }
  row.set("pair_columns", pair_columns);
  mu::data check_cells = list();
  for (const std::string& id : check_ids) {
    const results::GeometryCheck* g = findCheck(c, id);
    std::optional<std::string> cls;
    std::string text;
    if (g && g->verdict == results::PairVerdict::NotExpressible) {
      cls = "nexp";
      text = "not expressible";
    } else if (g) {
      cls = "l " + verdictClass(checkVerdict(*g));
      text = upperCase(checkVerdict(*g));
    }
    mu::data cell;
    cell.set("check_class", maybe(cls));
    cell.set("check_text", text);
    check_cells << cell;
  }
  row.set("check_cells", check_cells);
  return row;
}

// The page's head: scene_count and the cases by verdict (pass, fail,
// errors, not_compared), not_expressible_pairs, wall_seconds,
// geometry_checks (none when the run has none; else one: names and the
// checks by verdict), provenance (key, value).
mu::data pageHead(const results::Results& r, const Cases& cases, const std::vector<std::string>& check_ids) {
  mu::data page;
  int pass = 0, fail = 0, nexp = 0, err = 0, nexp_pairs = 0;
  std::map<std::string, int> checks;  // geometry checks by verdict
  for (const results::Case* c : cases) {
    for (const results::Pair& p : c->pairs) nexp_pairs += p.verdict == results::PairVerdict::NotExpressible;
    for (const results::GeometryCheck& g : c->geometry_checks) ++checks[checkVerdict(g)];
    const std::string v = caseVerdict(*c);
    (v == "error" ? err : v == "fail" ? fail : v == "pass" ? pass : nexp)++;
  }
  page.set("scene_count", std::to_string(cases.size()));
  page.set("pass", std::to_string(pass));
  page.set("fail", std::to_string(fail));
  page.set("errors", std::to_string(err));
  page.set("not_compared", std::to_string(nexp));
  page.set("not_expressible_pairs", std::to_string(nexp_pairs));
  page.set("wall_seconds", fixed(r.wall_seconds, 1));
  mu::data geometry = list();
  if (!check_ids.empty()) {
    mu::data g;
    g.set("names", renderers::joinNames(check_ids));
    g.set("pass", std::to_string(checks["pass"]));
    g.set("fail", std::to_string(checks["fail"]));
    g.set("errors", std::to_string(checks["error"]));
    g.set("not_expressible", std::to_string(checks["not expressible"]));
    geometry << g;
  }
  page.set("geometry_checks", geometry);
  page.set("provenance", members(r.provenance, "key", "value"));
  return page;
}

// The page: the template compiled in (report_page_template.h), its
// {{key}}s escaped by htmlEscape (the one escaping of the report's
// fragments too). Throws std::runtime_error when the template does not
// parse or render.
std::string renderPage(mu::data& page) {
  mu::mustache tmpl{std::string(kReportPageTemplate)};
  if (!tmpl.is_valid()) throw std::runtime_error("report template (report_page.mustache): " + tmpl.error_message());
  tmpl.set_custom_escape(htmlEscape);
  std::string out = tmpl.render(page);
  if (!tmpl.error_message().empty())
    throw std::runtime_error("report template (report_page.mustache): " + tmpl.error_message());
  return out;
}

}  // namespace

std::string pairSummary(const results::Pair& p) {
  std::string text = upperCase(pairVerdict(p));
  if (p.verdict == results::PairVerdict::Finding && p.metrics)
    return text + " of " + p.finding->renderer + ", p99.9 " + fixed(p.metrics->p999_abs_16bit, 2);
  if (p.finding && p.failed.empty() && p.verdict == results::PairVerdict::Fail)
    return text + " the finding of " + p.finding->renderer + " no longer holds";
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

  const std::vector<std::string> check_ids = checkIds(cases);
  mu::data page = pageHead(r, cases, check_ids);
  mu::data image_pairs = list();
  if (!pairs.empty()) image_pairs << mu::data("count", std::to_string(pairs.size()));
  page.set("image_pairs", image_pairs);
  page.set("check_names", strings(check_ids));
  mu::data summary = list(), case_list = list();
  for (const results::Case* c : cases) {
    summary << summaryRow(*c, run_pairs, check_ids);
    case_list << caseSection(*c, run_renderers, dir);
  }
  page.set("summary", summary);
  const std::string doc_href =
      relativeHref(toolkitToleranceFile().parent_path().parent_path() / kPixelClassDoc, html_dir);
  page.set("pixel_class_legend", pixelClassLegend(doc_href));
  std::vector<std::string> class_names;
  for (const PixelClassInfo& k : kPixelClasses) class_names.push_back(k.name);
  page.set("pixel_classes", strings(class_names));
  page.set("metric_columns", metricColumns());
  page.set("cases", case_list);
  // After the cases: the paper's claims, the extremes and the trade-off.
  page.set("paper_claims", paperClaimsSection(r, cases));
  page.set("extremes", extremes_dir ? extremes::reportSection(*extremes_dir, relativeHref(*extremes_dir, html_dir))
                                    : std::string());
  page.set("tradeoff", tradeoff_dir ? tradeoffReportSection(*tradeoff_dir, relativeHref(*tradeoff_dir, html_dir))
                                    : std::string());
  page.set("swap_script", swapScript());
  writeFileAtomically(html, renderPage(page));
}

}  // namespace xval
