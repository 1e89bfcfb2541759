// xval tradeoff SCENE.json -o DIR/ [--frames N] [--max-seconds S] [--threads T]
//                [--quick] [--reference-spp N] [--reference-tessellation F]
//                [--width W] [--height H] [--metric M] [--images]
//
// Speed against accuracy of the reference renderer's knobs, on one scene,
// in one process, side by side. validate/tradeoff.h defines the sweep, the
// converged reference and the error.
//
// Parameters (defaults):
//   --frames N                 timed frames per configuration after one
//                              warm-up frame (5); the figure is their median
//                              wall time, with min..max
//   --max-seconds S            stop timing a configuration once its timed
//                              frames add up to S seconds (3); at least one
//                              timed frame; the row says how many were timed
//   --threads T                render threads (0 = every hardware thread)
//   --quick                    leave out spp=64, tess=2 and corner:accurate,
//                              and the reference defaults to 16 spp and
//                              tessellation x2 (not converged: for trying)
//   --reference-spp N          samples of the converged reference (64; a
//                              perfect square)
//   --reference-tessellation F segments factor of the reference (4)
//   --width W, --height H      override the camera's resolution (the field
//                              of view is kept)
//   --metric M                 the error on the Pareto plot and front: rmse
//                              (default), p999, max or ciede2000 (mean)
//   --images                   also write every configuration's image as
//                              DIR/images/<id>.exr
//
// Each configuration is prepared once (PreparedScene: tessellation,
// texture, BVH; "setup", reported apart), rendered once to warm up, then
// timed frame by frame without diagnostics; its error is that of its last
// frame against the converged reference. A configuration whose warm-up
// frame alone takes --max-seconds is not rendered again: that frame is its
// one timed frame (n = 1, "warmup_frame_timed"). The converged
// configuration is itself a row: the reference frame is its warm-up, and
// it is always rendered at least once more; its error, that of the later
// frame, is 0 when rendering is deterministic (a check).
//
// Writes DIR/tradeoff.json, DIR/tradeoff.tsv, DIR/tradeoff.md, DIR/pareto.png
// (gnuplot; pareto.gp, pareto.dat and pareto.log beside it). Progress on
// stderr. Exit 0, or 1 on an error (bad scene, gnuplot missing, ...).
#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <limits>
#include <memory>
#include <sstream>
#include <thread>
#include <variant>

#include <nlohmann/json.hpp>

#include "cli/cli_common.h"
#include "cli/commands.h"
#include "process/run_process.h"
#include "files/atomic_write.h"
#include "files/output_folder.h"
#include "image/image.h"
#include "render/renderer.h"
#include "scene/scene_loader.h"
#include "validate/tradeoff/sweep.h"

namespace xval::cli {

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;
using J = nlohmann::ordered_json;

double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }


std::string cpuModel() {
  std::ifstream f("/proc/cpuinfo");
  std::string line;
  while (std::getline(f, line))
    if (line.rfind("model name", 0) == 0) {
      auto c = line.find(':');
      if (c != std::string::npos) return line.substr(line.find_first_not_of(" \t", c + 1));
    }
  return "unknown";
}

double loadAverage1() {
  std::ifstream f("/proc/loadavg");
  double l = -1;
  f >> l;
  return l;
}

std::string utcNow() {
  std::time_t t = std::time(nullptr);
  char b[32];
  std::strftime(b, sizeof b, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&t));
  return b;
}

// First line of a command's output, or "unavailable (...)".
std::string firstLine(const std::vector<std::string>& argv, const fs::path& log) {
  ProcessResult r = runProcess(argv, fs::current_path(), log, 30.0);
  std::string line;
  if (r.ok()) {
    std::ifstream in(log);
    std::getline(in, line);
  } else {
    line = "unavailable (" + r.describe() + ")";
  }
  fs::remove(log);
  return line;
}

std::string fmt(double v, int prec) {
  char b[64];
  std::snprintf(b, sizeof b, "%.*f", prec, v);
  return b;
}

