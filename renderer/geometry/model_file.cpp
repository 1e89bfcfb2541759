// Model files through Assimp (model_file.h states the rules).
#include "geometry/model_file.h"

#include <assimp/BaseImporter.h>
#include <assimp/DefaultIOSystem.h>
#include <assimp/Importer.hpp>
#include <assimp/ai_assert.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <nlohmann/json.hpp>

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <sstream>
#include <string_view>

#include "geometry/assimp_dump.h"
#include "geometry/assimp_read.h"
#include "geometry/degenerate_triangles.h"
#include "geometry/model_references.h"
#include "geometry/transform.h"
#include "process/run_process.h"
#include "scene/json_reader.h"


namespace xval {

namespace fs = std::filesystem;

namespace {

std::string num(double v) {
  std::ostringstream o;
  o.precision(9);
  o << v;
  return o.str();
}
std::string vec(double x, double y, double z) { return "(" + num(x) + ", " + num(y) + ", " + num(z) + ")"; }

std::string lower(std::string s) {
  for (auto& c : s) c = char(std::tolower((unsigned char)c));
  return s;
}


// --- checks before Assimp reads -----------------------------------------

std::string readPrefix(const fs::path& file, size_t n) {
  std::ifstream in(file, std::ios::binary);
  std::string s(n, '\0');
  in.read(s.data(), std::streamsize(n));
  s.resize(size_t(in.gcount()));
  return s;
}

// A PLY header's element counts against the bytes the file has: Assimp
// reserves per element before reading it. Each element instance takes at
// least: binary, the sum of its scalar sizes and list-count sizes; ASCII, two
// bytes per property ("0 "). A header that does not parse is left to
// Assimp, which refuses it.
void checkPlyHeader(const fs::path& file, long long file_size, const ModelLimits& limits) {
  const std::string head = readPrefix(file, 1 << 16);
  std::istringstream in(head);
  std::string line;
  if (!std::getline(in, line) || line.rfind("ply", 0) != 0) return;  // Assimp refuses it: no magic
  bool binary = false;
  struct Element { std::string name; unsigned long long count; unsigned long long min_bytes; };
  std::vector<Element> elements;
  auto size_of = [](const std::string& t) -> int {
    if (t == "char" || t == "uchar" || t == "int8" || t == "uint8") return 1;
    if (t == "short" || t == "ushort" || t == "int16" || t == "uint16") return 2;
    if (t == "int" || t == "uint" || t == "float" || t == "int32" || t == "uint32" || t == "float32") return 4;
    if (t == "double" || t == "float64") return 8;
    return 0;
  };
  bool ended = false;
  while (std::getline(in, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    std::istringstream w(line);
    std::string key;
    w >> key;
    if (key == "format") {
      std::string f;
      w >> f;
      binary = f.rfind("binary", 0) == 0;
    } else if (key == "element") {
      std::string name, count;
      w >> name >> count;
      if (count.empty() || count.find_first_not_of("0123456789") != std::string::npos)
        throw ModelFileError(file.string() + ": PLY header: element '" + name + "' count '" + count +
                             "' is not a number");
      errno = 0;
      unsigned long long c = std::strtoull(count.c_str(), nullptr, 10);
      if (errno == ERANGE) c = ~0ull;
      elements.push_back({name, c, 0});
    } else if (key == "property" && !elements.empty()) {
      std::string t;
      w >> t;
      if (t == "list") {  // the count's type (at least that many bytes), then the items'
        std::string item;
        w >> t >> item;
        if (!size_of(item))
          throw ModelFileError(file.string() + ": PLY header: unknown property type '" + item + "'");
      }
      if (!size_of(t)) throw ModelFileError(file.string() + ": PLY header: unknown property type '" + t + "'");
      elements.back().min_bytes += binary ? size_of(t) : 2;
    } else if (key == "end_header") {
      ended = true;
      break;
    } else if (!key.empty() && key != "comment" && key != "obj_info") {
      // Assimp 5.2.5 loops for ever on some malformed headers (an
      // end_header that is not on a line of its own). A line of other
      // printable text is skipped, as Assimp does (Blender 2.47 wrote its
      // comment without the keyword: the corpus's Wuson.ply); one with a
      // control byte or a buried end_header is refused.
      const bool control = std::any_of(line.begin(), line.end(), [](char c) {
        return (unsigned char)c < 0x20 && c != '\t';
      });
      if (control || line.find("end_header") != std::string::npos)
        throw ModelFileError(file.string() + ": PLY header: malformed line '" + line.substr(0, 40) + "'");
    }
  }
  if (!ended)
    throw ModelFileError(file.string() + ": PLY header: no 'end_header' line in the first " +
                         std::to_string(head.size()) + " bytes");
  const auto data_at = (size_t)in.tellg();
  // Assimp 5.2 skips a 0x0A byte right after "end_header\n" as one more line
  // end, and then reads every value of a binary file one byte late (a float
  // x = 1.28 begins with it): refused rather than read wrong.
  if (binary && data_at < head.size() && head[data_at] == '\n')
    throw ModelFileError(file.string() + ": PLY binary data begins with byte 0x0A, which Assimp 5.2 takes for a "
                         "line end (every value after it would be read shifted by one byte); refused");
  const long long body = file_size - (long long)data_at;
  long double need = 0;
  const long long max_count = std::max(limits.max_vertices, limits.max_triangles);
  for (const auto& e : elements) {
    if ((long long)std::min<unsigned long long>(e.count, ~0ull >> 1) > max_count)
      throw ModelFileError(file.string() + ": PLY header: element '" + e.name + "' count " +
                           std::to_string(e.count) + " exceeds the limit " + std::to_string(max_count));
    need += (long double)e.count * (long double)e.min_bytes;
  }
  if (need > (long double)body)
    throw ModelFileError(file.string() + ": PLY header: its element counts need at least " +
                         std::to_string((long long)need) + " bytes, the file has " + std::to_string(body) +
                         " after the header (truncated, or the counts are wrong)");
}

// An OFF header's counts ("OFF", then vertices, faces, edges) against the
// file: Assimp reserves for them before reading. Each vertex takes at
// least 6 bytes ("0 0 0\n"), each face 8 ("3 0 1 2\n").
void checkOffHeader(const fs::path& file, long long file_size, const ModelLimits& limits) {
  std::istringstream in(readPrefix(file, 4096));
  std::string tok;
  while (in >> tok && tok[0] == '#') std::getline(in, tok);
  if (tok.find("OFF") == std::string::npos) return;
  unsigned long long nv = 0, nf = 0;
  std::string a, b;
  if (!(in >> a >> b)) return;
  for (const std::string* t : {&a, &b})
    if (t->find_first_not_of("0123456789") != std::string::npos) return;
  errno = 0;
  nv = std::strtoull(a.c_str(), nullptr, 10);
  nf = std::strtoull(b.c_str(), nullptr, 10);
  if (errno == ERANGE) nv = nf = ~0ull >> 1;
  if (nv > (unsigned long long)limits.max_vertices || nf > (unsigned long long)limits.max_triangles)
    throw ModelFileError(file.string() + ": OFF header: " + a + " vertices, " + b + " faces exceed the limits " +
                         std::to_string(limits.max_vertices) + ", " + std::to_string(limits.max_triangles));
  if ((long double)nv * 6 + (long double)nf * 8 > (long double)file_size)
    throw ModelFileError(file.string() + ": OFF header: " + a + " vertices and " + b + " faces need more than the " +
                         std::to_string(file_size) + " bytes the file has");
}

// A count that stops growing at kSaturated: the counts over a node graph
// grow as 2^depth when nodes share children.
constexpr long long kSaturated = 1ll << 62;
long long satAdd(long long a, long long b) { return a >= kSaturated - b ? kSaturated : a + b; }
std::string countText(long long n) { return n >= kSaturated ? "more than 2^62" : std::to_string(n); }

// The limits on what the nodes place, with the one message each, whether
// counted over the glTF node graph before Assimp reads it or over the
// scene Assimp built.
void requirePlacedWithinLimits(const std::string& file, long long prims, long long tris, const ModelLimits& lim) {
  if (prims > lim.max_primitives)
    throw ModelFileError(file + ": " + countText(prims) + " placed meshes; the limit is " +
                         std::to_string(lim.max_primitives));
  if (tris > lim.max_triangles)
    throw ModelFileError(file + ": " + countText(tris) + " triangles (with every node's meshes); the limit is " +
                         std::to_string(lim.max_triangles));
}
ModelFileError tooManyNodes(const std::string& file, const ModelLimits& lim) {
  return ModelFileError(file + ": more than " + std::to_string(lim.max_nodes) + " nodes");
}
ModelFileError tooDeep(const std::string& file, const std::string& node, const ModelLimits& lim) {
  return ModelFileError(file + ": node '" + node + "': deeper than " + std::to_string(lim.max_node_depth) + " levels");
}

// The glTF node graph counted before Assimp expands it: Assimp copies a
// node once per path that reaches it, so 21 nodes that each name the next
// twice as a child are 2^20 copies of the last one (and its mesh), built
// in the child process before any limit of the expanded scene is checked.
// Over nodes[].children, from the roots of the scene with the most (every
// scene in scenes[]; without scenes, every node no other node names), by
// memoised sums (saturating, kSaturated): the nodes visited, the meshes
// placed (one per triangle primitive of a node's mesh) and their
// triangles, and the deepest level (Assimp adds a root above two or more
// root nodes). A cycle is refused (a node would be its own ancestor, and
// the glTF spec requires the nodes to form trees). A child index out of
// range is left to Assimp, which refuses it.
void checkGltfNodeGraph(const fs::path& file, const nlohmann::json& j, const std::vector<long long>& mesh_triangles,
                        const std::vector<long long>& mesh_placed, const ModelLimits& limits) {
  const std::string name = file.string();
  if (!j.contains("nodes") || !j["nodes"].is_array()) return;
  const nlohmann::json& nodes = j["nodes"];
  const size_t n = nodes.size();
  auto childrenOf = [&](size_t k) {
    std::vector<size_t> c;
    const auto& node = nodes[k];
    if (node.is_object() && node.contains("children") && node["children"].is_array())
      for (const auto& i : node["children"])
        if (i.is_number_unsigned() && i.get<unsigned long long>() < n) c.push_back(size_t(i.get<unsigned long long>()));
    return c;
  };
  struct Sums { long long nodes = 0, placed = 0, triangles = 0, height = 0; };
  std::vector<Sums> sums(n);
  std::vector<char> state(n, 0);  // 0 new, 1 on the path, 2 done
  for (size_t start = 0; start < n; ++start) {
    if (state[start]) continue;
    struct Frame { size_t node; std::vector<size_t> children; size_t next = 0; };
    std::vector<Frame> path;
    path.push_back({start, childrenOf(start)});
    state[start] = 1;
    while (!path.empty()) {
      Frame& f = path.back();
      if (f.next < f.children.size()) {
        const size_t c = f.children[f.next++];
        if (state[c] == 1)
          throw ModelFileError(name + ": nodes[" + std::to_string(f.node) + "].children names node " +
                               std::to_string(c) + ", which is its own ancestor (a cycle: glTF nodes form trees)");
        if (state[c] == 0) {
          state[c] = 1;
          path.push_back({c, childrenOf(c)});
        }
        continue;
      }
      Sums s;
      s.nodes = 1;
      const auto& node = nodes[f.node];
      if (node.is_object() && node.contains("mesh") && node["mesh"].is_number_unsigned() &&
          node["mesh"].get<unsigned long long>() < mesh_placed.size()) {
        const size_t m = size_t(node["mesh"].get<unsigned long long>());
        s.placed = mesh_placed[m], s.triangles = mesh_triangles[m];
      }
      for (size_t c : f.children) {
        s.nodes = satAdd(s.nodes, sums[c].nodes);
        s.placed = satAdd(s.placed, sums[c].placed);
        s.triangles = satAdd(s.triangles, sums[c].triangles);
        s.height = std::max(s.height, sums[c].height + 1);
      }
      sums[f.node] = s;
      state[f.node] = 2;
      path.pop_back();
    }
  }
  // The roots of each scene (the whole list: Assimp reads one scene).
  std::vector<std::vector<size_t>> scenes;
  if (j.contains("scenes") && j["scenes"].is_array())
    for (const auto& sc : j["scenes"]) {
      scenes.emplace_back();
      if (sc.is_object() && sc.contains("nodes") && sc["nodes"].is_array())
        for (const auto& i : sc["nodes"])
          if (i.is_number_unsigned() && i.get<unsigned long long>() < n)
            scenes.back().push_back(size_t(i.get<unsigned long long>()));
    }
  if (scenes.empty()) {
    std::vector<char> named(n, 0);
    for (size_t k = 0; k < n; ++k)
      for (size_t c : childrenOf(k)) named[c] = 1;
    scenes.emplace_back();
    for (size_t k = 0; k < n; ++k)
      if (!named[k]) scenes.back().push_back(k);
  }
  for (const auto& roots : scenes) {
    Sums all;
    const long long above = roots.size() > 1 ? 1 : 0;  // Assimp's added root
    all.nodes = above;
    for (size_t r : roots) {
      all.nodes = satAdd(all.nodes, sums[r].nodes);
      all.placed = satAdd(all.placed, sums[r].placed);
      all.triangles = satAdd(all.triangles, sums[r].triangles);
      if (sums[r].height + above > limits.max_node_depth)
        throw tooDeep(name, "nodes[" + std::to_string(r) + "] (a root)", limits);
    }
    if (all.nodes > limits.max_nodes) throw tooManyNodes(name, limits);
    requirePlacedWithinLimits(name, all.placed, all.triangles, limits);
  }
}

// glTF JSON: checks every buffer's declared byteLength (Assimp allocates it
// before reading). Returns the triangles the file's primitives declare (mode 4: count / 3,
// strips and fans 5, 6: count - 2, of the indices accessor or else of
// POSITION): Assimp's glTF reader drops a triangle whose index is out of
// range with only a warning, so the loader compares its count with this.
long long checkGltfJson(const fs::path& file, const std::string& text, long long bin_chunk, const ModelLimits& limits,
                        const GuardedIO& io) {
  // Read as every JSON file xval reads (scene/json_reader.h): nesting
  // bounded (Assimp's JSON parser recurses per level) and a key given
  // twice refused (Assimp and this check could each take another value).
  nlohmann::json j;
  try {
    j = parseJsonText(text, file.string() + ": glTF JSON");
  } catch (const SceneError& e) {
    throw ModelFileError(e.what());
  }
  if (!j.is_object()) throw ModelFileError(file.string() + ": glTF JSON is not an object");
  const auto asset = j.find("asset");
  const bool has = asset != j.end() && asset->is_object() && asset->contains("version");
  const bool text_version = has && (*asset)["version"].is_string();
  const std::string version = text_version ? (*asset)["version"].get<std::string>() : "";
  if (version.rfind("2.", 0) != 0)
    throw ModelFileError(file.string() + ": asset.version: " +
                         (text_version ? "'" + version + "'" : has ? (*asset)["version"].dump(-1, ' ', true) : "missing") +
                         " (only glTF 2.0 is read)");
  const auto& buffers = j.contains("buffers") ? j["buffers"] : nlohmann::json::array();
  if (!buffers.is_array()) throw ModelFileError(file.string() + ": buffers: expected an array");
  for (size_t b = 0; b < buffers.size(); ++b) {
    const auto& buf = buffers[b];
    const std::string at = file.string() + ": buffers[" + std::to_string(b) + "]";
    if (!buf.is_object() || !buf.contains("byteLength") || !buf["byteLength"].is_number_unsigned())
      throw ModelFileError(at + ".byteLength: expected a non-negative integer");
    const auto len = buf["byteLength"].get<unsigned long long>();
    long long have = limits.max_file_bytes;
    std::string what = "the file size limit";
    if (buf.contains("uri") && buf["uri"].is_string()) {
      const auto uri = buf["uri"].get<std::string>();
      if (uri.rfind("data:", 0) == 0) {
        have = (long long)(uri.size() / 4 * 3 + 3), what = "its data uri's decoded size";
      } else {
        std::string why;
        auto path = io.allowed(uri, &why);
        if (!path) throw ModelFileError(at + ".uri: " + why);
        std::error_code ec;
        have = (long long)fs::file_size(*path, ec), what = "the size of " + uri;
      }
    } else if (bin_chunk >= 0) {
      have = bin_chunk, what = "the GLB's binary chunk";
    }
    if (len > (unsigned long long)have)
      throw ModelFileError(at + ".byteLength: " + std::to_string(len) + " exceeds " + what + " (" +
                           std::to_string(have) + " bytes)");
  }
  std::vector<long long> mesh_triangles, mesh_placed;  // per glTF mesh
  const auto count = [&](const nlohmann::json& index) -> long long {
    if (!index.is_number_unsigned() || !j.contains("accessors") || !j["accessors"].is_array()) return 0;
    const auto a = index.get<unsigned long long>();
    if (a >= j["accessors"].size()) return 0;
    const auto& acc = j["accessors"][a];
    return acc.is_object() && acc.contains("count") && acc["count"].is_number_unsigned()
               ? (long long)std::min<unsigned long long>(acc["count"].get<unsigned long long>(), 1ull << 40)
               : 0;
  };
  if (j.contains("meshes") && j["meshes"].is_array())
    for (const auto& mesh : j["meshes"]) {
      mesh_triangles.push_back(0), mesh_placed.push_back(0);
      if (!mesh.is_object() || !mesh.contains("primitives") || !mesh["primitives"].is_array()) continue;
      for (const auto& prim : mesh["primitives"]) {
        if (!prim.is_object()) continue;
        const long long mode = prim.contains("mode") && prim["mode"].is_number_unsigned() ? prim["mode"].get<long long>() : 4;
        long long n = prim.contains("indices") ? count(prim["indices"])
                      : prim.contains("attributes") && prim["attributes"].is_object() &&
                              prim["attributes"].contains("POSITION")
                          ? count(prim["attributes"]["POSITION"])
                          : 0;
        mesh_triangles.back() += mode == 4 ? n / 3 : mode == 5 || mode == 6 ? std::max(0ll, n - 2) : 0;
        mesh_placed.back() += mode == 4 || mode == 5 || mode == 6;  // Assimp: one aiMesh per primitive
      }
    }
  checkGltfNodeGraph(file, j, mesh_triangles, mesh_placed, limits);
  long long declared = 0;
  for (long long t : mesh_triangles) declared += t;
  return declared;
}

long long checkGltf(const fs::path& file, long long size, const ModelLimits& limits, const GuardedIO& io) {
  std::ifstream in(file, std::ios::binary);
  std::string text((size_t)size, '\0');
  in.read(text.data(), size);
  return checkGltfJson(file, text, -1, limits, io);
}

uint32_t le32(const std::string& s, size_t at) {
  return uint32_t((unsigned char)s[at]) | uint32_t((unsigned char)s[at + 1]) << 8 |
         uint32_t((unsigned char)s[at + 2]) << 16 | uint32_t((unsigned char)s[at + 3]) << 24;
}

// GLB: 12-byte header (magic "glTF", version 2, total length), then chunks
// of (length, type, data): JSON first, BIN optional.
long long checkGlb(const fs::path& file, long long size, const ModelLimits& limits, const GuardedIO& io) {
  const std::string head = readPrefix(file, 20);
  const std::string at = file.string() + ": GLB header: ";
  if (head.size() < 20 || head.compare(0, 4, "glTF") != 0) throw ModelFileError(at + "no 'glTF' magic");
  if (le32(head, 4) != 2) throw ModelFileError(at + "version " + std::to_string(le32(head, 4)) + " (expected 2)");
  if ((long long)le32(head, 8) > size)
    throw ModelFileError(at + "length " + std::to_string(le32(head, 8)) + " exceeds the file's " +
                         std::to_string(size) + " bytes");
  const long long json_len = le32(head, 12);
  if (20 + json_len > size || le32(head, 16) != 0x4E4F534Au)
    throw ModelFileError(at + "the first chunk is not a JSON chunk within the file");
  std::ifstream in(file, std::ios::binary);
  in.seekg(20);
  std::string text((size_t)json_len, '\0');
  in.read(text.data(), json_len);
  long long bin = -1;
  const long long next = 20 + ((json_len + 3) & ~3ll);
  if (next + 8 <= size) {
    std::string ch = readPrefix(file, size_t(next + 8)).substr(size_t(next));
    if (ch.size() == 8 && le32(ch, 4) == 0x004E4942u) bin = std::min<long long>(le32(ch, 0), size - next - 8);
  }
  return checkGltfJson(file, text, bin, limits, io);
}

// --- Assimp -------------------------------------------------------------


glm::dvec3 d3(const aiVector3D& v) { return {v.x, v.y, v.z}; }
bool finite3(const aiVector3D& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

std::string nodeName(const aiNode* n) { return n->mName.length ? std::string(n->mName.C_Str()) : "(unnamed)"; }

struct Placed {
  const aiNode* node;
  std::string path;
  Affine to_file;  // the node's matrix times its ancestors'
};

// Every node, depth first with an explicit stack, and its accumulated
// transform. aiMatrix4x4 is row-major: row r = (a_r1 .. a_r4).
std::vector<Placed> placeNodes(const aiScene* scene, const std::string& file, const ModelLimits& limits) {
  std::vector<Placed> out;
  struct Item { const aiNode* node; Affine parent; std::string parent_path; int depth; };
  std::vector<Item> stack{{scene->mRootNode, Affine{}, "", 0}};
  while (!stack.empty()) {
    Item it = std::move(stack.back());
    stack.pop_back();
    if ((long long)out.size() >= limits.max_nodes) throw tooManyNodes(file, limits);
    if (it.depth > limits.max_node_depth) throw tooDeep(file, nodeName(it.node), limits);
    const std::string path = it.parent_path.empty() ? nodeName(it.node) : it.parent_path + "/" + nodeName(it.node);
    const aiMatrix4x4& m = it.node->mTransformation;
    const float all[16] = {m.a1, m.a2, m.a3, m.a4, m.b1, m.b2, m.b3, m.b4,
                           m.c1, m.c2, m.c3, m.c4, m.d1, m.d2, m.d3, m.d4};
    for (int k = 0; k < 16; ++k)
      if (!std::isfinite(all[k]))
        throw ModelFileError(file + ": node '" + path + "': transform element [" + std::to_string(k / 4) + "][" +
                             std::to_string(k % 4) + "] is " + num(all[k]));
    if (m.d1 != 0.0f || m.d2 != 0.0f || m.d3 != 0.0f || m.d4 != 1.0f)
      throw ModelFileError(file + ": node '" + path + "': transform's last row is " + vec(m.d1, m.d2, m.d3) +
                           ", " + num(m.d4) + " (expected 0, 0, 0, 1: not an affine map)");
    Affine local;
    local.linear = glm::dmat3(m.a1, m.b1, m.c1, m.a2, m.b2, m.c2, m.a3, m.b3, m.c3);  // columns
    local.offset = {m.a4, m.b4, m.c4};
    Affine to_file = then(local, it.parent);
    out.push_back({it.node, path, to_file});
    if (it.node->mNumChildren && !it.node->mChildren)
      throw ModelFileError(file + ": node '" + path + "': children missing");
    for (unsigned c = it.node->mNumChildren; c-- > 0;)
      stack.push_back({it.node->mChildren[c], to_file, path, it.depth + 1});
  }
  return out;
}

// Area-weighted vertex normals (model_file.h).
std::vector<glm::dvec3> computedNormals(const TriangleMesh& m) {
  std::vector<glm::dvec3> n(m.positions.size(), glm::dvec3(0.0));
  for (const auto& t : m.triangles) {
    const glm::dvec3 g = glm::cross(m.positions[t.y] - m.positions[t.x], m.positions[t.z] - m.positions[t.x]);
    n[t.x] += g, n[t.y] += g, n[t.z] += g;
  }
  for (auto& v : n) {
    const double len = glm::length(v);
    v = len > 0.0 && std::isfinite(len) ? v / len : glm::dvec3(0.0, 0.0, 1.0);
  }
  return n;
}

std::optional<ModelTexture> baseColorTexture(const aiScene* scene, const aiMesh* mesh, const std::string& where,
                                             const ModelLimits& limits) {
  if (mesh->mMaterialIndex >= scene->mNumMaterials || !scene->mMaterials) return std::nullopt;
  const aiMaterial* mat = scene->mMaterials[mesh->mMaterialIndex];
  if (!mat) return std::nullopt;
  for (aiTextureType type : {aiTextureType_BASE_COLOR, aiTextureType_DIFFUSE}) {
    if (mat->GetTextureCount(type) == 0) continue;
    aiString path;
    unsigned uv_index = 0;
    if (mat->GetTexture(type, 0, &path, nullptr, &uv_index) != aiReturn_SUCCESS) continue;
    if (uv_index != 0)
      throw ModelFileError(where + ": material " + std::to_string(mesh->mMaterialIndex) +
                           ": the base-colour texture uses uv set " + std::to_string(uv_index) +
                           " (only the first uv set is read)");
    ModelTexture t;
    t.name = path.C_Str();
    if (const aiTexture* e = scene->GetEmbeddedTexture(path.C_Str())) {
      if (e->mHeight != 0)
        throw ModelFileError(where + ": embedded texture '" + t.name +
                             "' is stored as raw texels (only encoded images such as PNG or JPEG are read)");
      if ((long long)e->mWidth > limits.max_texture_bytes)
        throw ModelFileError(where + ": embedded texture '" + t.name + "': " + std::to_string(e->mWidth) +
                             " bytes; the limit is " + std::to_string(limits.max_texture_bytes));
      const auto* bytes = reinterpret_cast<const std::uint8_t*>(e->pcData);
      t.bytes.assign(bytes, bytes + e->mWidth);
      t.format_hint = std::string(e->achFormatHint, strnlen(e->achFormatHint, sizeof e->achFormatHint));
    } else if (!t.name.empty() && t.name[0] == '*') {
      throw ModelFileError(where + ": texture '" + t.name + "' names an embedded image the file does not have");
    } else {
      t.file = t.name;  // resolved by the caller
    }
    return t;
  }
  return std::nullopt;
}

// --- Assimp in a child process -------------------------------------------
//
// Assimp's readers are not safe on hostile files: the fuzz smoke test
// (tests/fuzz, fuzz.model.smoke) found, in Debian's 5.2.5 under
// AddressSanitizer, a heap-buffer-overflow in the GLB reader and a bus
// error in a post-processing step on a PLY file, past every check above
// (kept in tests/fuzz/seeds/model; ModelFile.AssimpCrashIsAnError). So Assimp reads the
// file in a child process, xval-model-reader (geometry/assimp_read.h: what
// it writes back, and why a program of its own rather than a fork), run by
// process/run_process.h's runCaptured (its own process group, a time-out,
// killed on an interrupt), with everything of Assimp's that touches the
// file's bytes: the reader and the post-processing steps. This process
// rebuilds the aiScene from the dump, checking every count of it (a
// defect of Assimp's may have corrupted the child's memory). A crash, a
// sanitizer report or a hang of the child is this file's ModelFileError,
// naming what happened.

// An allocation past ModelLimits::max_import_memory_bytes fails in the
// child with std::bad_alloc: out of Assimp's ReadFile as its error string,
// out of the rest of the child's work as its exception message.
bool ranOutOfMemory(const std::string& message) { return message.find("bad_alloc") != std::string::npos; }
ModelFileError outOfImportMemory(const std::string& file, const ModelLimits& lim) {
  return ModelFileError(file + ": Assimp's child process ran out of the memory it may use reading it (" +
                        std::to_string(lim.max_import_memory_bytes) +
                        " bytes of address space, ModelLimits::max_import_memory_bytes)");
}

struct ChildRead {
  std::string error;
  std::vector<std::string> refusals;
  std::vector<fs::path> opened;
  std::string output;   // what the child wrote
  size_t scene_at = 0;  // where writeAssimpDump's bytes begin in it (they run to its end)
  std::string_view scene() const { return std::string_view(output).substr(scene_at); }
};


// The next field of `in` from `at`: its bytes are [begin, at) afterwards;
// false if it runs past the end.
bool skipField(const std::string& in, size_t& at, size_t& begin) {
  if (in.size() - at < 8) return false;
  uint64_t n = 0;
  for (int k = 0; k < 8; ++k) n |= uint64_t((unsigned char)in[at + k]) << (8 * k);
  at += 8;
  if (n > in.size() - at) return false;
  begin = at;
  at += size_t(n);
  return true;
}
// The same, copying the field.
bool takeField(const std::string& in, size_t& at, std::string& field) {
  size_t begin = 0;
  if (!skipField(in, at, begin)) return false;
  field.assign(in, begin, at - begin);
  return true;
}

// xval-model-reader beside the running program (xval's build folder), else
// where the build put it (XVAL_MODEL_READER_BUILT: the tests and tools are
// programs in other folders of the build).
fs::path modelReader(const std::string& file) {
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  if (!ec && fs::is_regular_file(self.parent_path() / kModelReader, ec)) return self.parent_path() / kModelReader;
  const fs::path built = XVAL_MODEL_READER_BUILT;
  if (fs::is_regular_file(built, ec)) return built;
  throw ModelFileError(file + ": cannot read it: " + kModelReader + " is neither beside " +
                       (self.empty() ? std::string("this program") : self.string()) + " nor at " + built.string() +
                       " (it is built with xval: cmake --build build)");
}

ChildRead readInChildProcess(const fs::path& real, const ModelLimits& lim) {
  const std::string file = real.string();
  // The dump holds every vertex with its attributes as floats, which can
  // be several times the files' bytes (an OBJ corner's indices become a
  // vertex of its own).
  const size_t max_output = size_t(16 * lim.max_total_bytes + (64ll << 20));
  const CapturedResult f =
      runCaptured(modelReaderArguments(modelReader(file), real, lim), lim.max_import_seconds, max_output);
  if (!f.process.ok()) {
    std::string what = f.process.describe();
    const std::string summary = f.summary();
    if (!summary.empty()) what += ": " + summary;
    if (ranOutOfMemory(summary)) throw outOfImportMemory(file, lim);
    if (f.process.timed_out)
      throw ModelFileError(file + ": Assimp did not finish reading it: its child process " + what +
                           " (ModelLimits::max_import_seconds)");
    throw ModelFileError(file + ": Assimp failed reading it, in its child process (" + what +
                         "): the file is malformed in a way Assimp's reader does not check");
  }
  ChildRead r;
  size_t at = 0;
  std::string count;
  auto bad = [&](const char* field) {
    return ModelFileError(file + ": the result Assimp's child process wrote is cut or malformed at field '" +
                          field + "' (" + std::to_string(f.output.size()) + " bytes)");
  };
  auto takeCount = [&](const char* field) {
    if (!takeField(f.output, at, count) || count.empty() || count.size() > 9 ||
        count.find_first_not_of("0123456789") != std::string::npos)
      throw bad(field);
    return std::stoul(count);
  };
  if (!takeField(f.output, at, r.error)) throw bad("error");
  for (unsigned long k = takeCount("refusals"); k > 0; --k) {
    r.refusals.emplace_back();
    if (!takeField(f.output, at, r.refusals.back())) throw bad("refusals");
  }
  for (unsigned long k = takeCount("opened"); k > 0; --k) {
    std::string o;
    if (!takeField(f.output, at, o)) throw bad("opened");
    r.opened.emplace_back(o);
  }
  // The scene's bytes stay where they are (the dump is the size of the
  // mesh); they are the last field.
  size_t scene_at = 0;
  if (!skipField(f.output, at, scene_at) || at != f.output.size()) throw bad("scene");
  if (r.error.empty() && scene_at == at) throw bad("scene");
  r.output = std::move(f.output);
  r.scene_at = scene_at;
  return r;
}

// The child's reads this process has made, kept with the bytes of every
// file the child opened (kChildReadMemoBytes in all): a validate run loads
// each scene several times (its plan, its jobs, its compare), and the
// child's Assimp read is most of a load. A kept read is used only when its
// limits are the same and every file it opened still holds exactly the
// bytes it held (read again and compared, never a time stamp); a read that
// failed or refused a file is never kept.
constexpr size_t kChildReadMemoBytes = size_t(256) << 20;

struct KeptRead {
  std::string key;  // the canonical path and every limit
  std::vector<std::pair<fs::path, std::string>> files;
  ChildRead read;
  size_t bytes = 0;
};
struct ChildReadMemo {
  std::mutex lock;
  std::vector<KeptRead> kept;
  size_t bytes = 0;
};
ChildReadMemo& childReadMemo() {
  static ChildReadMemo memo;
  return memo;
}

std::string readKey(const fs::path& real, const ModelLimits& l) {
  std::ostringstream k;
  k.precision(17);
  k << real.string() << '\n'
    << l.max_file_bytes << ' ' << l.max_total_bytes << ' ' << l.max_triangles << ' ' << l.max_vertices << ' '
    << l.max_primitives << ' ' << l.max_nodes << ' ' << l.max_node_depth << ' ' << l.max_texture_bytes << ' '
    << l.max_import_seconds << ' ' << l.max_import_memory_bytes;
  return k.str();
}

// The file's bytes if it is a regular file of exactly `size` bytes.
std::optional<std::string> bytesIfSize(const fs::path& file, size_t size) {
  std::error_code ec;
  if (!fs::is_regular_file(file, ec) || fs::file_size(file, ec) != size || ec) return std::nullopt;
  std::ifstream in(file, std::ios::binary);
  std::string b(size, '\0');
  if (!in.read(b.data(), std::streamsize(size)) || in.peek() != std::char_traits<char>::eof()) return std::nullopt;
  return b;
}

ChildRead readInChildProcessOnce(const fs::path& real, const ModelLimits& lim) {
  const std::string key = readKey(real, lim);
  ChildReadMemo& memo = childReadMemo();
  {
    std::unique_lock<std::mutex> hold(memo.lock);
    for (const KeptRead& k : memo.kept) {
      if (k.key != key) continue;
      const KeptRead candidate = k;  // compared without the lock
      hold.unlock();
      bool same = true;
      for (const auto& [file, bytes] : candidate.files) {
        const std::optional<std::string> now = bytesIfSize(file, bytes.size());
        if (!now || *now != bytes) {
          same = false;
          break;
        }
      }
      if (same) return candidate.read;
      break;
    }
  }
  ChildRead r = readInChildProcess(real, lim);
  if (!r.error.empty() || !r.refusals.empty()) return r;
  // The files as they are now: had one changed during the read, the kept
  // bytes would not match the next time and the file would be read again.
  KeptRead k{key, {}, r, r.output.size()};
  std::vector<fs::path> files = r.opened;
  if (std::find(files.begin(), files.end(), real) == files.end()) files.push_back(real);
  for (const fs::path& f : files) {
    std::error_code ec;
    const auto size = fs::file_size(f, ec);
    if (ec || size > kChildReadMemoBytes) return r;
    const std::optional<std::string> b = bytesIfSize(f, size_t(size));
    if (!b) return r;
    k.bytes += b->size();
    k.files.emplace_back(f, *b);
  }
  std::lock_guard<std::mutex> hold(memo.lock);
  memo.kept.erase(std::remove_if(memo.kept.begin(), memo.kept.end(),
                                 [&](const KeptRead& e) {
                                   if (e.key != key) return false;
                                   memo.bytes -= e.bytes;
                                   return true;
                                 }),
                  memo.kept.end());
  if (memo.bytes + k.bytes <= kChildReadMemoBytes) {
    memo.bytes += k.bytes;
    memo.kept.push_back(std::move(k));
  }
  return r;
}

}  // namespace


long long Model::triangleCount() const {
  long long n = 0;
  for (const auto& p : primitives) n += (long long)p.mesh.triangleCount();
  return n;
}
long long Model::vertexCount() const {
  long long n = 0;
  for (const auto& p : primitives) n += (long long)p.mesh.vertexCount();
  return n;
}

Model loadModelFile(const fs::path& file_in, const ModelLoadOptions& options) {
  const ModelLimits& lim = options.limits;
  const std::string file = file_in.string();
  const std::string ext = lower(file_in.extension().string());
  const auto& exts = modelFileExtensions();
  if (std::find(exts.begin(), exts.end(), ext) == exts.end()) {
    std::string list;
    for (const auto& e : exts) list += (list.empty() ? "" : ", ") + e;
    throw ModelFileError(file + ": unsupported model format '" + ext + "' (expected one of " + list + ")");
  }
  std::error_code ec;
  if (!fs::is_regular_file(file_in, ec))
    throw ModelFileError(file + ": " + (fs::exists(file_in, ec) ? "not a regular file" : "no such file"));
  const long long size = (long long)fs::file_size(file_in, ec);
  if (ec) throw ModelFileError(file + ": " + ec.message());
  if (size > lim.max_file_bytes)
    throw ModelFileError(file + ": " + std::to_string(size) + " bytes; the limit is " +
                         std::to_string(lim.max_file_bytes));
  const fs::path real = fs::canonical(file_in, ec);
  if (ec) throw ModelFileError(file + ": " + ec.message());

  GuardedIO io(real.parent_path(), lim);
  if (ext == ".ply") checkPlyHeader(real, size, lim);
  if (ext == ".off") checkOffHeader(real, size, lim);
  long long gltf_triangles = -1;
  if (ext == ".gltf") gltf_triangles = checkGltf(real, size, lim, io);
  if (ext == ".glb") gltf_triangles = checkGlb(real, size, lim, io);

  const ChildRead child = readInChildProcessOnce(real, lim);
  if (!child.refusals.empty())
    throw ModelFileError(file + ": refers to a file that cannot be read: " + child.refusals.front());
  if (!child.error.empty()) {
    if (ranOutOfMemory(child.error)) throw outOfImportMemory(file, lim);
    if (child.error.find("No meshes remaining") != std::string::npos)  // aiProcess_SortByPType removed them all
      throw ModelFileError(file + ": no triangles (the file has only points or lines)");
    throw ModelFileError(file + ": cannot read: " + child.error);
  }
  const std::unique_ptr<aiScene> rebuilt = readAssimpDump(child.scene(), file, lim.max_node_depth);
  const aiScene* scene = rebuilt.get();
  if (!scene->mRootNode || scene->mNumMeshes == 0 || !scene->mMeshes)
    throw ModelFileError(file + ": no triangles (the file has no surface meshes)");

  if (gltf_triangles >= 0) {
    long long read = 0;
    for (unsigned k = 0; k < scene->mNumMeshes; ++k)
      if (scene->mMeshes[k] && (scene->mMeshes[k]->mPrimitiveTypes & aiPrimitiveType_TRIANGLE))
        read += scene->mMeshes[k]->mNumFaces;
    if (read < gltf_triangles)
      throw ModelFileError(file + ": meshes: the primitives declare " + std::to_string(gltf_triangles) +
                           " triangles, Assimp read " + std::to_string(read) +
                           " (it drops a triangle with an index out of range)");
  }

  Model model;
  model.file = real;
  model.format = ext.substr(1);
  model.files = {real};
  for (const fs::path& f : child.opened)
    if (f != real) model.files.push_back(f);
  const std::vector<Placed> nodes = placeNodes(scene, file, lim);

  // Counts first, before any mesh array is filled.
  long long tris = 0, verts = 0, prims = 0;
  for (const auto& pl : nodes) {
    for (unsigned k = 0; k < pl.node->mNumMeshes; ++k) {
      const unsigned mi = pl.node->mMeshes[k];
      if (mi >= scene->mNumMeshes || !scene->mMeshes[mi])
        throw ModelFileError(file + ": node '" + pl.path + "': mesh index " + std::to_string(mi) +
                             " out of range (the file has " + std::to_string(scene->mNumMeshes) + " meshes)");
      const aiMesh* m = scene->mMeshes[mi];
      if (!(m->mPrimitiveTypes & aiPrimitiveType_TRIANGLE)) continue;
      tris += m->mNumFaces, verts += m->mNumVertices, ++prims;
    }
  }
  requirePlacedWithinLimits(file, prims, tris, lim);
  if (verts > lim.max_vertices)
    throw ModelFileError(file + ": " + std::to_string(verts) + " vertices (with every node's meshes); the limit is " +
                         std::to_string(lim.max_vertices));

  // Triangles dropped by the rule of geometry/degenerate_triangles.h, over
  // every placed mesh: one note for the file.
  struct {
    size_t read = 0, repeated_index = 0, duplicates = 0, primitives = 0;
    std::string first;  // the first placed mesh with any
  } dropped;
  for (const auto& pl : nodes) {
    for (unsigned k = 0; k < pl.node->mNumMeshes; ++k) {
      const unsigned mi = pl.node->mMeshes[k];
      const aiMesh* m = scene->mMeshes[mi];
      if (!(m->mPrimitiveTypes & aiPrimitiveType_TRIANGLE)) continue;
      ModelPrimitive p;
      p.mesh_index = mi;
      p.mesh_name = m->mName.C_Str();
      p.node_path = pl.path;
      p.label = "mesh " + std::to_string(mi) + " '" + p.mesh_name + "' (node '" + pl.path + "')";
      const std::string where = file + ": " + p.label;
      if (!m->mVertices) throw ModelFileError(where + ": has no positions");
      const unsigned nv = m->mNumVertices;
      TriangleMesh tm;
      tm.positions.reserve(nv);
      for (unsigned v = 0; v < nv; ++v) {
        if (!finite3(m->mVertices[v]))
          throw ModelFileError(where + ": vertex " + std::to_string(v) + ": position " +
                               vec(m->mVertices[v].x, m->mVertices[v].y, m->mVertices[v].z) + " is not finite");
        tm.positions.push_back(d3(m->mVertices[v]));
      }
      p.file_normals = m->mNormals != nullptr;
      if (p.file_normals) {
        tm.normals.reserve(nv);
        for (unsigned v = 0; v < nv; ++v) {
          if (!finite3(m->mNormals[v]))
            throw ModelFileError(where + ": vertex " + std::to_string(v) + ": normal " +
                                 vec(m->mNormals[v].x, m->mNormals[v].y, m->mNormals[v].z) + " is not finite");
          tm.normals.push_back(d3(m->mNormals[v]));
        }
      }
      p.has_uvs = m->mTextureCoords[0] != nullptr && m->mNumUVComponents[0] >= 2;
      tm.uvs.assign(nv, glm::dvec2(0.0));
      if (p.has_uvs) {
        for (unsigned v = 0; v < nv; ++v) {
          const aiVector3D& t = m->mTextureCoords[0][v];
          if (!std::isfinite(t.x) || !std::isfinite(t.y))
            throw ModelFileError(where + ": vertex " + std::to_string(v) + ": uv (" + num(t.x) + ", " + num(t.y) +
                                 ") is not finite");
          tm.uvs[v] = {double(t.x), 1.0 - double(t.y)};
        }
      }
      if (m->mNumFaces && !m->mFaces) throw ModelFileError(where + ": has no faces");
      tm.triangles.reserve(m->mNumFaces);
      for (unsigned f = 0; f < m->mNumFaces; ++f) {
        const aiFace& face = m->mFaces[f];
        if (face.mNumIndices != 3) continue;  // a point or line left in a mixed mesh
        for (unsigned c = 0; c < 3; ++c)
          if (face.mIndices[c] >= nv)
            throw ModelFileError(where + ": face " + std::to_string(f) + ": index " + std::to_string(face.mIndices[c]) +
                                 " out of range (the mesh has " + std::to_string(nv) + " vertices)");
        tm.triangles.push_back({face.mIndices[0], face.mIndices[1], face.mIndices[2]});
      }
      // Before the normals are computed: the mesh is the one without them.
      dropped.read += tm.triangles.size();
      if (DroppedTriangles d = dropDegenerateTriangles(tm.triangles); d.dropped() > 0) {
        dropped.repeated_index += d.repeated_index, dropped.duplicates += d.duplicates;
        if (dropped.first.empty()) dropped.first = p.label;
        ++dropped.primitives;
        tm.triangles = std::move(d.kept);
      }
      if (tm.triangles.empty()) continue;
      if (!p.file_normals) tm.normals.assign(nv, glm::dvec3(0.0, 0.0, 1.0));
      try {
        tm = transformed(tm, pl.to_file);
      } catch (const TransformError& e) {
        throw ModelFileError(file + ": node '" + pl.path + "': " + e.what());
      }
      // Normals last, on the placed triangles: computed ones, and file ones
      // of zero length (transformed() made those NaN).
      std::vector<glm::dvec3> computed;
      for (unsigned v = 0; v < nv; ++v) {
        const glm::dvec3& n = tm.normals[v];
        if (!p.file_normals || !std::isfinite(n.x) || !std::isfinite(n.y) || !std::isfinite(n.z)) {
          if (computed.empty()) computed = computedNormals(tm);
          tm.normals[v] = computed[v];
        }
      }
      for (unsigned v = 0; v < nv; ++v)
        if (!std::isfinite(tm.positions[v].x) || !std::isfinite(tm.positions[v].y) ||
            !std::isfinite(tm.positions[v].z))
          throw ModelFileError(where + ": vertex " + std::to_string(v) + ": position is not finite after node '" +
                               pl.path + "''s transform");
      p.texture = baseColorTexture(scene, m, where, lim);
      if (p.texture && !p.texture->embedded() && options.uvs == UvRequirement::ModelTextures) {
        std::string why;
        auto path = io.allowed(p.texture->name, &why);
        if (!path) throw ModelFileError(where + ": base-colour texture " + why);
        p.texture->file = *path;
      } else if (p.texture && !p.texture->embedded()) {
        std::string fixed = p.texture->name;
        std::replace(fixed.begin(), fixed.end(), '\\', '/');
        p.texture->file = fs::path(fixed).is_absolute() ? fs::path(fixed) : real.parent_path() / fixed;
      }
      const bool needs_uvs = options.uvs == UvRequirement::All ||
                             (options.uvs == UvRequirement::ModelTextures && p.texture.has_value());
      if (needs_uvs && !p.has_uvs)
        throw ModelFileError(where + ": a texture is applied to it, but the mesh has no uv coordinates");
      if (p.texture && !p.texture->embedded())
        if (auto inside = io.allowed(p.texture->name, nullptr))
          if (std::find(model.files.begin(), model.files.end(), *inside) == model.files.end())
            model.files.push_back(*inside);
      p.mesh = std::move(tm);
      model.primitives.push_back(std::move(p));
    }
  }
  if (dropped.primitives > 0)
    model.notes.push_back(
        file + ": " + std::to_string(dropped.repeated_index + dropped.duplicates) + " of " +
        std::to_string(dropped.read) + " triangles dropped in " + std::to_string(dropped.primitives) +
        " placed meshes (the first: " + dropped.first + "), " + std::to_string(dropped.repeated_index) +
        " with a repeated vertex index and " + std::to_string(dropped.duplicates) +
        " repeating an earlier triangle's three vertices: they cover no pixel, and every renderer gets the "
        "same triangles (geometry/degenerate_triangles.h)");
  if (model.primitives.empty()) {
    const std::string also = model.notes.empty() ? "" : " (" + model.notes.front() + ")";
    throw ModelFileError(file + ": no triangles (every mesh has only points or lines, or only dropped triangles)" +
                         also);
  }
  return model;
}

}  // namespace xval
