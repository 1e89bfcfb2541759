// A scene set as one archive, and the check of an unpacked one (pack/set_pack.h).
#include "pack/set_pack.h"

#include <archive.h>
#include <archive_entry.h>

#include <algorithm>
#include <ctime>
#include <fstream>
#include <memory>
#include <set>
#include <variant>

#include <nlohmann/json.hpp>

#include "files/atomic_write.h"
#include "files/scratch_folder.h"
#include "geometry/model_file.h"
#include "files/sha256.h"
#include "golden/golden_set.h"
#include "process/run_process.h"
#include "renderers/renderer.h"
#include "scene/json_reader.h"
#include "scene_file/scene_loader.h"
#include "scene_file/scene_set.h"
#include "validate/common/provenance.h"
#include "validate/tolerances.h"

namespace xval::pack {

namespace fs = std::filesystem;
using J = nlohmann::ordered_json;

namespace {

// What is wrong with a relative path as a name inside the archive ("" when
// nothing): empty, absolute, a "." or ".." component, a backslash (another
// tool's separator) or a control character.
std::string nameProblem(const std::string& rel) {
  if (rel.empty()) return "an empty path";
  if (rel.front() == '/') return "an absolute path";
  if (rel.find('\\') != std::string::npos) return "a backslash in the path (a separator to other tools)";
  for (unsigned char c : rel)
    if (c < 0x20 || c == 0x7f) return "a control character in the path";
  size_t start = 0;
  while (start <= rel.size()) {
    const size_t end = std::min(rel.find('/', start), rel.size());
    const std::string part = rel.substr(start, end - start);
    if (part.empty() || part == "." || part == "..") return "a path component \"" + part + "\"";
    start = end + 1;
  }
  return "";
}

// The set's folder, as given (absolute, lexically normal) and as it really
// is (symbolic links resolved).
struct SetRoot {
  fs::path lexical, real;
};

bool below(const fs::path& p, const fs::path& folder) {
  const auto [end, _] = std::mismatch(folder.begin(), folder.end(), p.begin(), p.end());
  return end == folder.end();
}

// `file`'s path relative to the set, after the checks of set_pack.h;
// `what` says who refers to it ("scenes/x.json: objects[0].path").
std::string inSet(const SetRoot& root, const fs::path& file, const std::string& what) {
  const fs::path abs = fs::absolute(file).lexically_normal();
  if (!below(abs, root.lexical))
    throw PackError(what + ": " + abs.string() + " is outside the set folder " + root.lexical.string() +
                    "; xval pack packs only files inside the set (copy it into the set and refer to it "
                    "from there)");
  std::error_code ec;
  const fs::path real = fs::canonical(abs, ec);
  if (ec) throw PackError(what + ": " + abs.string() + ": " + ec.message());
  if (!below(real, root.real))
    throw PackError(what + ": " + abs.string() + " is a symbolic link (or lies below one) resolving to " +
                    real.string() + ", outside the set folder " + root.lexical.string());
  if (!fs::is_regular_file(real)) throw PackError(what + ": " + abs.string() + ": not a regular file");
  const std::string rel = abs.lexically_relative(root.lexical).generic_string();
  if (const std::string p = nameProblem(rel); !p.empty())
    throw PackError(what + ": " + abs.string() + ": cannot be packed: " + p);
  return rel;
}

// Every "path" a scene file writes as an absolute path: refused, since the
// set's copy elsewhere would not find it.
void refuseAbsoluteReferences(const J& j, const std::string& where, const std::string& file) {
  if (j.is_object()) {
    for (const auto& [key, value] : j.items()) {
      const std::string here = where.empty() ? key : where + "." + key;
      if (key == "path" && value.is_string() && fs::path(value.get<std::string>()).is_absolute())
        throw PackError(file + ": " + here + ": \"" + value.get<std::string>() +
                        "\" is an absolute path; a packed set refers to its files relative to the scene file");
      refuseAbsoluteReferences(value, here, file);
    }
  } else if (j.is_array()) {
    for (size_t k = 0; k < j.size(); ++k) refuseAbsoluteReferences(j[k], where + "[" + std::to_string(k) + "]", file);
  }
}

class FileList {
 public:
  void add(SetFile f) {
    if (seen_.insert(f.path).second) files_.push_back(std::move(f));
  }
  std::vector<SetFile> take() { return std::move(files_); }

