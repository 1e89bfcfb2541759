// xval_model_corpus ROOT PROBE [--timeout S] [--every K] [--report FILE] [--render] [--blender XVAL]:
// every regular file under ROOT (sorted; with --every K, the K-th ones of
// the sorted list plus every file in a folder named "invalid" or whose
// path names a deliberately broken case, see kAlwaysRun) through the model
// loader, each model file (an extension loadModelFile reads) in a probe
// process of its own with a time-out, all other files in one probe
// (refused by their extension before anything is read).
//
// Passes (exit 0) when every file was loaded or refused with a message
// naming it, and no probe crashed (signal, sanitizer report: non-zero
// exit), hung (time-out) or let an exception other than ModelFileError
// escape. With --render, each model file is also rendered by the probe
// (xval_model_probe --render: a generated scene of it, both paths), and a
// loaded file must have been rendered. With --blender XVAL (implies
// --render), every probe scene of a file that loaded then goes through the
// Blender export: `XVAL validate` of them all with the renderers reference
// and blender (the glTF export, Blender's import of it and its harness,
// exporters/blender/render_gltf.py, whose corner count check is where a
// mesh Blender changes on import shows), batched; each file's Blender
// render must be ok or declared not expressible with a reason (a render
// error is a failure; the images are not compared, the scenes declare no
// tolerances). Prints one line per model file (outcome, seconds, message)
// and a summary; --report writes the same lines to FILE.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "geometry/model_file.h"
#include "process/run_process.h"

namespace fs = std::filesystem;

