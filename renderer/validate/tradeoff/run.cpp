// The trade-off run (validate/tradeoff/run.h).
#include "validate/tradeoff/run.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <thread>
#include <variant>

#include <nlohmann/json.hpp>

#include "files/atomic_write.h"
#include "files/output_folder.h"
#include "image/image.h"
#include "render/renderer.h"
#include "scene_file/scene_loader.h"
#include "validate/common/frame_timing.h"
#include "text/number_text.h"
#include "validate/common/provenance.h"
#include "validate/tradeoff/pareto_plot.h"
#include "validate/tradeoff/sweep.h"
#include "validate/tradeoff/tables.h"

namespace xval {

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;
using J = nlohmann::ordered_json;

double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// "768x40" for the first tessellated shape, "-" for planes only.
std::string segmentsOf(const Scene& s) {
  for (const SceneObject& object : s.objects) {
    const Shape& shape = object.shape;
    if (auto* k = std::get_if<TorusKnot>(&shape))
      return std::to_string(k->segments_along) + "x" + std::to_string(k->segments_around);
    if (auto* u = std::get_if<UvSphere>(&shape))
      return std::to_string(u->segments_longitude) + "x" + std::to_string(u->segments_latitude);
  }
  return "-";
}

// The named fields, and "metrics": the metric table's values by id (a
// value that is not finite as null).
J errorJson(const TradeoffError& e) {
  J metrics = J::object();
  for (const auto& [id, v] : e.metrics) metrics[id] = std::isfinite(v) ? J(v) : J(nullptr);
  return {{"pixels", e.pixels},           {"max_16bit", e.max_16bit},
          {"p999_16bit", e.p999_16bit},   {"rmse_16bit", e.rmse_16bit},
          {"ciede2000_mean", e.ciede2000_mean}, {"ciede2000_max", e.ciede2000_max},
          {"metrics", metrics}};
}

TradeoffError errorFromJson(const J& j) {
  TradeoffError e;
  e.pixels = j.value("pixels", 0LL);
  e.max_16bit = j.at("max_16bit").get<double>();
  e.p999_16bit = j.at("p999_16bit").get<double>();
  e.rmse_16bit = j.at("rmse_16bit").get<double>();
  e.ciede2000_mean = j.at("ciede2000_mean").get<double>();
  e.ciede2000_max = j.at("ciede2000_max").get<double>();
  const J metrics = j.value("metrics", J::object());  // a local: items() refers to it
  for (const auto& [id, v] : metrics.items()) e.metrics[id] = v.is_number() ? v.get<double>() : std::nan("");
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

// One configuration's row: timing and error of its last frame.
J row(const TradeoffConfig& c, const Scene& applied, const PreparedScene& p, const FrameTimes& ft,
      const Image& img, const Image& reference) {
  const Spread s = spread(ft.wall_s);
  return {{"id", c.id}, {"group", c.group}, {"knobs", knobsJson(c, applied, p.triangleCount())},
          {"setup_s", p.setupSeconds()}, {"frame_median_s", s.median}, {"frame_min_s", s.min},
          {"frame_max_s", s.max}, {"frames", s.n}, {"warmup_frame_timed", ft.warmup_frame_timed},
          {"error", errorJson(tradeoffError(img, reference))}};
}

std::string commandLine(const TradeoffRun& a, const SweepSettings& settings, int W, int H) {
  return "xval tradeoff " + a.scene_file + " -o " + a.out + (a.quick ? " --quick" : "") + " --frames " +
         std::to_string(a.frames) + " --max-seconds " + fixed(a.max_seconds, 3) + " --reference-spp " +
         std::to_string(settings.reference_spp) + " --reference-tessellation " +
         fixed(settings.reference_tessellation, 3) + " --width " + std::to_string(W) + " --height " +
         std::to_string(H) + " --metric " + a.metric + (a.threads ? " --threads " + std::to_string(a.threads) : "");
}

// Renders and times the configurations of one run.
class Runner {
 public:
  Runner(const TradeoffRun& a, const fs::path& dir, int W, int H) : a_(a), dir_(dir), W_(W), H_(H) {
    opt_.threads = a.threads;
    opt_.diagnostics = false;
  }

  // 1. The converged reference (into `reference`), its knobs as "reference",
  // and the converged row timed on it (the reference frame was its warm-up).
  std::pair<J, J> reference(const TradeoffConfig& cfg, const Scene& applied, Image& reference) const {
    std::fprintf(stderr, "[reference] preparing %s ...\n", cfg.id.c_str());
    PreparedScene p(applied, Precision::Double);
    std::fprintf(stderr, "[reference] %zu triangles, setup %.2f s; rendering %d spp ...\n", p.triangleCount(),
                 p.setupSeconds(), cfg.spp);
    const double t_ref = renderOnce(p, cfg.spp, reference, true);
    std::fprintf(stderr, "[reference] %.2f s\n", t_ref);
    saveImage("reference", reference);
    J ref_json = knobsJson(cfg, applied, p.triangleCount());
    ref_json["setup_s"] = p.setupSeconds();
    ref_json["render_s"] = t_ref;
    Image img(W_, H_, false);
    const FrameTimes ft = timeFrames([&] { renderOnce(p, cfg.spp, img, false); }, budget(), WarmUp::AlreadyDone);
    J converged_row = row(cfg, applied, p, ft, img, reference);
    std::fprintf(stderr, "[converged] frame %.1f ms (n=%zu), error against the reference: RMSE %.3g\n",
                 converged_row["frame_median_s"].get<double>() * 1e3, ft.wall_s.size(),
                 converged_row["error"]["rmse_16bit"].get<double>());
    return {ref_json, converged_row};
  }

  // 2. The reference against one step finer each way: the residuals.
  J convergence(const std::vector<TradeoffConfig>& checks, const std::vector<Scene>& applied,
                const Image& reference) const {
    J conv = J::array();
    for (size_t i = 0; i < checks.size(); ++i) {
      std::fprintf(stderr, "[check %zu/%zu] %s: preparing ...\n", i + 1, checks.size(), checks[i].id.c_str());
      PreparedScene p(applied[i], Precision::Double);
      Image img(W_, H_, false);
      std::fprintf(stderr, "[check %zu/%zu] %zu triangles, setup %.2f s; rendering %d spp ...\n", i + 1,
                   checks.size(), p.triangleCount(), p.setupSeconds(), checks[i].spp);
      const double t = renderOnce(p, checks[i].spp, img, true);
      const TradeoffError e = tradeoffError(img, reference);
      saveImage(checks[i].id, img);
      conv.push_back({{"id", checks[i].id}, {"knobs", knobsJson(checks[i], applied[i], p.triangleCount())},
                      {"setup_s", p.setupSeconds()}, {"render_s", t}, {"residual", errorJson(e)}});
      std::fprintf(stderr,
                   "[check %zu/%zu] %s: %.2f s; residual max %.2f, p99.9 %.2f, RMSE %.3f (1/65535), "
                   "CIEDE2000 mean %.4f\n",
                   i + 1, checks.size(), checks[i].id.c_str(), t, e.max_16bit, e.p999_16bit, e.rmse_16bit,
                   e.ciede2000_mean);
    }
    return conv;
  }

  // 3. The sweep: every configuration but the last ("converged").
  J sweep(const std::vector<TradeoffConfig>& configs, const std::vector<Scene>& applied,
          const Image& reference) const {
    J rows = J::array();
    for (size_t i = 0; i + 1 < configs.size(); ++i) {
      const TradeoffConfig& c = configs[i];
      PreparedScene p(applied[i], c.precision);
      Image img(W_, H_, false);
      const FrameTimes ft = timeFrames([&] { renderOnce(p, c.spp, img, false); }, budget(), WarmUp::Render);
      saveImage(c.id, img);
      rows.push_back(row(c, applied[i], p, ft, img, reference));
      const J& r = rows.back();
      const J& e = r["error"];
      std::fprintf(stderr,
                   "[%zu/%zu] %-20s frame %9.1f ms (%.1f..%.1f, n=%zu), setup %.2f s; "
                   "max %.1f p99.9 %.1f RMSE %.2f (1/65535), CIEDE2000 %.3f\n",
                   i + 1, configs.size() - 1, c.id.c_str(), r["frame_median_s"].get<double>() * 1e3,
                   r["frame_min_s"].get<double>() * 1e3, r["frame_max_s"].get<double>() * 1e3, ft.wall_s.size(),
                   p.setupSeconds(), e["max_16bit"].get<double>(), e["p999_16bit"].get<double>(),
                   e["rmse_16bit"].get<double>(), e["ciede2000_mean"].get<double>());
    }
    return rows;
  }

 private:
  FrameBudget budget() const { return {a_.frames, a_.max_seconds}; }
  double renderOnce(const PreparedScene& p, int spp, Image& img, bool progress) const {
    RenderOptions o = opt_;
    o.spp = spp;
    o.precision = p.precision();
    o.progress = progress;
    const auto t0 = Clock::now();
    p.render(o, img);
    return since(t0);
  }
  void saveImage(const std::string& id, const Image& img) const {
    if (a_.images) writeImage(img, dir_ / "images" / (fileSafe(id) + ".exr"));
  }

  const TradeoffRun& a_;
  fs::path dir_;
  int W_, H_;
  RenderOptions opt_;
};

// 4. The Pareto front (the converged row is the yardstick, not a
// candidate): marks every row's pareto_error and pareto; returns the
// front's ids and the tolerance (the largest convergence residual: errors
// closer than the reference's own residual are not resolved).
std::pair<J, double> markParetoFront(J& rows, const J& conv, const std::string& metric) {
  std::vector<ParetoPoint> pts;
  for (const auto& r : rows) {
    const TradeoffError e = errorFromJson(r["error"]);
    const bool candidate = r["group"] != "converged";
    pts.push_back({candidate ? r["frame_median_s"].get<double>() : std::nan(""), errorMetric(e, metric)});
  }
  double tolerance = 0.0;
  for (const auto& c : conv) tolerance = std::max(tolerance, errorMetric(errorFromJson(c["residual"]), metric));
  const std::vector<size_t> front = paretoFront(pts, tolerance);
  J front_ids = J::array();
  for (size_t i = 0; i < rows.size(); ++i) {
    rows[i]["pareto_error"] = pts[i].error;
    rows[i]["pareto"] = std::find(front.begin(), front.end(), i) != front.end();
  }
  for (size_t i : front) front_ids.push_back(rows[i]["id"]);
  return {front_ids, tolerance};
}

// The run's header fields of tradeoff.json (format .. pareto_metric).
J header(const TradeoffRun& a, const Scene& scene, const SweepSettings& settings, const Provenance& prov) {
  const int W = scene.camera.width, H = scene.camera.height;
  J out;
  out["format"] = "xval-tradeoff/1";
  out["scene"] = scene.name;
  out["scene_file"] = a.scene_file;
  out["width"] = W, out["height"] = H;
  out["command"] = commandLine(a, settings, W, H);
  out["date_utc"] = prov.date_utc;
  out["machine"] = {{"cpu", prov.cpu},
                    {"hardware_threads", prov.hardware_threads},
                    {"threads_used", a.threads ? unsigned(a.threads) : prov.hardware_threads},
                    {"load_average_1min_start", prov.load_average_1min},
                    {"load_average_1min_end", loadAverage1()}};
  out["git_commit"] = prov.git_commit;
  out["git_status_lines"] = prov.git_modified_files;  // modified tracked files (-1: not a git checkout)
  out["compiler"] = prov.compiler;
  out["timing"] = {
      {"frames_per_config", a.frames},
      {"max_seconds_per_config", a.max_seconds},
      {"statistic",
       "wall time of one frame (visibility + shading + writing pixels, no diagnostics), median over the "
       "timed frames after one warm-up frame, with min..max; setup (tessellation, texture, BVH) apart"}};
  out["error_definition"] =
      "against the converged reference, over the pixels either image covers, on the final colour "
      "(premultiplied by coverage, over black); a pixel's error is its largest RGB channel difference; "
      "max, p99.9 (nearest rank) and RMSE in 1/65535; CIEDE2000 of the colours taken as sRGB-coded; "
      "metrics: every entry of the metric table (image/metric_table.h) over the same pixels";
  out["pareto_metric"] = a.metric;
  return out;
}

fs::path makeOutputFolder(const std::string& out) {
  const fs::path dir(out);
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir))
    throw std::runtime_error(dir.string() + ": cannot create the output folder" +
                             (ec ? ": " + ec.message() : std::string()));
  return dir;
}

}  // namespace

