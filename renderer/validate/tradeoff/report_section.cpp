// The report's trade-off section (validate/tradeoff/report_section.h).
#include "validate/tradeoff/report_section.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "text/number_text.h"
#include "validate/common/html_text.h"

namespace xval {

namespace {

using J = nlohmann::json;

std::string text(const J& j) { return htmlEscape(j.is_string() ? j.get<std::string>() : j.dump()); }

}  // namespace

std::string tradeoffReportSection(const std::filesystem::path& folder, const std::string& href) {
  const std::filesystem::path file = folder / "tradeoff.json";
  if (!std::filesystem::exists(file)) return "";
  std::ifstream in(file);
  if (!in) throw std::runtime_error(file.string() + ": cannot open");
  J t;
  try {
    t = J::parse(in);
  } catch (const J::exception& e) {
    throw std::runtime_error(file.string() + ": not valid JSON: " + e.what());
  }
  if (t.value("format", "") != "xval-tradeoff/1")
    throw std::runtime_error(file.string() + ": format: expected \"xval-tradeoff/1\", got " +
                             (t.contains("format") ? t["format"].dump() : std::string("nothing")));
  std::ostringstream h;
  try {
    const J& ref = t.at("reference");
    h << "<h2 id=\"tradeoff\">Speed against accuracy (reference renderer)</h2>\n<p>Scene "
      << text(t.at("scene")) << " at " << t.at("width").get<int>() << "x" << t.at("height").get<int>()
      << ", each configuration against a converged reference (double, " << ref.at("spp").get<int>()
      << " spp, " << text(ref.at("segments")) << " segments = tessellation x"
      << fixed(ref.at("tessellation_factor").get<double>(), 2) << ", " << text(ref.at("shading")) << ", "
      << text(ref.at("texture_filter")) << " filter; " << fixed(ref.at("render_s").get<double>(), 1)
      << " s). Frame time: " << text(t.at("timing").at("statistic")) << ". Error: "
      << text(t.at("error_definition")) << ". Machine: " << text(t.at("machine").at("cpu")) << ", "
      << t.at("machine").at("threads_used").get<unsigned>() << " threads, 1-minute load average "
      << fixed(t.at("machine").at("load_average_1min_start").get<double>(), 2) << " at the start and "
      << fixed(t.at("machine").at("load_average_1min_end").get<double>(), 2) << " at the end; "
      << text(t.at("date_utc")) << ". Reproduce: <code>" << text(t.at("command")) << "</code> "
      << "(docs/tradeoff.md).</p>\n";
    h << "<p>The reference against one step finer (its residual; errors below it mean nothing):</p>\n"
         "<table><tr><th class=\"l\">check</th><th>segments</th><th>spp</th><th>max</th><th>p99.9</th>"
         "<th>RMSE</th><th>CIEDE2000 mean</th></tr>\n";
    for (const auto& c : ref.at("convergence")) {
      const J& r = c.at("residual");
      h << "<tr><td class=\"l\">" << text(c.at("id")) << "</td><td>" << text(c.at("knobs").at("segments"))
        << "</td><td>" << c.at("knobs").at("spp").get<int>() << "</td><td>" << fixed(r.at("max_16bit"), 2)
        << "</td><td>" << fixed(r.at("p999_16bit"), 2) << "</td><td>" << fixed(r.at("rmse_16bit"), 3) << "</td><td>"
        << fixed(r.at("ciede2000_mean"), 4) << "</td></tr>\n";
    }
    h << "</table>\n";
    if (std::filesystem::exists(folder / "pareto.png"))
      h << "<figure><img src=\"" << htmlEscape(href) << "/pareto.png\" alt=\"Pareto plot\" style=\"width:800px\">"
           "<figcaption>Error (" << text(t.at("pareto_metric"))
        << ") against frame time, log axes; Pareto-optimal configurations in red, errors closer than the "
           "reference's residual (" << fixed(t.at("pareto_error_tolerance").get<double>(), 2)
        << ") counted as equal (gnuplot)</figcaption></figure>\n";
    else
      h << "<p class=\"err\">" << htmlEscape(href) << "/pareto.png is missing.</p>\n";
    h << "<table><tr><th class=\"l\">configuration</th><th>spp</th><th>segments</th><th>triangles</th>"
         "<th class=\"l\">precision</th><th class=\"l\">shading</th><th class=\"l\">filter</th>"
         "<th>frame ms: median (min..max, n)</th><th>setup s</th><th>max</th><th>p99.9</th><th>RMSE</th>"
         "<th>CIEDE2000 mean / max</th><th>Pareto</th></tr>\n";
    for (const auto& c : t.at("configs")) {
      const J& k = c.at("knobs");
      const J& e = c.at("error");
      const bool pareto = c.at("pareto").get<bool>();
      h << "<tr><td class=\"l\">" << (pareto ? "<b>" : "") << text(c.at("id")) << (pareto ? "</b>" : "")
        << "</td><td>" << k.at("spp").get<int>() << "</td><td>" << text(k.at("segments")) << "</td><td>"
        << k.at("triangles").get<long long>() << "</td><td class=\"l\">" << text(k.at("precision"))
        << "</td><td class=\"l\">" << text(k.at("shading")) << "</td><td class=\"l\">"
        << (k.at("texture_filter").is_null() ? std::string("-") : text(k.at("texture_filter"))) << "</td><td>"
        << fixed(c.at("frame_median_s").get<double>() * 1e3, 1) << " ("
        << fixed(c.at("frame_min_s").get<double>() * 1e3, 1) << ".." << fixed(c.at("frame_max_s").get<double>() * 1e3, 1)
        << ", " << c.at("frames").get<int>() << ")</td><td>" << fixed(c.at("setup_s"), 2) << "</td><td>"
        << fixed(e.at("max_16bit"), 1) << "</td><td>" << fixed(e.at("p999_16bit"), 1) << "</td><td>"
        << fixed(e.at("rmse_16bit"), 2) << "</td><td>" << fixed(e.at("ciede2000_mean"), 3) << " / "
        << fixed(e.at("ciede2000_max"), 2) << "</td><td class=\"" << (pareto ? "pass\">yes" : "\">")
        << "</td></tr>\n";
    }
    h << "</table>\n";
  } catch (const J::exception& e) {
    throw std::runtime_error(file.string() + ": missing or mistyped field: " + e.what());
  }
  return h.str();
}

}  // namespace xval