 private:
  std::vector<SetFile> files_;
  std::set<std::string> seen_;
};

// The files a loaded scene refers to.
void addSceneReferences(const SetRoot& root, const Scene& scene, const std::string& scene_rel, FileList& out) {
  auto texture = [&](const std::optional<TextureSpec>& t, const std::string& field) {
    if (t && t->source == TextureSpec::Source::Image)
      out.add({inSet(root, t->path, scene_rel + ": " + field), t->path, "texture"});
  };
  texture(scene.material.texture, "material.texture.path");
  for (size_t k = 0; k < scene.objects.size(); ++k) {
    const SceneObject& o = scene.objects[k];
    const std::string field = "objects[" + std::to_string(k) + "]";
    if (o.material) texture(o.material->texture, field + ".material.texture.path");
    const auto* m = std::get_if<MeshFile>(&o.shape);
    if (!m) continue;
    const std::string model_rel = inSet(root, m->path, scene_rel + ": " + field + ".path");
    out.add({model_rel, m->path, "model"});
    // The files the model is made of, at their place relative to the
    // model file (where its loader looks for them).
    const fs::path real_folder = m->model->file.parent_path();
    const fs::path lexical_folder = (root.lexical / model_rel).parent_path();
    for (size_t i = 1; i < m->model->files.size(); ++i) {
      const fs::path& dep = m->model->files[i];
      const fs::path as_used = lexical_folder / dep.lexically_relative(real_folder);
      out.add({inSet(root, as_used, scene_rel + ": " + field + ".path: " + model_rel + " refers to it"), as_used,
               "model"});
    }
  }
}

std::string utcNow() {
  const std::time_t t = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

using ArchivePtr = std::unique_ptr<struct archive, decltype(&archive_write_free)>;
using EntryPtr = std::unique_ptr<struct archive_entry, decltype(&archive_entry_free)>;

void writeHeader(struct archive* a, const std::string& name, long long size, std::time_t mtime,
                 const fs::path& archive_file) {
  EntryPtr e(archive_entry_new(), &archive_entry_free);
  archive_entry_set_pathname(e.get(), name.c_str());
  archive_entry_set_filetype(e.get(), AE_IFREG);
  archive_entry_set_perm(e.get(), 0644);
  archive_entry_set_size(e.get(), la_int64_t(size));
  archive_entry_set_mtime(e.get(), mtime, 0);
  if (archive_write_header(a, e.get()) != ARCHIVE_OK)
    throw PackError(archive_file.string() + ": " + name + ": cannot write the tar header: " + archive_error_string(a));
}

void writeData(struct archive* a, const char* data, size_t n, const std::string& name, const fs::path& archive_file) {
  if (archive_write_data(a, data, n) != la_ssize_t(n))
    throw PackError(archive_file.string() + ": " + name + ": cannot write: " +
                    (archive_error_string(a) ? archive_error_string(a) : "short write"));
}

}  // namespace

std::vector<SetFile> setFiles(const fs::path& set) {
  std::error_code ec;
  SetRoot root{fs::absolute(set).lexically_normal(), {}};
  if (!root.lexical.has_filename()) root.lexical = root.lexical.parent_path();  // "ref/" -> "ref"
  root.real = fs::canonical(root.lexical, ec);
  if (ec || !fs::is_directory(root.real))
    throw PackError(set.string() + ": not a folder (expected a scene set: a folder holding scenes/)");
  const fs::path scenes = root.lexical / "scenes";
  if (!fs::is_directory(scenes))
    throw PackError(set.string() + ": has no scenes/ folder (expected a scene set: SET/scenes/*.json)");
  // The scenes folder's files as validate finds them (scene_file/scene_set.h);
  // each is checked to lie in the set before it is read.
  std::vector<fs::path> jsons;
  try {
    jsons = jsonFilesOf({scenes.string()});
  } catch (const std::runtime_error& e) {
    throw PackError(e.what());
  }
  if (jsons.empty()) throw PackError(scenes.string() + ": no *.json files");

  FileList out;
  std::vector<fs::path> scene_files;
  for (const fs::path& f : jsons) {
    const std::string rel = inSet(root, f, scenes.string());
    if (const std::string why = nonSceneReason(f); !why.empty()) {
      out.add({rel, f, "file"});
      continue;
    }
    refuseAbsoluteReferences(parseOrderedJsonText(readJsonFile(f, "scene file"), f.string()), "", rel);
    const Scene scene = loadScene(f);
    out.add({rel, f, "scene"});
    addSceneReferences(root, scene, rel, out);
    scene_files.push_back(f);
  }
  if (scene_files.empty()) throw PackError(scenes.string() + ": no scene files (only files validate skips)");

  // The tolerance file the scenes find; one from outside the set goes to
  // SET/tolerances.json, where the unpacked scenes find it (no nearer one
  // exists, or the rule would have found that).
  const ToleranceFile tol = findToleranceFile({}, scene_files);
  if (below(tol.path, root.lexical))
    out.add({inSet(root, tol.path, "the tolerance file (" + tol.found_by + ")"), tol.path, "tolerances"});
  else
    out.add({"tolerances.json", tol.path, "tolerances"});

  // The golden sets beside the scenes folder.
  const fs::path golden = root.lexical / "golden";
  if (fs::is_directory(golden)) {
    std::vector<fs::path> folders;
    for (const auto& e : fs::directory_iterator(golden))
      if (e.is_directory()) folders.push_back(e.path());
    std::sort(folders.begin(), folders.end());
    for (const fs::path& folder : folders) {
      const fs::path manifest_file = folder / "manifest.json";
      if (!fs::exists(manifest_file)) continue;
      const std::string manifest_rel = inSet(root, manifest_file, "golden set " + folder.string());
      golden::Manifest m;
      try {
        m = golden::readManifest(folder, folder.filename().string());
      } catch (const std::exception& e) {
        throw PackError(std::string("golden set: ") + e.what());
      }
      out.add({manifest_rel, manifest_file, "golden manifest"});
      for (const auto& [stem, entry] : m.entries) {
        const fs::path image = folder / entry.image;
        if (!fs::exists(fs::symlink_status(image)))
          throw PackError(manifest_file.string() + ": entries." + stem + ".image: " + image.string() +
                          " is missing (xval golden update " + (scenes / (stem + ".json")).string() + " --renderer " +
                          m.renderer + " stores it again)");
        out.add({inSet(root, image, manifest_file.string() + ": entries." + stem + ".image"), image, "golden image"});
      }
    }
  }
  return out.take();
}

PackSummary packSet(const fs::path& set, const fs::path& archive_file,
                    const std::function<void(const Progress&)>& progress) {
  const std::string name = archive_file.filename().string();
  if (name.size() <= 7 || name.substr(name.size() - 7) != ".tar.gz")
    throw PackError(archive_file.string() + ": expected a file name ending in .tar.gz");
  const std::vector<SetFile> files = setFiles(set);
  PackSummary summary;
  fs::path lexical = fs::absolute(set).lexically_normal();
  if (!lexical.has_filename()) lexical = lexical.parent_path();
  summary.top = lexical.filename().string();
  if (const std::string p = nameProblem(summary.top); !p.empty())
    throw PackError(set.string() + ": the set folder's name cannot name the archive's top folder: " + p);
  const fs::path out_abs = fs::absolute(archive_file).lexically_normal();
  for (const SetFile& f : files)
    if (fs::absolute(f.source).lexically_normal() == out_abs)
      throw PackError(archive_file.string() + ": is a file of the set (" + f.path + ")");
  Progress p;
  p.n = files.size();
  for (const SetFile& f : files) p.bytes_total += (long long)fs::file_size(f.source);

  Provenance prov;
  {
    const ScratchFolder scratch("pack-git");
    prov = collectProvenance(scratch.dir() / "git.log");
  }
  const std::time_t mtime = std::time(nullptr);
  J manifest;
  manifest["format"] = kManifestFormat;
  manifest["about"] = "The files of a scene set packed by xval pack, relative to this file's folder; "
                      "`xval pack --verify THIS_FOLDER` checks them";
  manifest["set"] = summary.top;
  manifest["xval_version"] = renderers::kXvalVersion;
  manifest["git_commit"] = prov.git_commit;
  manifest["date_utc"] = prov.date_utc.empty() ? utcNow() : prov.date_utc;
  manifest["files"] = J::array();

  if (archive_file.has_parent_path()) fs::create_directories(archive_file.parent_path());
  writeFileAtomically(archive_file, [&](const fs::path& tmp) {
    ArchivePtr a(archive_write_new(), &archive_write_free);
    if (!a) throw PackError("libarchive: cannot create a writer");
    if (archive_write_add_filter_gzip(a.get()) != ARCHIVE_OK ||
        archive_write_set_format_pax_restricted(a.get()) != ARCHIVE_OK ||
        archive_write_open_filename(a.get(), tmp.c_str()) != ARCHIVE_OK)
      throw PackError(archive_file.string() + ": cannot open for writing: " + archive_error_string(a.get()));
    std::vector<char> buf(1 << 16);
    for (const SetFile& f : files) {
      ++p.k;
      p.file = &f;
      if (progress) progress(p);
      const std::string entry = summary.top + "/" + f.path;
      std::ifstream in(f.source, std::ios::binary);
      if (!in) throw PackError(f.source.string() + ": cannot read");
      const long long size = (long long)fs::file_size(f.source);
      writeHeader(a.get(), entry, size, mtime, archive_file);
      long long done = 0;
      const std::string sha = sha256Pieces([&](const auto& update) {
        while (in.read(buf.data(), std::streamsize(buf.size())) || in.gcount() > 0) {
          const size_t n = size_t(in.gcount());
          if (done + (long long)n > size) break;
          update(buf.data(), n);
          writeData(a.get(), buf.data(), n, entry, archive_file);
          done += (long long)n;
        }
      });
      if (in.bad() || done != size)
        throw PackError(f.source.string() + ": changed while it was packed (" + std::to_string(size) +
                        " bytes when it was listed, " + (done > size ? "more" : std::to_string(done)) + " read)");
      p.bytes_done += size;
      manifest["files"].push_back({{"path", f.path}, {"role", f.role}, {"size", size}, {"sha256", sha}});
      summary.bytes += size;
    }
    const std::string text = manifest.dump(2) + "\n";
    writeHeader(a.get(), summary.top + "/" + kManifestName, (long long)text.size(), mtime, archive_file);
    writeData(a.get(), text.data(), text.size(), kManifestName, archive_file);
    if (archive_write_close(a.get()) != ARCHIVE_OK)
      throw PackError(archive_file.string() + ": cannot finish the archive: " + archive_error_string(a.get()));
    return true;
  });
  summary.files = files.size();
  return summary;
}

std::vector<std::string> verifyUnpacked(const fs::path& dir) {
  const fs::path file = dir / kManifestName;
  if (!fs::is_regular_file(fs::symlink_status(file)))
    throw PackError(file.string() + ": no pack manifest (expected the folder an xval pack archive unpacked into, "
                    "holding " + kManifestName + ")");
  const J j = parseOrderedJsonText(readJsonFile(file, "pack manifest"), file.string());
  if (!j.is_object() || !j.contains("format") || j["format"] != kManifestFormat)
    throw PackError(file.string() + ": format: expected \"" + kManifestFormat + "\"");
  if (!j.contains("files") || !j["files"].is_array()) throw PackError(file.string() + ": files: expected an array");
  std::vector<std::string> problems;
  std::set<std::string> listed;
  for (size_t k = 0; k < j["files"].size(); ++k) {
    const J& e = j["files"][k];
    const std::string where = file.string() + ": files[" + std::to_string(k) + "]";
    if (!e.is_object() || !e.contains("path") || !e["path"].is_string() || !e.contains("sha256") ||
        !e["sha256"].is_string() || !e.contains("size") || !e["size"].is_number_unsigned())
      throw PackError(where + ": expected {\"path\": string, \"sha256\": string, \"size\": non-negative integer}");
    const std::string rel = e["path"].get<std::string>();
    if (const std::string p = nameProblem(rel); !p.empty())
      throw PackError(where + ".path: \"" + rel + "\": " + p + " (a packed path stays inside the set)");
    if (rel == kManifestName || !listed.insert(rel).second)
      throw PackError(where + ".path: \"" + rel + "\": listed twice");
    const fs::path f = dir / rel;
    const fs::file_status st = fs::symlink_status(f);
    if (!fs::exists(st)) {
      problems.push_back(f.string() + ": missing");
      continue;
    }
    if (!fs::is_regular_file(st)) {
      problems.push_back(f.string() + ": not a regular file" + (fs::is_symlink(st) ? " (a symbolic link)" : ""));
      continue;
    }
    // Sizes first: a file of another size has changed, and is not read (a
    // sparse file of terabytes in place of a small texture is answered at
    // once); one of the packed size is hashed, reading no more than that.
    const auto size = (unsigned long long)fs::file_size(f);
    const auto want_size = e["size"].get<unsigned long long>();
    const std::string want = e["sha256"].get<std::string>();
    if (size != want_size) {
      problems.push_back(f.string() + ": changed (" + std::to_string(size) + " bytes; packed: " +
                         std::to_string(want_size) + " bytes, SHA-256 " + want + ")");
      continue;
    }
    std::string sha;
    try {
      sha = sha256File(f, want_size);
    } catch (const std::runtime_error& err) {
      problems.push_back(err.what());
      continue;
    }
    if (sha != want)
      problems.push_back(f.string() + ": changed (" + std::to_string(size) + " bytes, SHA-256 " + sha +
                         "; packed: " + std::to_string(want_size) + " bytes, " + want + ")");
  }
  for (auto it = fs::recursive_directory_iterator(dir); it != fs::recursive_directory_iterator(); ++it) {
    if (fs::is_directory(it->symlink_status())) continue;
    const std::string rel = it->path().lexically_relative(dir).generic_string();
    if (rel != kManifestName && !listed.count(rel))
      problems.push_back(it->path().string() + ": not in the pack manifest (not part of the packed set)");
  }
  std::sort(problems.begin(), problems.end());
  return problems;
}

}  // namespace xval::pack