void runTradeoff(const TradeoffRun& a) {
  const std::string metric_label = labelWithUnit(tradeoffAxis(a.metric));
  Scene scene = loadScene(a.scene_file, a.budget);
  if (a.width) scene.camera.width = a.width;
  if (a.height) scene.camera.height = a.height;
  SweepSettings settings;
  settings.quick = a.quick;
  settings.reference_spp = a.reference_spp ? a.reference_spp : (a.quick ? 16 : 64);
  settings.reference_tessellation = a.reference_tessellation > 0 ? a.reference_tessellation : (a.quick ? 2.0 : 4.0);
  const std::vector<TradeoffConfig> configs = sweepConfigs(scene, settings);
  const std::vector<TradeoffConfig> checks = convergenceChecks(scene, settings);
  // Every configuration is checked by the loader before anything runs.
  std::vector<Scene> applied, applied_checks;
  for (const auto& c : configs) applied.push_back(applyConfig(scene, c, a.budget));
  for (const auto& c : checks) applied_checks.push_back(applyConfig(scene, c, a.budget));

  const fs::path dir = makeOutputFolder(a.out);
  const FolderLock folder_lock(dir, FolderLock::Mode::Exclusive, "xval tradeoff");
  if (a.images) makeRealFolder(dir, dir / "images");
  const int W = scene.camera.width, H = scene.camera.height;
  const auto t_all = Clock::now();
  const Provenance prov = collectProvenance(dir / "git.log");
  std::fprintf(stderr,
               "xval tradeoff %s (%dx%d): %zu configurations, reference %d spp x%g tessellation "
               "double phong, %zu convergence checks; up to %d frames or %.1f s per configuration\n",
               scene.name.c_str(), W, H, configs.size(), configs.back().spp, configs.back().tessellation_factor,
               checks.size(), a.frames, a.max_seconds);

  const Runner runner(a, dir, W, H);
  Image reference(W, H, false);
  auto [ref_json, converged_row] = runner.reference(configs.back(), applied.back(), reference);
  const J conv = runner.convergence(checks, applied_checks, reference);
  ref_json["convergence"] = conv;
  J rows = runner.sweep(configs, applied, reference);
  rows.push_back(converged_row);
  const auto [front_ids, tolerance] = markParetoFront(rows, conv, a.metric);

  J out = header(a, scene, settings, prov);
  out["pareto_error_tolerance"] = tolerance;
  out["reference"] = ref_json;
  out["configs"] = rows;
  out["pareto_front"] = front_ids;
  out["total_seconds"] = since(t_all);
  writeFileAtomically(dir / "tradeoff.json", out.dump(2) + "\n");
  writeFileAtomically(dir / "tradeoff.tsv", tsvTable(out));
  writeFileAtomically(dir / "tradeoff.md", markdownTable(out));
  writeParetoPlot(out, metric_label, dir);
  std::fprintf(stderr, "xval tradeoff: %.1f s; Pareto-optimal (%s):", since(t_all), a.metric.c_str());
  for (const auto& id : front_ids) std::fprintf(stderr, " %s", id.get<std::string>().c_str());
  std::fprintf(stderr, "\nxval tradeoff: wrote %s/{tradeoff.json,tradeoff.tsv,tradeoff.md,pareto.png}\n", dir.c_str());
}

}  // namespace xval