// "768x40" for the first tessellated shape, "-" for planes only.
std::string segmentsOf(const Scene& s) {
  for (const Shape& shape : s.objects) {
    if (auto* k = std::get_if<TorusKnot>(&shape))
      return std::to_string(k->segments_along) + "x" + std::to_string(k->segments_around);
    if (auto* u = std::get_if<UvSphere>(&shape))
      return std::to_string(u->segments_longitude) + "x" + std::to_string(u->segments_latitude);
  }
  return "-";
}

J errorJson(const TradeoffError& e) {
  return {{"pixels", e.pixels},           {"max_16bit", e.max_16bit},
          {"p999_16bit", e.p999_16bit},   {"rmse_16bit", e.rmse_16bit},
          {"ciede2000_mean", e.ciede2000_mean}, {"ciede2000_max", e.ciede2000_max}};
}

TradeoffError errorFromJson(const J& j) {
  TradeoffError e;
  e.pixels = j.value("pixels", 0LL);
  e.max_16bit = j.at("max_16bit").get<double>();
  e.p999_16bit = j.at("p999_16bit").get<double>();
  e.rmse_16bit = j.at("rmse_16bit").get<double>();
  e.ciede2000_mean = j.at("ciede2000_mean").get<double>();
  e.ciede2000_max = j.at("ciede2000_max").get<double>();
  return e;
}

J knobsJson(const TradeoffConfig& c, const Scene& applied, size_t triangles) {
  return {{"spp", c.spp},
          {"tessellation_factor", c.tessellation_factor},
          {"segments", segmentsOf(applied)},
          {"triangles", triangles},
          {"precision", toString(c.precision)},
          {"shading", toString(c.shading)},
          {"texture_filter", c.texture_filter ? J(toString(*c.texture_filter)) : J(nullptr)}};
}

std::string fileSafe(const std::string& id) {
  std::string s;
  for (char ch : id) s += std::isalnum(static_cast<unsigned char>(ch)) || ch == '-' || ch == '.' ? ch : '_';
  return s;
}

void writeText(const fs::path& file, const std::string& text) { writeFileAtomically(file, text); }

