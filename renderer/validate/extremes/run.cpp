// xval extremes -o DIR/ [--size N] [--only NAME,...] [--no-external]
//               [--renderers povray,blender] [--jobs N] [--timeout S] [--threads N]
//
// Runs the extremes matrix (validate/extremes.h, docs/extremes.md): writes
// every case's scene into DIR/scenes/, renders it with the reference
// renderer in double and in float (one case after another, all threads),
// then with POV-Ray and Blender (--jobs renders at a time, default the
// core count; each killed after --timeout seconds, default 600), and
// compares. Writes:
//   DIR/extremes.json       per case: scene file, NaN/Inf counts of both
//                           reference renders, float-vs-double metrics,
//                           per external renderer its status and metrics
//   DIR/extremes.md         the same as a Markdown table (for docs)
//   DIR/<case>/double.exr, float.exr, <renderer>.exr (ignored by git),
//   DIR/<case>/*.png        8-bit previews and heat maps (heat_float.png:
//                           float vs double; heat_<renderer>.png: that
//                           renderer vs double), DIR/heat_scale.png
// Progress on stderr.
//
// Parameters and defaults: --size 160 (pixels per side of every case),
// --only all cases, --renderers povray,blender, --jobs = hardware threads,
// --timeout 600 s, --threads = hardware threads (reference renders).
//
// Exit status: 0 when the reference renderer has no NaN/Inf in any case and
// precision (final or raw channels) and every external render that was
// attempted either succeeded or was refused by its exporter with a reason;
// 1 when the reference renderer produced a NaN or Inf; 2 on an error (bad
// option, a case that cannot be written or loaded, an external renderer
// that failed, timed out or is missing: an error, never a pass).
#include <atomic>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <sstream>
#include <thread>

#include "blender/blender_render.h"
#include "cli/cli_common.h"
#include "cli/commands.h"
#include "common/export_common.h"
#include "process/run_process.h"
#include "files/atomic_write.h"
#include "files/output_folder.h"
#include "povray/pov_render.h"
#include "scene/scene_loader.h"
#include "validate/extremes/matrix.h"

