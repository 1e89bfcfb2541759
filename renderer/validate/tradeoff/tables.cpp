// The trade-off's Markdown and TSV tables (validate/tradeoff/tables.h).
#include "validate/tradeoff/tables.h"

#include <sstream>

#include "text/number_text.h"

namespace xval {

using J = nlohmann::ordered_json;

std::string markdownTable(const J& out) {
  std::ostringstream m;
  m << "| configuration | spp | segments | precision | shading | filter | frame ms: median (min..max, n) "
       "| max | p99.9 | RMSE | CIEDE2000 mean | Pareto |\n"
       "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& c : out["configs"]) {
    const J& k = c["knobs"];
    const J& e = c["error"];
    m << "| " << c["id"].get<std::string>() << " | " << k["spp"].get<int>() << " | "
      << k["segments"].get<std::string>() << " | " << k["precision"].get<std::string>() << " | "
      << k["shading"].get<std::string>() << " | "
      << (k["texture_filter"].is_null() ? std::string("-") : k["texture_filter"].get<std::string>()) << " | "
      << fixed(c["frame_median_s"].get<double>() * 1e3, 1) << " (" << fixed(c["frame_min_s"].get<double>() * 1e3, 1)
      << ".." << fixed(c["frame_max_s"].get<double>() * 1e3, 1) << ", " << c["frames"].get<int>() << ") | "
      << fixed(e["max_16bit"], 1) << " | " << fixed(e["p999_16bit"], 1) << " | " << fixed(e["rmse_16bit"], 2)
      << " | " << fixed(e["ciede2000_mean"], 3) << " | " << (c["pareto"].get<bool>() ? "**yes**" : "") << " |\n";
  }
  return m.str();
}

std::string tsvTable(const J& out) {
  std::ostringstream t;
  t << "id\tgroup\tspp\ttessellation_factor\tsegments\ttriangles\tprecision\tshading\ttexture_filter\t"
       "setup_s\tframe_median_s\tframe_min_s\tframe_max_s\tframes\tmax_16bit\tp999_16bit\trmse_16bit\t"
       "ciede2000_mean\tciede2000_max\tpareto\n";
  for (const auto& c : out["configs"]) {
    const J& k = c["knobs"];
    const J& e = c["error"];
    t << c["id"].get<std::string>() << "\t" << c["group"].get<std::string>() << "\t" << k["spp"] << "\t"
      << k["tessellation_factor"] << "\t" << k["segments"].get<std::string>() << "\t" << k["triangles"] << "\t"
      << k["precision"].get<std::string>() << "\t" << k["shading"].get<std::string>() << "\t"
      << (k["texture_filter"].is_null() ? std::string("-") : k["texture_filter"].get<std::string>()) << "\t"
      << c["setup_s"] << "\t" << c["frame_median_s"] << "\t" << c["frame_min_s"] << "\t" << c["frame_max_s"]
      << "\t" << c["frames"] << "\t" << e["max_16bit"] << "\t" << e["p999_16bit"] << "\t" << e["rmse_16bit"]
      << "\t" << e["ciede2000_mean"] << "\t" << e["ciede2000_max"] << "\t" << (c["pareto"].get<bool>() ? 1 : 0)
      << "\n";
  }
  return t.str();
}

}  // namespace xval