// The Pareto plot: every configuration (grey, labelled small), the front
// (red, joined by time, labelled), the reference's convergence residual as
// a dashed line; log axes with ranges fitted to the points.
void writePlot(const J& out, const std::string& metric_label, const fs::path& dir) {
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
  writeText(dir / "pareto.dat", all.str() + "\n\n" + front.str());
  // Labels are placed here, not by gnuplot (which lets them overlap): the
  // plot area is fixed in screen fractions, so a point's pixel position is
  // known; each label takes the first free slot near its point (the
  // front's first, to the left and below, the others to the right), and a
  // label moved away from its point gets a thin line to it.
  const double xlo = tmin / 1.6, xhi = tmax * 4.0, ylo = emin / 1.6, yhi = emax * 1.6;
  constexpr double kW = 1000, kH = 700, kL = 0.09, kR = 0.97, kB = 0.09, kT = 0.93;
  const double aw = kW * (kR - kL), ah = kH * (kT - kB);  // plot area, pixels
  auto px = [&](double t) { return aw * std::log(t / xlo) / std::log(xhi / xlo); };
  auto py = [&](double e) { return ah * std::log(e / ylo) / std::log(yhi / ylo); };
  struct Box { double x0, x1, y0, y1; };
  std::vector<Box> taken;
  auto overlaps = [&](const Box& b) {
    if (b.x0 < 0 || b.x1 > aw || b.y0 < 0 || b.y1 > ah) return true;
    for (const Box& o : taken)
      if (b.x0 < o.x1 && o.x0 < b.x1 && b.y0 < o.y1 && o.y0 < b.y1) return true;
    return false;
  };
  struct Item { std::string id; double t, e; bool front; };
  std::vector<Item> items;
  for (const auto& id : out["pareto_front"])
    for (const auto& c : out["configs"])
      if (c["id"] == id) items.push_back({id, c["frame_median_s"], shown(c["pareto_error"]), true});
  std::vector<Item> rest;
  for (const auto& c : out["configs"])
    if (c["group"] != "converged" && !c["pareto"].get<bool>())
      rest.push_back({c["id"], c["frame_median_s"], shown(c["pareto_error"]), false});
  std::sort(rest.begin(), rest.end(), [](const Item& a, const Item& b) { return a.e > b.e; });
  items.insert(items.end(), rest.begin(), rest.end());
  for (const Item& it : items) taken.push_back({px(it.t) - 5, px(it.t) + 5, py(it.e) - 5, py(it.e) + 5});
  taken.push_back({aw - 175, aw, ah - 42, ah});  // the key
  if (tolerance > 0) taken.push_back({0, 0.01 * aw + 500, py(tolerance) - 2, py(tolerance * 1.12) + 10});
  std::ostringstream labels;
  for (const Item& it : items) {
    const double cw = it.front ? 7.5 : 6.0, lh = it.front ? 14 : 12;
    const double w = cw * double(it.id.size()), x = px(it.t), y = py(it.e);
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
    labels << "set label \"" << it.id << "\" at graph " << lx / aw << ", graph " << ly / ah
           << (left ? " right" : " left") << " font '," << (it.front ? "9:Bold" : "8") << "' tc rgb '"
           << (it.front ? "#c02020" : "#606060") << "' front\n";
    if (std::abs(dy - base) > 0.6 * lh)
      labels << "set arrow from graph " << lx / aw << ", graph " << ly / ah << " to first " << it.t
             << ", first " << it.e << " nohead lw 0.5 lc rgb '#b0b0b0'\n";
  }
  std::ostringstream g;
  g << "set terminal pngcairo size " << kW << "," << kH << " font ',9' noenhanced\nset output 'pareto.png'\n"
       "set lmargin at screen " << kL << "\nset rmargin at screen " << kR << "\nset bmargin at screen " << kB
    << "\nset tmargin at screen " << kT << "\n"
       "set logscale xy\nset grid xtics ytics mxtics mytics lc rgb '#dddddd'\n"
       "set xrange [" << xlo << ":" << xhi << "]\nset yrange [" << ylo << ":" << yhi << "]\n"
       "set xlabel 'frame time, median (s)'\n"
       "set ylabel '" << metric_label << " against the converged reference'\n"
       "set title '" << fileSafe(out["scene"].get<std::string>()) << " " << out["width"].get<int>() << "x"
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
  writeText(dir / "pareto.gp", g.str());  // the script as a user would rerun it
  // gnuplot runs a copy that writes the plot into writeFileAtomically's
  // private folder; the plot is renamed into place once whole.
  writeFileAtomically(dir / "pareto.png", [&](const fs::path& tmp_png) {
    const fs::path rel = tmp_png.lexically_relative(dir);
    std::string script = g.str();
    const std::string line = "set output 'pareto.png'";
    script.replace(script.find(line), line.size(), "set output '" + rel.string() + "'");
    writeText(tmp_png.parent_path() / "pareto.gp", script);
    ProcessResult r = runProcess({"gnuplot", (rel.parent_path() / "pareto.gp").string()}, dir,
                                 dir / "pareto.log", 120.0);
    if (!r.ok() || !fs::exists(tmp_png))
      throw std::runtime_error("gnuplot " + (dir / "pareto.gp").string() + ": " +
                               (r.started ? r.describe() : "not found (Debian package gnuplot-nox)") + "; see " +
                               (dir / "pareto.log").string());
    requireDecodable(tmp_png, int(kW), int(kH));
    return true;
  });
}

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
      << fmt(c["frame_median_s"].get<double>() * 1e3, 1) << " (" << fmt(c["frame_min_s"].get<double>() * 1e3, 1)
      << ".." << fmt(c["frame_max_s"].get<double>() * 1e3, 1) << ", " << c["frames"].get<int>() << ") | "
      << fmt(e["max_16bit"], 1) << " | " << fmt(e["p999_16bit"], 1) << " | " << fmt(e["rmse_16bit"], 2)
      << " | " << fmt(e["ciede2000_mean"], 3) << " | " << (c["pareto"].get<bool>() ? "**yes**" : "") << " |\n";
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

}  // namespace