namespace xval::cli {

namespace {

using Clock = std::chrono::steady_clock;
using J = nlohmann::ordered_json;
namespace ex = xval::extremes;

double since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

const char* displayName(const std::string& renderer) {
  return renderer == "povray" ? "POV-Ray" : "Blender";
}

struct External {
  std::string status;  // "ok", "not renderable", "error", "not run"
  std::string reason;  // for anything but ok
  Image image;
  double seconds = 0.0, render_seconds = -1.0;
};

struct CaseRun {
  ex::Case c;
  std::filesystem::path file;
  Scene scene;
  ex::ReferenceRender dbl, flt;
  std::map<std::string, External> external;
};

External renderExternal(const Scene& scene, const std::string& renderer,
                        const std::filesystem::path& work, double timeout) {
  External e;
  const auto t0 = Clock::now();
  try {
    ExternalRenderInfo info;
    e.image = renderer == "povray" ? renderWithPovray(scene, work, timeout, &info)
                                   : renderWithBlender(scene, work, timeout, &info);
    e.render_seconds = info.render_seconds;
    e.status = "ok";
  } catch (const ExportError& err) {
    e.status = "not renderable";
    e.reason = std::string("not renderable by ") + displayName(renderer) + ": " + err.what();
  } catch (const std::exception& err) {
    e.status = "error";
    e.reason = std::string(displayName(renderer)) + " failed: " + err.what();
  }
  e.seconds = since(t0);
  return e;
}

std::string firstLineOf(const std::filesystem::path& f) {
  std::ifstream in(f);
  std::string line;
  std::getline(in, line);
  return line;
}

// "model name : AMD EPYC ..." from /proc/cpuinfo, and the thread count.
std::string machine() {
  std::ifstream in("/proc/cpuinfo");
  std::string line, model = "unknown CPU";
  while (std::getline(in, line))
    if (line.rfind("model name", 0) == 0) {
      model = line.substr(line.find(':') + 2);
      break;
    }
  return model + ", " + std::to_string(std::thread::hardware_concurrency()) + " hardware threads";
}

// The commit of the working tree xval runs in, else of the one its
// executable was built in (build folders live inside the source tree),
// with "-dirty" when that tree has uncommitted changes outside results/
// (the main job rewrites the published report there before this runs).
std::string gitCommit(const std::filesystem::path& tmp) {
  std::error_code ec;
  const std::filesystem::path exe_dir = std::filesystem::read_symlink("/proc/self/exe", ec).parent_path();
  std::string s = "unknown";
  for (const auto& where : {std::filesystem::current_path(), exe_dir}) {
    if (where.empty()) continue;
    ProcessResult r = runProcess({"git", "-C", where.string(), "rev-parse", "HEAD"}, where, tmp, 30);
    if (!r.ok()) continue;
    s = firstLineOf(tmp);
    r = runProcess({"git", "-C", where.string(), "status", "--porcelain", "--untracked-files=no", "--",
                    ":(top,exclude)results"},
                   where, tmp, 30);
    if (!r.ok() || !firstLineOf(tmp).empty()) s += "-dirty";
    break;
  }
  std::filesystem::remove(tmp);
  return s;
}

std::string fmt(const J& v, int prec) {
  if (v.is_null()) return "n/a";
  char b[64];
  std::snprintf(b, sizeof b, "%.*f", prec, v.get<double>());
  return b;
}

// The Markdown table of DIR/extremes.md (docs/extremes.md quotes it).
std::string markdown(const J& results) {
  std::ostringstream o;
  o << "Generated by `xval extremes` (" << results["provenance"]["date"].get<std::string>()
    << ", " << results["provenance"]["machine"].get<std::string>() << ", commit "
    << ex::shortCommit(results["provenance"]["git_commit"].get<std::string>())
    << "). Errors in 1/65535 of full scale over the pixels both images cover; "
       "NaN/Inf: pixels with a non-finite final / raw value.\n\n"
       "| case | NaN/Inf double | NaN/Inf float | float vs double: max / p99.9 (mask) | "
       "POV-Ray: max / p99.9 (mask) | Blender: max / p99.9 (mask) |\n|---|---|---|---|---|---|\n";
  for (const J& c : results["cases"]) {
    const J& r = c["reference"];
    auto nf = [](const J& p) {
      return std::to_string(p["nonfinite"]["final"].get<long long>()) + " / " +
             std::to_string(p["nonfinite"]["raw"].get<long long>());
    };
    auto m = [](const J& mm) {
      return fmt(mm["max_abs_16bit"], 2) + " / " + fmt(mm["p999_abs_16bit"], 2) + " (" +
             std::to_string(mm["mask_disagree"].get<long long>()) + ")";
    };
    o << "| " << c["name"].get<std::string>() << " | " << nf(r["double"]) << " | " << nf(r["float"])
      << " | " << m(c["float_vs_double"]);
    for (const char* rr : {"povray", "blender"}) {
      o << " | ";
      if (!c["external"].contains(rr)) {
        o << "not run";
        continue;
      }
      const J& e = c["external"][rr];
      const std::string st = e["status"].get<std::string>();
      if (st == "ok") o << m(e["metrics"]);
      else if (st == "not renderable") o << "not renderable";
      else o << st;
    }
    o << " |\n";
  }
  return o.str();
}

}  // namespace

void addExtremesCommand(CLI::App& app, std::function<int()>& run) {
  struct Args {
    std::string dir, only, renderers = "povray,blender";
    int size = 160, jobs = 0, threads = 0;
    double timeout = kDefaultToolTimeoutSeconds;
    bool no_external = false;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "extremes",
      "Run the extremes matrix (docs/extremes.md): scenes at the edges of every model's domain "
      "(specular power 0..1e6, N.L near 0 and +-1, a light on the surface and 1e8 away, scale "
      "1e-6 and 1e6, black/white/saturated colours, a thin high-p,q knot, degenerate "
      "triangles, light at the eye, a spot cone's edge), each rendered by the reference "
      "renderer in float and double and by POV-Ray and Blender. Writes DIR/scenes/*.json, "
      "DIR/extremes.json, DIR/extremes.md and heat maps.\n"
      "Exit 0: no NaN/Inf in the reference renderer and no external error; 1: the reference "
      "renderer produced a NaN/Inf; 2: an error (an external renderer failed: never a pass).");
  cmd->add_option("-o,--output", args->dir, "Output folder")->required();
  cmd->add_option("--size", args->size, "Pixels per side of every case (default 160)")
      ->check(CLI::Range(8, 4096));
  cmd->add_option("--only", args->only, "Comma-separated case names (default: all)");
  cmd->add_flag("--no-external", args->no_external,
                "Reference renderer only (float and double); no POV-Ray or Blender");
  cmd->add_option("--renderers", args->renderers,
                  "External renderers, comma-separated: povray, blender (default: both)");
  cmd->add_option("--jobs", args->jobs, "External renders in parallel (default: the core count)")
      ->check(CLI::Range(1, 256));
  cmd->add_option("--timeout", args->timeout, "Seconds before an external renderer is killed (600)")
      ->check(Seconds);
  cmd->add_option("--threads", args->threads,
                  "Threads of each reference render (default: every hardware thread)")
      ->check(CLI::Range(1, 1024));
  cmd->callback([args, &run]() {
    run = [args]() -> int {
      try {
        const auto t_start = Clock::now();
        const std::filesystem::path dir(args->dir);
        std::vector<ex::Case> all = ex::extremesMatrix({args->size});
        std::vector<ex::Case> cases;
        if (args->only.empty()) {
          cases = all;
        } else {
          std::set<std::string> want;
          std::stringstream ss(args->only);
          for (std::string item; std::getline(ss, item, ',');)
            if (!item.empty()) want.insert(item);
          for (const auto& c : all)
            if (want.erase(c.name)) cases.push_back(c);
          if (!want.empty()) {
            std::string names;
            for (const auto& c : all) names += " " + c.name;
            throw std::runtime_error("--only: no case named " + *want.begin() + "; the cases are:" + names);
          }
        }
        std::vector<std::string> renderers;
        if (!args->no_external) {
          std::stringstream ss(args->renderers);
          for (std::string item; std::getline(ss, item, ',');) {
            if (item != "povray" && item != "blender")
              throw std::runtime_error("--renderers: expected povray and/or blender, got " + item);
            renderers.push_back(item);
          }
        }
        std::filesystem::create_directories(dir);
        const FolderLock folder_lock(dir, FolderLock::Mode::Exclusive, "xval extremes");
        std::filesystem::remove(dir / "extremes.json");  // a new run: no stale results
        std::filesystem::remove(dir / "extremes.md");
        makeRealFolder(dir, dir / "scenes");
        const auto files = ex::writeCaseScenes(cases, dir / "scenes");
        std::vector<CaseRun> runs(cases.size());
        for (size_t k = 0; k < cases.size(); ++k) {
          runs[k].c = cases[k];
          runs[k].file = files[k];
          runs[k].scene = loadScene(files[k]);  // the file as anyone would load it
        }
        std::fprintf(stderr, "xval extremes: %zu cases, %dx%d, reference renderer (double, float)%s\n",
                     runs.size(), args->size, args->size,
                     renderers.empty() ? "" : (", then " + args->renderers).c_str());

        // 1. The reference renderer, both precisions, one case at a time.
        for (size_t k = 0; k < runs.size(); ++k) {
          CaseRun& r = runs[k];
          const std::filesystem::path cdir = dir / r.c.name;
          makeRealFolder(dir, cdir);
          r.dbl = ex::renderReference(r.scene, Precision::Double, args->threads);
          r.flt = ex::renderReference(r.scene, Precision::Float, args->threads);
          writeImage(r.dbl.image, cdir / "double.exr");
          writeImage(r.flt.image, cdir / "float.exr");
          writePreviewPng(r.dbl.image, cdir / "double.png", 360);
          ex::writeHeatMap(r.dbl.image, r.flt.image, cdir / "heat_float.png");
          const CompareMetrics m = ex::compareToReference(r.dbl.image, r.flt.image);
          std::fprintf(stderr,
                       "[%2zu/%zu] %-28s double %.2f s, float %.2f s; NaN/Inf %lld/%lld (double), "
                       "%lld/%lld (float); float vs double max %.2f p99.9 %.2f /65535, mask %lld\n",
                       k + 1, runs.size(), r.c.name.c_str(), r.dbl.seconds, r.flt.seconds,
                       r.dbl.nonfinite.final_pixels, r.dbl.nonfinite.raw_pixels,
                       r.flt.nonfinite.final_pixels, r.flt.nonfinite.raw_pixels, m.max_abs * 65535.0,
                       m.p999_abs * 65535.0, m.mask_disagree);
        }

        // 2. External renderers, in parallel.
        struct Job { size_t k; std::string renderer; };
        std::vector<Job> jobs;
        for (size_t k = 0; k < runs.size(); ++k)
          for (const auto& rr : renderers) jobs.push_back({k, rr});
        const int workers = args->jobs > 0 ? args->jobs : int(std::max(1u, std::thread::hardware_concurrency()));
        std::atomic<size_t> next{0}, done{0};
        std::mutex lock;
        const auto t_ext = Clock::now();
        auto worker = [&]() {
          for (size_t j = next++; j < jobs.size(); j = next++) {
            CaseRun& r = runs[jobs[j].k];
            const std::string& rr = jobs[j].renderer;
            External e;
            try {
              const std::filesystem::path work = dir / r.c.name / (rr + ".work");
              makeFreshFolder(work);  // nothing from an earlier attempt, no planted link
              e = renderExternal(r.scene, rr, work, args->timeout);
            } catch (const std::exception& err) {  // never out of the thread
              e.status = "error";
              e.reason = err.what();
            }
            std::lock_guard<std::mutex> g(lock);
            const size_t n = ++done;
            const double el = since(t_ext);
            std::fprintf(stderr, "[%zu/%zu] %-28s %-8s %-14s %6.2f s   elapsed %.0f s, ~%.0f s left\n",
                         n, jobs.size(), r.c.name.c_str(), rr.c_str(), e.status.c_str(), e.seconds, el,
                         el * double(jobs.size() - n) / double(n));
            if (e.status != "ok") std::fprintf(stderr, "  %s\n", e.reason.c_str());
            r.external[rr] = std::move(e);
          }
        };
        std::vector<std::thread> pool;
        for (int w = 0; w < std::min<int>(workers, int(std::max<size_t>(1, jobs.size()))); ++w)
          pool.emplace_back(worker);
        for (auto& t : pool) t.join();

        // 3. Comparisons and the results.
        long long reference_nonfinite = 0;
        int external_errors = 0;
        J jcases = J::array();
        for (CaseRun& r : runs) {
          const std::filesystem::path cdir = dir / r.c.name;
          J jc;
          jc["name"] = r.c.name;
          jc["group"] = r.c.group;
          jc["what"] = r.c.what;
          jc["scene"] = "scenes/" + r.c.name + ".json";
          jc["size"] = J::array({r.scene.camera.width, r.scene.camera.height});
          jc["rerun"] = "xval render " + (dir / jc["scene"].get<std::string>()).string() +
                        " -o OUT.exr --precision float|double";
          for (auto* p : {&r.dbl, &r.flt}) {
            const char* key = p == &r.dbl ? "double" : "float";
            jc["reference"][key] = {{"seconds", p->seconds},
                                    {"image", r.c.name + "/" + key + ".exr"},
                                    {"nonfinite", {{"final", p->nonfinite.final_pixels},
                                                   {"raw", p->nonfinite.raw_pixels}}}};
            reference_nonfinite += p->nonfinite.total();
          }
          J fd = ex::metricsJson(ex::compareToReference(r.dbl.image, r.flt.image));
          fd["map"] = r.c.name + "/heat_float.png";
          jc["float_vs_double"] = fd;
          jc["preview"] = r.c.name + "/double.png";
          jc["external"] = J::object();
          for (const auto& rr : renderers) {
            External& e = r.external[rr];
            J je = {{"status", e.status}, {"seconds", e.seconds}};
            if (e.render_seconds >= 0) je["render_seconds"] = e.render_seconds;
            if (e.status == "ok") {
              writeImage(e.image, cdir / (rr + ".exr"));
              writePreviewPng(e.image, cdir / (rr + ".png"), 360);
              ex::writeHeatMap(r.dbl.image, e.image, cdir / ("heat_" + rr + ".png"));
              J m = ex::metricsJson(ex::compareToReference(r.dbl.image, e.image));
              m["map"] = r.c.name + "/heat_" + rr + ".png";
              const ex::NonFinite nf = ex::countNonFinite(e.image);
              je["nonfinite"] = {{"final", nf.final_pixels}, {"raw", nf.raw_pixels}};
              je["metrics"] = m;
              je["preview"] = r.c.name + "/" + rr + ".png";
            } else {
              je["reason"] = e.reason;
              external_errors += e.status == "error";
            }
            jc["external"][rr] = je;
          }
          jcases.push_back(jc);
        }
        ex::writeHeatScale(dir / "heat_scale.png");
        J results;
        results["format"] = "xval-extremes/1";
        {
          std::time_t now = std::time(nullptr);
          char date[32];
          std::strftime(date, sizeof date, "%Y-%m-%d", std::gmtime(&now));
          results["provenance"] = {{"date", date},
                                   {"machine", machine()},
                                   {"git_commit", gitCommit(dir / "git.log")},
                                   {"command", "xval extremes -o " + args->dir +
                                                   (args->size != 160 ? " --size " + std::to_string(args->size) : "") +
                                                   (args->no_external ? " --no-external" : "")},
                                   {"renderers", renderers}};
        }
        results["size"] = args->size;
        results["wall_seconds"] = since(t_start);
        results["totals"] = {{"cases", runs.size()},
                             {"reference_nonfinite_pixels", reference_nonfinite},
                             {"external_errors", external_errors}};
        results["cases"] = jcases;
        writeFileAtomically(dir / "extremes.md", markdown(results));
        writeFileAtomically(dir / "extremes.json", results.dump(2) + "\n");
        std::fprintf(stderr,
                     "xval extremes: wrote %s (%zu cases, %.0f s): reference renderer NaN/Inf pixels: "
                     "%lld; external renderer errors: %d\n",
                     (dir / "extremes.json").c_str(), runs.size(), since(t_start), reference_nonfinite,
                     external_errors);
        if (external_errors) return 2;
        return reference_nonfinite ? 1 : 0;
      } catch (const std::exception& e) {
        std::fprintf(stderr, "xval extremes: error: %s\n", e.what());
        return 2;
      }
    };
  });
}

}  // namespace xval::cli
