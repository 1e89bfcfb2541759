// xval pack SET -o FILE.tar.gz | xval pack --verify DIR: argument parsing;
// the work is pack/set_pack.h.
//
// Exit: 0 packed / every file as packed; 1 (--verify) some file missing,
// changed or not in the manifest (each printed by name); 2 an error (a
// refused set, a file that cannot be read or written, a malformed
// manifest).
#include <cstdio>
#include <memory>

#include "cli/cli_common.h"
#include "cli/commands.h"
#include "pack/set_pack.h"

namespace xval::cli {

void addPackCommand(CLI::App& app, std::function<int()>& run) {
  struct Args {
    std::string set, output, verify;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "pack",
      "Pack a scene set into one .tar.gz (docs/pack.md): the scene files of SET/scenes, the textures and "
      "model files they refer to (with the files a model file refers to: an OBJ's mtl and images, a glTF's "
      "buffers), the tolerance file the scenes find, the golden images of SET/golden, and pack-manifest.json "
      "(every file's SHA-256 and size, the xval version, git commit and date). The archive's top folder is "
      "named like SET; unpacked anywhere, `xval validate DIR/scenes -o OUT` uses its tolerances and golden images. "
      "A file outside SET (or a symbolic link resolving outside it, an absolute reference, a backslash in a "
      "path) is refused, naming the scene and the field. The archive is written under a temporary name and "
      "renamed when whole.\n"
      "--verify DIR checks an unpacked set against its pack-manifest.json and names every file that is "
      "missing, changed or not in the manifest.\n"
      "Exit 0 packed / all files as packed, 1 (--verify) some file is not, 2 on an error.");
  auto* set = cmd->add_option("set", args->set, "The scene set: a folder holding scenes/*.json (e.g. reference)");
  auto* out = cmd->add_option("-o,--output", args->output, "The archive to write, FILE.tar.gz");
  auto* verify = cmd->add_option("--verify", args->verify,
                                 "Check the unpacked set DIR (the folder holding pack-manifest.json) instead");
  set->needs(out);
  out->needs(set);
  verify->excludes(set)->excludes(out);
  cmd->callback([args, &run]() {
    run = [args]() -> int {
      try {
        if (!args->verify.empty()) {
          const std::vector<std::string> problems = pack::verifyUnpacked(args->verify);
          for (const std::string& p : problems) std::printf("FAIL %s\n", p.c_str());
          std::fprintf(stderr, "xval pack --verify: %s: %s\n", args->verify.c_str(),
                       problems.empty() ? "every file as packed"
                                        : (std::to_string(problems.size()) + " file(s) not as packed").c_str());
          return problems.empty() ? 0 : 1;
        }
        if (args->set.empty()) throw std::runtime_error("expected SET -o FILE.tar.gz, or --verify DIR");
        const pack::PackSummary s = pack::packSet(args->set, args->output, [](const pack::Progress& p) {
          std::fprintf(stderr, "xval pack: [%zu/%zu] %.1f of %.1f MB: %s (%s)\n", p.k, p.n, p.bytes_done / 1e6,
                       p.bytes_total / 1e6, p.file->path.c_str(), p.file->role.c_str());
        });
        std::fprintf(stderr, "xval pack: wrote %s: %zu files, %.1f MB uncompressed, top folder %s/\n",
                     args->output.c_str(), s.files, s.bytes / 1e6, s.top.c_str());
        return 0;
      } catch (const std::exception& e) {
        std::fprintf(stderr, "xval pack: error: %s\n", e.what());
        return 2;
      }
    };
  });
}

}  // namespace xval::cli