void addTradeoffCommand(CLI::App& app, std::function<int()>& run) {
  struct Args {
    std::string scene, out, metric = "rmse";
    int frames = 5, threads = 0, reference_spp = 0, width = 0, height = 0;
    double max_seconds = 3.0, reference_tessellation = 0.0;
    bool quick = false, images = false;
    std::vector<std::string> argv;
    BudgetOptions budget;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "tradeoff",
      "Speed against accuracy of the reference renderer's knobs (samples per pixel, tessellation, "
      "float/double, flat/Gouraud/Phong, nearest/bilinear) on one scene: each configuration is "
      "prepared once, rendered once to warm up and timed over several frames (median, min..max; "
      "setup apart, diagnostics off), and its error measured against a converged reference "
      "(double, 64 spp, tessellation x4, Phong, bilinear; its own residual against one step "
      "finer each way is reported). Writes DIR/tradeoff.json, tradeoff.tsv, tradeoff.md and a "
      "Pareto plot pareto.png (gnuplot). The sweep: docs/tradeoff.md.");
  cmd->add_option("scene", args->scene, "Scene file (JSON)")->required()->check(CLI::ExistingFile);
  cmd->add_option("-o,--output", args->out, "Output folder (created)")->required();
  cmd->add_option("--frames", args->frames,
                  "Timed frames per configuration after one warm-up frame (default 5)")
      ->check(CLI::Range(1, 1000));
  cmd->add_option("--max-seconds", args->max_seconds,
                  "Stop timing a configuration once its timed frames add up to this many seconds "
                  "(default 3; at least one timed frame; a warm-up frame this long is itself the "
                  "one timed frame)")
      ->check(Seconds);
  cmd->add_option("--threads", args->threads, "Render threads (default: all hardware threads)")
      ->check(CLI::Range(1, 1024));
  cmd->add_flag("--quick", args->quick,
                "Leave out spp=64, tess=2 and corner:accurate; the reference defaults to 16 spp and "
                "tessellation x2 (not converged: for trying things out)");
  cmd->add_option("--reference-spp", args->reference_spp,
                  "Samples per pixel of the converged reference, a perfect square (default 64; "
                  "16 with --quick)")
      ->check(CLI::Range(1, 256));
  cmd->add_option("--reference-tessellation", args->reference_tessellation,
                  "Tessellation factor of the converged reference, times the scene's segments each "
                  "way (default 4; 2 with --quick)")
      ->check(FinitePositive);
  cmd->add_option("--width", args->width, "Override the camera's width in pixels (field of view kept)")
      ->check(CLI::Range(1, kMaxImageSide));
  cmd->add_option("--height", args->height, "Override the camera's height in pixels")
      ->check(CLI::Range(1, kMaxImageSide));
  cmd->add_option("--metric", args->metric,
                  "Error on the Pareto plot and front: rmse (default), p999, max, or ciede2000 (mean)")
      ->check(CLI::IsMember({"rmse", "p999", "max", "ciede2000"}));
  cmd->add_flag("--images", args->images, "Also write every configuration's image as DIR/images/ID.exr");
  addBudgetOptions(cmd, args->budget);
  cmd->callback([args, &run]() {
    run = [args]() -> int {
      Scene scene = loadScene(args->scene, args->budget.get());
      if (args->width) scene.camera.width = args->width;
      if (args->height) scene.camera.height = args->height;
      SweepSettings settings;
      settings.quick = args->quick;
      settings.reference_spp = args->reference_spp ? args->reference_spp : (args->quick ? 16 : 64);
      settings.reference_tessellation =
          args->reference_tessellation > 0 ? args->reference_tessellation : (args->quick ? 2.0 : 4.0);
      requirePerfectSquareSpp(settings.reference_spp, "--reference-spp");
      const std::vector<TradeoffConfig> configs = sweepConfigs(scene, settings);
      const std::vector<TradeoffConfig> checks = convergenceChecks(scene, settings);
      const TradeoffConfig ref_cfg = configs.back();  // "converged"
      // Every configuration is checked by the loader before anything runs.
      std::vector<Scene> applied;
      for (const auto& c : configs) applied.push_back(applyConfig(scene, c, args->budget.get()));
      std::vector<Scene> applied_checks;
      for (const auto& c : checks) applied_checks.push_back(applyConfig(scene, c, args->budget.get()));

      const fs::path dir(args->out);
      std::error_code ec;
      fs::create_directories(dir, ec);
      if (ec || !fs::is_directory(dir))
        throw std::runtime_error(dir.string() + ": cannot create the output folder" +
                                 (ec ? ": " + ec.message() : std::string()));
      const FolderLock folder_lock(dir, FolderLock::Mode::Exclusive, "xval tradeoff");
      if (args->images) makeRealFolder(dir, dir / "images");

      RenderOptions opt;
      opt.threads = args->threads;
      opt.diagnostics = false;
      const int W = scene.camera.width, H = scene.camera.height;
      const auto t_all = Clock::now();
      const double load_start = loadAverage1();
      std::fprintf(stderr,
                   "xval tradeoff %s (%dx%d): %zu configurations, reference %d spp x%g tessellation "
                   "double phong, %zu convergence checks; up to %d frames or %.1f s per configuration\n",
                   scene.name.c_str(), W, H, configs.size(), ref_cfg.spp, ref_cfg.tessellation_factor,
                   checks.size(), args->frames, args->max_seconds);

      auto renderOnce = [&](const PreparedScene& p, int spp, Image& img, bool progress) {
        RenderOptions o = opt;
        o.spp = spp;
        o.precision = p.precision();
        o.progress = progress;
        const auto t0 = Clock::now();
        p.render(o, img);
        return since(t0);
      };
      auto saveImage = [&](const std::string& id, const Image& img) {
        if (args->images) writeImage(img, dir / "images" / (fileSafe(id) + ".exr"));
      };

      // 1. The converged reference, and the converged row timed on it.
      Image reference(W, H, false);
      J ref_json;
      J converged_row;
      {
        std::fprintf(stderr, "[reference] preparing %s ...\n", ref_cfg.id.c_str());
        PreparedScene p(applied.back(), Precision::Double);
        std::fprintf(stderr, "[reference] %zu triangles, setup %.2f s; rendering %d spp ...\n",
                     p.triangleCount(), p.setupSeconds(), ref_cfg.spp);
        const double t_ref = renderOnce(p, ref_cfg.spp, reference, true);
        std::fprintf(stderr, "[reference] %.2f s\n", t_ref);
        saveImage("reference", reference);
        ref_json = knobsJson(ref_cfg, applied.back(), p.triangleCount());
        ref_json["setup_s"] = p.setupSeconds();
        ref_json["render_s"] = t_ref;
        // Its row: the reference frame was the warm-up.
        Image img(W, H, false);
        std::vector<double> t;
        double sum = 0;
        while (int(t.size()) < args->frames && (t.empty() || sum < args->max_seconds)) {
          t.push_back(renderOnce(p, ref_cfg.spp, img, false));
          sum += t.back();
        }
        const Spread s = spread(t);
        converged_row = {{"id", ref_cfg.id}, {"group", ref_cfg.group},
                         {"knobs", knobsJson(ref_cfg, applied.back(), p.triangleCount())},
                         {"setup_s", p.setupSeconds()}, {"frame_median_s", s.median},
                         {"frame_min_s", s.min}, {"frame_max_s", s.max}, {"frames", s.n},
                         {"warmup_frame_timed", false},
                         {"error", errorJson(tradeoffError(img, reference))}};
        std::fprintf(stderr, "[converged] frame %.1f ms (n=%zu), error against the reference: RMSE %.3g\n",
                     s.median * 1e3, s.n, converged_row["error"]["rmse_16bit"].get<double>());
      }
      // 2. The reference against one step finer each way.
      J conv = J::array();
      for (size_t i = 0; i < checks.size(); ++i) {
        std::fprintf(stderr, "[check %zu/%zu] %s: preparing ...\n", i + 1, checks.size(), checks[i].id.c_str());
        PreparedScene p(applied_checks[i], Precision::Double);
        Image img(W, H, false);
        std::fprintf(stderr, "[check %zu/%zu] %zu triangles, setup %.2f s; rendering %d spp ...\n", i + 1,
                     checks.size(), p.triangleCount(), p.setupSeconds(), checks[i].spp);
        const double t = renderOnce(p, checks[i].spp, img, true);
        const TradeoffError e = tradeoffError(img, reference);
        saveImage(checks[i].id, img);
        J cj = {{"id", checks[i].id}, {"knobs", knobsJson(checks[i], applied_checks[i], p.triangleCount())},
                {"setup_s", p.setupSeconds()}, {"render_s", t}, {"residual", errorJson(e)}};
        conv.push_back(cj);
        std::fprintf(stderr, "[check %zu/%zu] %s: %.2f s; residual max %.2f, p99.9 %.2f, RMSE %.3f (1/65535), "
                     "CIEDE2000 mean %.4f\n", i + 1, checks.size(), checks[i].id.c_str(), t, e.max_16bit,
                     e.p999_16bit, e.rmse_16bit, e.ciede2000_mean);
      }
      ref_json["convergence"] = conv;

      // 3. The sweep.
      J rows = J::array();
      for (size_t i = 0; i + 1 < configs.size(); ++i) {
        const TradeoffConfig& c = configs[i];
        PreparedScene p(applied[i], c.precision);
        Image img(W, H, false);
        const double warm = renderOnce(p, c.spp, img, false);  // warm-up
        std::vector<double> t;
        double sum = 0;
        // A frame that alone takes --max-seconds is not repeated: the
        // warm-up frame is the one timed frame (n = 1).
        const bool warm_counted = warm >= args->max_seconds;
        if (warm_counted) t.push_back(warm), sum = warm;
        while (int(t.size()) < args->frames && (t.empty() || sum < args->max_seconds)) {
          t.push_back(renderOnce(p, c.spp, img, false));
          sum += t.back();
        }
        const Spread s = spread(t);
        const TradeoffError e = tradeoffError(img, reference);
        saveImage(c.id, img);
        rows.push_back({{"id", c.id}, {"group", c.group}, {"knobs", knobsJson(c, applied[i], p.triangleCount())},
                        {"setup_s", p.setupSeconds()}, {"frame_median_s", s.median}, {"frame_min_s", s.min},
                        {"frame_max_s", s.max}, {"frames", s.n}, {"warmup_frame_timed", warm_counted},
                        {"error", errorJson(e)}});
        std::fprintf(stderr, "[%zu/%zu] %-20s frame %9.1f ms (%.1f..%.1f, n=%zu), setup %.2f s; "
                     "max %.1f p99.9 %.1f RMSE %.2f (1/65535), CIEDE2000 %.3f\n",
                     i + 1, configs.size() - 1, c.id.c_str(), s.median * 1e3, s.min * 1e3, s.max * 1e3, s.n,
                     p.setupSeconds(), e.max_16bit, e.p999_16bit, e.rmse_16bit, e.ciede2000_mean);
      }
      rows.push_back(converged_row);

      // 4. The Pareto front (the converged row is the yardstick, not a candidate).
      std::vector<ParetoPoint> pts;
      for (const auto& r : rows) {
        const TradeoffError e = errorFromJson(r["error"]);
        const bool candidate = r["group"] != "converged";
        pts.push_back({candidate ? r["frame_median_s"].get<double>() : std::nan(""), errorMetric(e, args->metric)});
      }
      // Errors closer than the reference's own residual are not resolved.
      double tolerance = 0.0;
      for (const auto& c : conv) tolerance = std::max(tolerance, errorMetric(errorFromJson(c["residual"]), args->metric));
      const std::vector<size_t> front = paretoFront(pts, tolerance);
      J front_ids = J::array();
      for (size_t i = 0; i < rows.size(); ++i) {
        rows[i]["pareto_error"] = pts[i].error;
        rows[i]["pareto"] = std::find(front.begin(), front.end(), i) != front.end();
      }
      for (size_t i : front) front_ids.push_back(rows[i]["id"]);

      const char* metric_labels[][2] = {{"rmse", "RMSE (1/65535)"}, {"p999", "p99.9 error (1/65535)"},
                                        {"max", "max error (1/65535)"}, {"ciede2000", "mean CIEDE2000"}};
      std::string metric_label;
      for (auto& m : metric_labels)
        if (args->metric == m[0]) metric_label = m[1];

      J out;
      out["format"] = "xval-tradeoff/1";
      out["scene"] = scene.name;
      out["scene_file"] = args->scene;
      out["width"] = W, out["height"] = H;
      out["command"] = "xval tradeoff " + args->scene + " -o " + args->out +
                       (args->quick ? " --quick" : "") + " --frames " + std::to_string(args->frames) +
                       " --max-seconds " + fmt(args->max_seconds, 3) + " --reference-spp " +
                       std::to_string(settings.reference_spp) + " --reference-tessellation " +
                       fmt(settings.reference_tessellation, 3) + " --width " + std::to_string(W) +
                       " --height " + std::to_string(H) + " --metric " + args->metric +
                       (args->threads ? " --threads " + std::to_string(args->threads) : "");
      out["date_utc"] = utcNow();
      out["machine"] = {{"cpu", cpuModel()},
                        {"hardware_threads", std::thread::hardware_concurrency()},
                        {"threads_used", args->threads ? unsigned(args->threads) : std::thread::hardware_concurrency()},
                        {"load_average_1min_start", load_start},
                        {"load_average_1min_end", loadAverage1()}};
      out["git_commit"] = firstLine({"git", "rev-parse", "HEAD"}, dir / "git.log");
      out["git_status_lines"] = [&] {
        ProcessResult r = runProcess({"git", "status", "--porcelain", "--untracked-files=no"}, fs::current_path(),
                                     dir / "git.log", 30.0);
        long n = -1;
        if (r.ok()) {
          std::ifstream in(dir / "git.log");
          std::string l;
          n = 0;
          while (std::getline(in, l)) ++n;
        }
        fs::remove(dir / "git.log");
        return n;  // modified tracked files when run (-1: not a git checkout)
      }();
      out["timing"] = {
          {"frames_per_config", args->frames},
          {"max_seconds_per_config", args->max_seconds},
          {"statistic",
           "wall time of one frame (visibility + shading + writing pixels, no diagnostics), median over the "
           "timed frames after one warm-up frame, with min..max; setup (tessellation, texture, BVH) apart"}};
      out["error_definition"] =
          "against the converged reference, over the pixels either image covers, on the final colour "
          "(premultiplied by coverage, over black); a pixel's error is its largest RGB channel difference; "
          "max, p99.9 (nearest rank) and RMSE in 1/65535; CIEDE2000 of the colours taken as sRGB-coded";
      out["pareto_metric"] = args->metric;
      out["pareto_error_tolerance"] = tolerance;
      out["reference"] = ref_json;
      out["configs"] = rows;
      out["pareto_front"] = front_ids;
      out["total_seconds"] = since(t_all);

      writeText(dir / "tradeoff.json", out.dump(2) + "\n");
      writeText(dir / "tradeoff.tsv", tsvTable(out));
      writeText(dir / "tradeoff.md", markdownTable(out));
      writePlot(out, metric_label, dir);
      std::fprintf(stderr, "xval tradeoff: %.1f s; Pareto-optimal (%s):", since(t_all), args->metric.c_str());
      for (const auto& id : front_ids) std::fprintf(stderr, " %s", id.get<std::string>().c_str());
      std::fprintf(stderr, "\nxval tradeoff: wrote %s/{tradeoff.json,tradeoff.tsv,tradeoff.md,pareto.png}\n",
                   dir.c_str());
      return 0;
    };
  });
}

}  // namespace xval::cli