namespace {

// Path parts of the corpus's deliberately broken files (always run).
const char* const kAlwaysRun[] = {"invalid", "OutOfRange", "Infinit", "Missing", "wrongTypes", "Recursive",
                                  "SchemaFailures", "IncorrectVertexArrays", "crash", "empty", "malformed"};

bool isModelFile(const fs::path& p) {
  std::string e = p.extension().string();
  for (auto& c : e) c = char(std::tolower((unsigned char)c));
  const auto& exts = xval::modelFileExtensions();
  return std::find(exts.begin(), exts.end(), e) != exts.end();
}

std::string readAll(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::cerr << "usage: xval_model_corpus ROOT PROBE [--timeout S] [--every K] [--report FILE] [--render]\n";
    return 64;
  }
  const fs::path root = argv[1], probe = fs::absolute(argv[2]);
  double timeout = 60;
  size_t every = 1;
  fs::path report;
  bool render = false;
  fs::path xval_cli;
  for (int i = 3; i < argc; i += 2) {
    const std::string a = argv[i];
    if (a == "--render") {
      render = true, --i;
      continue;
    }
    if (i + 1 >= argc) return std::cerr << "option " << a << " needs a value\n", 64;
    if (a == "--timeout") timeout = std::stod(argv[i + 1]);
    else if (a == "--every") every = std::max<size_t>(1, std::stoul(argv[i + 1]));
    else if (a == "--report") report = argv[i + 1];
    else if (a == "--blender") xval_cli = fs::absolute(argv[i + 1]), render = true;
    else return std::cerr << "unknown option " << a << "\n", 64;
  }
  std::error_code ec;
  if (!fs::is_directory(root, ec)) {
    std::cerr << "xval_model_corpus: " << root << " is not a folder (install assimp-testmodels)\n";
    return 1;
  }
  std::vector<fs::path> files;
  for (auto it = fs::recursive_directory_iterator(root, ec); !ec && it != fs::recursive_directory_iterator();
       it.increment(ec))
    if (it->is_regular_file(ec)) files.push_back(it->path());
  if (ec) return std::cerr << "xval_model_corpus: " << root << ": " << ec.message() << "\n", 1;
  std::sort(files.begin(), files.end());
  std::vector<fs::path> models, others;
  for (size_t i = 0; i < files.size(); ++i) {
    const std::string s = files[i].string();
    bool always = false;
    for (const char* part : kAlwaysRun) always = always || s.find(part) != std::string::npos;
    if (!always && i % every != 0) continue;
    (isModelFile(files[i]) ? models : others).push_back(files[i]);
  }
  const fs::path work = fs::temp_directory_path() / ("xval_model_corpus_" + xval::attemptToken());
  fs::create_directories(work);
  std::ostringstream lines;
  int bad = 0, loaded = 0, refused = 0;
  // One probe per model file; the others in one (refused by extension).
  auto run = [&](const std::vector<fs::path>& batch, const std::string& name) {
    std::vector<std::string> args{probe.string()};
    if (render) args.push_back("--render");
    if (!xval_cli.empty() && batch.size() == 1 && name.rfind("model_", 0) == 0)
      args.insert(args.end(), {"--keep-scene", (work / "scenes" / (name + ".json")).string()});
    for (const auto& f : batch) args.push_back(f.string());
    const fs::path log = work / (name + ".log");
    const xval::ProcessResult r = xval::runProcess(args, work, log, timeout);
    const std::string out = readAll(log);
    std::istringstream in(out);
    std::string line;
    size_t answered = 0;
    while (std::getline(in, line)) {
      const size_t k = answered;
      if (line.rfind("loaded ", 0) == 0 || line.rfind("refused ", 0) == 0) {
        ++answered;
        const bool names_file = k < batch.size() && line.find(batch[k].string()) != std::string::npos;
        if (!names_file) ++bad, lines << "BAD (message does not name the file) ";
        const bool rendered = line.find("; rendered: ") != std::string::npos;
        if (render && line[0] == 'l' && !rendered && k < batch.size() && isModelFile(batch[k]))
          ++bad, lines << "BAD (loaded but not rendered) ";
        (line[0] == 'l' ? loaded : refused) += 1;
        if (batch.size() == 1) lines << "[" << r.seconds << " s] ";
        lines << line << "\n";
      } else if (line.rfind("escaped ", 0) == 0) {
        ++answered, ++bad;
        lines << "BAD " << line << "\n";
      }
    }
    if (!r.ok() || answered != batch.size()) {
      ++bad;
      lines << "BAD " << (batch.size() == 1 ? batch[0].string() : name) << ": probe " << r.describe() << "; "
            << answered << " of " << batch.size() << " answered\n"
            << xval::tailOfFile(log) << "\n";
    }
  };
  if (!xval_cli.empty()) fs::create_directories(work / "scenes");
  for (size_t k = 0; k < models.size(); ++k) run({models[k]}, "model_" + std::to_string(k));
  if (!others.empty()) run(others, "others");
  // The Blender sweep: one validate run over every kept scene.
  int b_ok = 0, b_refused = 0, b_bad = 0;
  if (!xval_cli.empty()) {
    std::vector<size_t> swept;
    for (size_t k = 0; k < models.size(); ++k)
      if (fs::exists(work / "scenes" / ("model_" + std::to_string(k) + ".json"), ec)) swept.push_back(k);
    const fs::path out = work / "validate", log = work / "validate.log";
    if (!swept.empty()) {
      const xval::ProcessResult r =
          xval::runProcess({xval_cli.string(), "validate", (work / "scenes").string(), "--renderers",
                            "reference,blender", "-o", out.string()},
                           work, log, timeout * double(swept.size()));
      // Exit 0 or 1 (pairs compared, pass or fail); anything else is looked
      // at per record below, and a crash or time-out is a failure itself.
      const bool exited = r.started && !r.timed_out && r.signal == 0;
      if (!(exited && r.exit_code >= 0 && r.exit_code <= 2))
        ++bad, lines << "BAD blender sweep: xval validate " << r.describe() << "\n" << xval::tailOfFile(log) << "\n";
    }
    for (size_t k : swept) {
      const std::string name = "model_" + std::to_string(k);
      const fs::path rec = out / name / "blender.job.json";
      std::string outcome;
      try {
        const auto j = nlohmann::json::parse(readAll(rec));
        if (j.contains("error")) outcome = "BAD blender ERROR " + j["error"].get<std::string>();
        else if (j.contains("not_expressible"))
          outcome = "blender not expressible: " + j["not_expressible"].get<std::string>();
        else outcome = "blender ok";
      } catch (const std::exception& e) {
        outcome = "BAD blender: no readable record " + rec.string() + " (" + e.what() + ")";
      }
      if (outcome.rfind("BAD", 0) == 0) {
        ++bad, ++b_bad;
        outcome += "\n" + xval::tailOfFile(log);
      } else {
        (outcome == "blender ok" ? b_ok : b_refused) += 1;
      }
      lines << outcome.substr(0, outcome.find('\n')) << " [" << models[k].string() << "]"
            << (outcome.find('\n') != std::string::npos ? outcome.substr(outcome.find('\n')) : "") << "\n";
    }
  }
  std::ostringstream summary;
  summary << "xval_model_corpus: " << models.size() << " model files (" << loaded << " loaded, "
          << refused - (int)others.size() << " refused), " << others.size()
          << " other files refused by extension; " << bad << " failures\n";
  if (!xval_cli.empty())
    summary << "xval_model_corpus: Blender export of the " << b_ok + b_refused + b_bad << " rendered: " << b_ok
            << " ok, " << b_refused << " not expressible, " << b_bad << " errors\n";
  std::cout << lines.str() << summary.str();
  if (!report.empty()) std::ofstream(report) << lines.str() << summary.str();
  fs::remove_all(work, ec);
  return bad == 0 ? 0 : 1;
}
