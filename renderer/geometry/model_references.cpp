// The files a model names and the rule for opening them (model_references.h).
#include "geometry/model_references.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <iterator>
#include <sstream>

#include <nlohmann/json.hpp>

#include "scene/json_reader.h"

namespace xval {

namespace fs = std::filesystem;

ResolvedName resolveInsideFolder(const fs::path& folder, const std::string& name) {
  ResolvedName r;
  std::string fixed = name;
  std::replace(fixed.begin(), fixed.end(), '\\', '/');
  fs::path p(fixed);
  if (p.is_relative()) p = folder / p;
  std::error_code ec;
  r.real = fs::weakly_canonical(p, ec);
  if (ec) {
    r.why = name + ": " + ec.message();
    return r;
  }
  auto [end, _] = std::mismatch(folder.begin(), folder.end(), r.real.begin(), r.real.end());
  if (end != folder.end()) {
    r.kind = NameResolution::Outside;
    r.why = name + ": resolves to " + r.real.string() + ", outside the model's folder " + folder.string();
    return r;
  }
  if (fs::is_regular_file(r.real, ec)) {
    r.kind = NameResolution::RegularFile;
    return r;
  }
  const bool exists = fs::exists(fs::symlink_status(r.real, ec));
  r.kind = exists ? NameResolution::NotRegularFile : NameResolution::NoSuchFile;
  r.why = name + ": " + (exists ? "not a regular file" : "no such file");
  return r;
}

namespace {

std::string lower(std::string s) {
  for (auto& c : s) c = char(std::tolower((unsigned char)c));
  return s;
}

std::string readAll(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

uint32_t le32(const std::string& s, size_t at) {
  return uint32_t((unsigned char)s[at]) | uint32_t((unsigned char)s[at + 1]) << 8 |
         uint32_t((unsigned char)s[at + 2]) << 16 | uint32_t((unsigned char)s[at + 3]) << 24;
}

// The JSON of a .gltf, or the first chunk of a .glb; empty if there is none.
std::string gltfJsonText(const fs::path& file, bool glb) {
  const std::string bytes = readAll(file);
  if (!glb) return bytes;
  if (bytes.size() < 20 || bytes.compare(0, 4, "glTF") != 0 || le32(bytes, 16) != 0x4E4F534Au) return "";
  return bytes.substr(20, std::min<size_t>(le32(bytes, 12), bytes.size() - 20));
}

// Every string member named "uri" below `j`, with its JSON path.
void urisIn(const nlohmann::json& j, const std::string& at, const fs::path& file, std::vector<ModelReference>& out) {
  if (j.is_object()) {
    for (auto it = j.begin(); it != j.end(); ++it) {
      const std::string field = at.empty() ? it.key() : at + "." + it.key();
      if (it.key() == "uri" && it->is_string()) out.push_back({file, field, it->get<std::string>()});
      else urisIn(*it, field, file, out);
    }
  } else if (j.is_array()) {
    for (size_t k = 0; k < j.size(); ++k) urisIn(j[k], at + "[" + std::to_string(k) + "]", file, out);
  }
}

// The rest of the line after its keyword, trimmed, then each word of it.
std::vector<std::string> lineNames(const std::string& rest) {
  std::vector<std::string> names;
  const size_t b = rest.find_first_not_of(" \t");
  if (b == std::string::npos) return names;
  const size_t e = rest.find_last_not_of(" \t\r");
  names.push_back(rest.substr(b, e - b + 1));
  std::istringstream words(names.front());
  for (std::string w; words >> w;)
    if (w != names.front()) names.push_back(w);
  return names;
}

// (keyword, names) of each line of an OBJ or MTL text whose keyword `keep` accepts.
template <class Keep>
void namedLines(const fs::path& file, Keep keep, std::vector<ModelReference>& out) {
  std::istringstream in(readAll(file));
  for (std::string line; std::getline(in, line);) {
    std::istringstream w(line);
    std::string key;
    w >> key;
    if (key.empty() || !keep(lower(key))) continue;
    std::string rest;
    std::getline(w, rest);
    for (const std::string& n : lineNames(rest)) out.push_back({file, key, n});
  }
}

bool isMapKeyword(const std::string& k) {
  return k.rfind("map_", 0) == 0 || k == "bump" || k == "disp" || k == "decal" || k == "refl" || k == "norm";
}

// "%41" -> "A"; a malformed escape is kept as written.
std::string percentDecoded(const std::string& s) {
  std::string out;
  for (size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '%' && i + 2 < s.size() && std::isxdigit((unsigned char)s[i + 1]) &&
        std::isxdigit((unsigned char)s[i + 2])) {
      out.push_back(char(std::stoi(s.substr(i + 1, 2), nullptr, 16)));
      i += 2;
    } else {
      out.push_back(s[i]);
    }
  }
  return out;
}

// The scheme of a URI ("file", "http"), empty for a relative reference.
std::string uriScheme(const std::string& s) {
  if (s.empty() || !std::isalpha((unsigned char)s[0])) return "";
  const size_t colon = s.find(':');
  if (colon == std::string::npos) return "";
  for (size_t i = 1; i < colon; ++i)
    if (!std::isalnum((unsigned char)s[i]) && s[i] != '+' && s[i] != '-' && s[i] != '.') return "";
  return lower(s.substr(0, colon));
}

}  // namespace

std::vector<ModelReference> modelReferences(const fs::path& model) {
  std::vector<ModelReference> out;
  const std::string ext = lower(model.extension().string());
  if (ext == ".gltf" || ext == ".glb") {
    try {
      urisIn(parseJsonText(gltfJsonText(model, ext == ".glb"), model.string() + ": glTF JSON"), "", model, out);
    } catch (const std::exception&) {
      // Not JSON: the loader refuses the file itself.
    }
  } else if (ext == ".obj") {
    namedLines(model, [](const std::string& k) { return k == "mtllib"; }, out);
    const size_t mtllibs = out.size();
    for (size_t i = 0; i < mtllibs; ++i) {
      const ResolvedName mtl = resolveInsideFolder(model.parent_path(), out[i].value);
      if (mtl.kind == NameResolution::RegularFile) namedLines(mtl.real, isMapKeyword, out);
    }
  }
  return out;
}

std::string refusedModelReference(const fs::path& model) {
  const fs::path folder = model.parent_path();
  const std::string ext = lower(model.extension().string());
  const bool gltf = ext == ".gltf" || ext == ".glb";
  for (const ModelReference& r : modelReferences(model)) {
    const std::string at = r.file.string() + ": " + r.field + ": '" + r.value + "': ";
    if (gltf) {
      const std::string scheme = uriScheme(r.value);
      if (scheme == "data") continue;
      if (!scheme.empty())
        return at + "a URL (scheme '" + scheme + "'), not a file name in the model's folder " + folder.string();
    }
    std::vector<std::string> names{r.value};
    if (gltf && percentDecoded(r.value) != r.value) names.push_back(percentDecoded(r.value));
    std::vector<fs::path> bases{folder};
    if (r.file != model && r.file.parent_path() != folder) bases.insert(bases.begin(), r.file.parent_path());
    for (const std::string& name : names)
      for (const fs::path& base : bases) {
        // Relative to the material file's folder: the name as a path from
        // the model's folder, so the rule's folder stays the model's.
        const std::string from_folder =
            base == folder || fs::path(name).is_absolute() ? name : (fs::relative(base, folder) / name).string();
        const ResolvedName n = resolveInsideFolder(folder, from_folder);
        if (n.kind != NameResolution::RegularFile && n.kind != NameResolution::NoSuchFile) return at + n.why;
      }
  }
  return "";
}

}  // namespace xval
