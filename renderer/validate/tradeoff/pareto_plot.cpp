// The Pareto plot and its label placement (validate/tradeoff/pareto_plot.h).
#include "validate/tradeoff/pareto_plot.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "files/atomic_write.h"
#include "image/image.h"
#include "process/run_process.h"

namespace xval {

namespace fs = std::filesystem;
using J = nlohmann::ordered_json;

namespace {

struct Box {
  double x0, x1, y0, y1;
};

// Letters, digits, '-' and '.' kept; anything else '_' (the title is
// inside a gnuplot string).
std::string titleSafe(const std::string& id) {
  std::string s;
  for (char ch : id) s += std::isalnum(static_cast<unsigned char>(ch)) || ch == '-' || ch == '.' ? ch : '_';
  return s;
}

}  // namespace

std::vector<PlacedLabel> placeLabels(const std::vector<PlotItem>& items, const PlotAxes& ax, double tolerance,
                                     const PlotArea& area) {
  const double aw = area.width * (area.right - area.left), ah = area.height * (area.top - area.bottom);
  auto px = [&](double t) { return aw * std::log(t / ax.xlo) / std::log(ax.xhi / ax.xlo); };
  auto py = [&](double e) { return ah * std::log(e / ax.ylo) / std::log(ax.yhi / ax.ylo); };
  std::vector<Box> taken;
  auto overlaps = [&](const Box& b) {
    if (b.x0 < 0 || b.x1 > aw || b.y0 < 0 || b.y1 > ah) return true;
    for (const Box& o : taken)
      if (b.x0 < o.x1 && o.x0 < b.x1 && b.y0 < o.y1 && o.y0 < b.y1) return true;
    return false;
  };
  for (const PlotItem& it : items)
    taken.push_back({px(it.seconds) - 5, px(it.seconds) + 5, py(it.error) - 5, py(it.error) + 5});
  taken.push_back({aw - 175, aw, ah - 42, ah});  // the key
  if (tolerance > 0) taken.push_back({0, 0.01 * aw + 500, py(tolerance) - 2, py(tolerance * 1.12) + 10});
  std::vector<PlacedLabel> out;
  for (const PlotItem& it : items) {
    const double cw = it.front ? 7.5 : 6.0, lh = it.front ? 14 : 12;
    const double w = cw * double(it.id.size()), x = px(it.seconds), y = py(it.error);
    const double base = it.front ? -lh : 0;
    bool placed = false, left = it.front;
    double dy = base;
    for (int k = 0; k <= 16 && !placed; ++k) {
      const double cand = base + (k % 2 ? 1 : -1) * ((k + 1) / 2) * lh;
      for (bool l : {it.front, !it.front}) {
        const Box b = l ? Box{x - 9 - w, x - 9, y + cand - lh / 2, y + cand + lh / 2}
                        : Box{x + 9, x + 9 + w, y + cand - lh / 2, y + cand + lh / 2};
        if (!overlaps(b)) {
          taken.push_back(b), placed = true, left = l, dy = cand;
          break;
        }
      }
    }
    const double lx = left ? x - 9 : x + 9, ly = y + dy;
    out.push_back({it.id, lx / aw, ly / ah, left, it.front, std::abs(dy - base) > 0.6 * lh, it.seconds, it.error});
  }
  return out;
}

void writeParetoPlot(const J& out, const std::string& metric_label, const fs::path& dir) {
  const double tolerance = out["pareto_error_tolerance"].get<double>();
  const double inf = std::numeric_limits<double>::infinity();
  double tmin = inf, tmax = 0, emin = inf, emax = 0;
  for (const auto& c : out["configs"]) {
    if (c["group"] == "converged") continue;
    const double e = c["pareto_error"].get<double>(), t = c["frame_median_s"].get<double>();
    if (e > 0) emin = std::min(emin, e);
    emax = std::max(emax, e);
    tmin = std::min(tmin, t), tmax = std::max(tmax, t);
  }
  if (!std::isfinite(emin)) emin = emax > 0 ? emax : 1.0;
  if (tolerance > 0) emin = std::min(emin, tolerance);
  emax = std::max(emax, emin);
  auto shown = [&](double e) { return std::max(e, emin * 0.5); };  // 0 has no place on a log axis
  std::ostringstream all, front;
  all << "# id frame_median_s error(" << metric_label << "), configurations off the Pareto front\n";
  front << "# id frame_median_s error, the Pareto front by time\n";
  for (const auto& c : out["configs"]) {
    if (c["group"] == "converged" || c["pareto"].get<bool>()) continue;
    all << "\"" << c["id"].get<std::string>() << "\" " << c["frame_median_s"].get<double>() << " "
        << shown(c["pareto_error"].get<double>()) << "\n";
  }
  for (const auto& id : out["pareto_front"])
    for (const auto& c : out["configs"])
      if (c["id"] == id)
        front << "\"" << id.get<std::string>() << "\" " << c["frame_median_s"].get<double>() << " "
              << shown(c["pareto_error"].get<double>()) << "\n";
  writeFileAtomically(dir / "pareto.dat", all.str() + "\n\n" + front.str());

  const PlotAxes axes{tmin / 1.6, tmax * 4.0, emin / 1.6, emax * 1.6};
  std::vector<PlotItem> items;
  for (const auto& id : out["pareto_front"])
    for (const auto& c : out["configs"])
      if (c["id"] == id) items.push_back({id, c["frame_median_s"], shown(c["pareto_error"]), true});
  std::vector<PlotItem> rest;
  for (const auto& c : out["configs"])
    if (c["group"] != "converged" && !c["pareto"].get<bool>())
      rest.push_back({c["id"], c["frame_median_s"], shown(c["pareto_error"]), false});
  std::sort(rest.begin(), rest.end(), [](const PlotItem& a, const PlotItem& b) { return a.error > b.error; });
  items.insert(items.end(), rest.begin(), rest.end());
  std::ostringstream labels;
  for (const PlacedLabel& l : placeLabels(items, axes, tolerance)) {
    labels << "set label \"" << l.id << "\" at graph " << l.x << ", graph " << l.y
           << (l.left ? " right" : " left") << " font '," << (l.front ? "9:Bold" : "8") << "' tc rgb '"
           << (l.front ? "#c02020" : "#606060") << "' front\n";
    if (l.leader)
      labels << "set arrow from graph " << l.x << ", graph " << l.y << " to first " << l.seconds << ", first "
             << l.error << " nohead lw 0.5 lc rgb '#b0b0b0'\n";
  }
  const PlotArea& a = kPlotArea;
  std::ostringstream g;
  g << "set terminal pngcairo size " << a.width << "," << a.height
    << " font ',9' noenhanced\nset output 'pareto.png'\n"
       "set lmargin at screen " << a.left << "\nset rmargin at screen " << a.right << "\nset bmargin at screen "
    << a.bottom << "\nset tmargin at screen " << a.top << "\n"
       "set logscale xy\nset grid xtics ytics mxtics mytics lc rgb '#dddddd'\n"
       "set xrange [" << axes.xlo << ":" << axes.xhi << "]\nset yrange [" << axes.ylo << ":" << axes.yhi << "]\n"
       "set xlabel 'frame time, median (s)'\n"
       "set ylabel '" << metric_label << " against the converged reference'\n"
       "set title '" << titleSafe(out["scene"].get<std::string>()) << " " << out["width"].get<int>() << "x"
    << out["height"].get<int>() << ": error against frame time (Pareto-optimal in red)'\n"
       "set key top right box opaque\n";
  if (tolerance > 0)
    g << "set arrow from graph 0, first " << tolerance << " to graph 1, first " << tolerance
      << " nohead dt 2 lc rgb '#3060c0'\n"
         "set label \"converged reference's residual (errors closer than this are not resolved)\" at graph 0.01, first "
      << tolerance * 1.12 << " tc rgb '#3060c0'\n";
  g << labels.str();
  g << "plot 'pareto.dat' index 0 using 2:3 with points pt 7 ps 1.1 lc rgb '#909090' title 'configuration', \\\n"
       "     '' index 1 using 2:3 with linespoints pt 7 ps 1.4 lw 1.5 lc rgb '#c02020' title 'Pareto-optimal'\n";
  writeFileAtomically(dir / "pareto.gp", g.str());  // the script as a user would rerun it
  // gnuplot runs a copy that writes the plot into writeFileAtomically's
  // private folder; the plot is renamed into place once whole.
  writeFileAtomically(dir / "pareto.png", [&](const fs::path& tmp_png) {
    const fs::path rel = tmp_png.lexically_relative(dir);
    std::string script = g.str();
    const std::string line = "set output 'pareto.png'";
    script.replace(script.find(line), line.size(), "set output '" + rel.string() + "'");
    writeFileAtomically(tmp_png.parent_path() / "pareto.gp", script);
    ProcessResult r = runProcess({"gnuplot", (rel.parent_path() / "pareto.gp").string()}, dir,
                                 dir / "pareto.log", 120.0);
    if (!r.ok() || !fs::exists(tmp_png))
      throw std::runtime_error("gnuplot " + (dir / "pareto.gp").string() + ": " +
                               (r.started ? r.describe() : "not found (Debian package gnuplot-nox)") + "; see " +
                               (dir / "pareto.log").string());
    requireDecodable(tmp_png, int(a.width), int(a.height));
    return true;
  });
}

}  // namespace xval
