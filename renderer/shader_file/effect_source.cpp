// An HLSL effect file made into what glslang reads (effect_source.h).
#include "shader_file/effect_source.h"

#include <algorithm>
#include <cctype>
#include <regex>
#include <stdexcept>

namespace xval::shaderfile {

namespace {

bool identStart(char c) { return std::isalpha((unsigned char)c) || c == '_'; }
bool identChar(char c) { return std::isalnum((unsigned char)c) || c == '_'; }

std::string upper(std::string s) {
  for (char& c : s) c = char(std::toupper((unsigned char)c));
  return s;
}

std::string trim(const std::string& s) {
  const size_t b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r\n") - b + 1);
}

// Whitespace runs as one space, ends trimmed.
std::string squeeze(const std::string& s) {
  std::string out;
  for (char c : s) {
    const bool space = std::isspace((unsigned char)c);
    if (space && (out.empty() || out.back() == ' ')) continue;
    out += space ? ' ' : c;
  }
  return trim(out);
}

struct Text {
  const std::string& s;

  int lineOf(size_t pos) const { return 1 + int(std::count(s.begin(), s.begin() + std::min(pos, s.size()), '\n')); }

  // Past a comment or string starting at pos (pos itself when none starts there).
  size_t skipCommentOrString(size_t pos) const {
    if (s.compare(pos, 2, "//") == 0) {
      const size_t e = s.find('\n', pos);
      return e == std::string::npos ? s.size() : e;
    }
    if (s.compare(pos, 2, "/*") == 0) {
      const size_t e = s.find("*/", pos + 2);
      if (e == std::string::npos)
        throw std::runtime_error("line " + std::to_string(lineOf(pos)) + ": a /* comment is not closed");
      return e + 2;
    }
    if (s[pos] == '"') {
      for (size_t k = pos + 1; k < s.size(); ++k) {
        if (s[k] == '\\') ++k;
        else if (s[k] == '"') return k + 1;
        else if (s[k] == '\n') break;
      }
      throw std::runtime_error("line " + std::to_string(lineOf(pos)) + ": a string is not closed on its line");
    }
    return pos;
  }

  // The identifiers and punctuation of [b, e) (comments, strings skipped).
  std::vector<std::pair<std::string, size_t>> tokens(size_t b, size_t e) const {
    std::vector<std::pair<std::string, size_t>> out;
    for (size_t k = b; k < e;) {
      if (const size_t n = skipCommentOrString(k); n != k) {
        k = n;
        continue;
      }
      if (std::isspace((unsigned char)s[k])) {
        ++k;
      } else if (identChar(s[k])) {
        size_t j = k;
        while (j < e && (identChar(s[j]) || s[j] == '.')) ++j;
        out.emplace_back(s.substr(k, j - k), k);
        k = j;
      } else {
        out.emplace_back(std::string(1, s[k]), k);
        ++k;
      }
    }
    return out;
  }
};

// A top-level item: a declaration, a function, a struct or a technique.
struct Item {
  size_t begin = 0, end = 0;  // end: past its ';' or closing '}'
  bool closed = true;
  bool function = false;
  size_t paren = std::string::npos;  // the first '(' at depth 0 (a function's parameters)
  size_t brace = std::string::npos;  // the first '{' at depth 0, and its match
  size_t brace_end = std::string::npos;
  size_t eq = std::string::npos;  // the first '=' at depth 0 outside annotations
  std::vector<std::pair<size_t, size_t>> annotations;  // [<, >] at depth 0
  std::string first;                                    // its first word
};

std::vector<Item> topLevelItems(const Text& t) {
  const std::string& s = t.s;
  std::vector<Item> items;
  size_t pos = 0;
  while (pos < s.size()) {
    if (const size_t n = t.skipCommentOrString(pos); n != pos) {
      pos = n;
      continue;
    }
    if (std::isspace((unsigned char)s[pos])) {
      ++pos;
      continue;
    }
    if (s[pos] == '#') {  // a preprocessor line (with continuations)
      while (pos < s.size() && s[pos] != '\n') pos += s[pos] == '\\' ? 2 : 1;
      continue;
    }
    Item it;
    it.begin = pos;
    size_t w = pos;
    while (w < s.size() && identChar(s[w])) ++w;
    it.first = s.substr(pos, w - pos);
    const bool ends_at_brace_always = it.first.rfind("technique", 0) == 0 || it.first == "cbuffer";
    int depth = 0, paren = 0;
    size_t angle_open = std::string::npos;
    bool done = false;
    for (size_t k = pos; k < s.size() && !done;) {
      if (const size_t n = t.skipCommentOrString(k); n != k) {
        k = n;
        continue;
      }
      const char c = s[k];
      if (angle_open != std::string::npos) {
        if (c == '>') {
          it.annotations.emplace_back(angle_open, k);
          angle_open = std::string::npos;
        }
        ++k;
        continue;
      }
      if (depth == 0) {
        if (c == '(') {
          if (it.paren == std::string::npos && it.eq == std::string::npos) it.paren = k;
          ++paren;
        } else if (c == ')') {
          --paren;
        } else if (c == '<' && paren == 0 && it.eq == std::string::npos && it.brace == std::string::npos) {
          angle_open = k;
        } else if (c == '=' && paren == 0 && it.eq == std::string::npos && it.brace == std::string::npos) {
          it.eq = k;
        } else if (c == ';' && paren == 0) {
          it.end = k + 1;
          done = true;
        } else if (c == '{') {
          if (it.brace == std::string::npos) it.brace = k;
          if (it.paren != std::string::npos && it.eq == std::string::npos && it.brace == k) it.function = true;
          ++depth;
        }
      } else if (c == '{') {
        ++depth;
      } else if (c == '}') {
        if (--depth == 0) {
          if (it.brace_end == std::string::npos) it.brace_end = k;
          if (it.function || ends_at_brace_always) {
            it.end = k + 1;
            done = true;
          }
        }
      }
      ++k;
    }
    if (!done) {
      if (it.first.rfind("technique", 0) != 0)
        throw std::runtime_error("line " + std::to_string(t.lineOf(it.begin)) + ": \"" + it.first +
                                 " ...\" is not closed by the end of the file (expected ';' or '}')");
      it.closed = false;
      it.end = s.size();
    }
    items.push_back(it);
    pos = it.end;
  }
  return items;
}

bool isModifier(const std::string& w) {
  static const char* kModifiers[] = {"uniform", "static", "const", "extern", "shared", "volatile",
                                     "row_major", "column_major", "in", "out", "inout", "precise",
                                     "nointerpolation", "linear", "centroid", "noperspective", "sample"};
  return std::find(std::begin(kModifiers), std::end(kModifiers), w) != std::end(kModifiers);
}

// `[modifiers] TYPE NAME [: SEMANTIC]` of the tokens (annotations, initialiser excluded).
struct Declarator {
  std::vector<std::string> modifiers;
  std::string type, name, semantic;
  size_t semantic_pos = std::string::npos;
};

Declarator declarator(const std::vector<std::pair<std::string, size_t>>& toks) {
  Declarator d;
  size_t k = 0;
  while (k < toks.size() && isModifier(toks[k].first)) d.modifiers.push_back(toks[k++].first);
  std::vector<std::pair<std::string, size_t>> head;
  for (; k < toks.size() && toks[k].first != ":"; ++k) head.push_back(toks[k]);
  if (head.size() >= 2 && identStart(head.back().first[0])) {
    d.name = head.back().first;
    for (size_t j = 0; j + 1 < head.size(); ++j) d.type += head[j].first;
  }
  if (k + 1 < toks.size() && toks[k].first == ":") {
    d.semantic = toks[k + 1].first;
    d.semantic_pos = toks[k + 1].second;
  }
  return d;
}

struct StructField {
  std::string name, semantic;
  size_t semantic_pos = std::string::npos;
};

}  // namespace

PreparedEffect prepareEffect(const std::string& text, const std::string& vertex_entry) {
  const Text t{text};
  PreparedEffect out;
  // Replacements of [pos, pos + len) by `with`, applied last to first.
  struct Replacement {
    size_t pos, len;
    std::string with;
  };
  std::vector<Replacement> edits;
  auto blank = [&](size_t b, size_t e) {
    std::string with = text.substr(b, e - b);
    for (char& c : with)
      if (c != '\n') c = ' ';
    edits.push_back({b, e - b, with});
  };

  const std::vector<Item> items = topLevelItems(t);
  std::map<std::string, std::vector<StructField>> structs;
  const Item* vertex_function = nullptr;
  for (const Item& it : items) {
    const int line = t.lineOf(it.begin);
    if (it.first.rfind("technique", 0) == 0) {
      // Each pass: `pass NAME <...> { Key = Value; ... }`.
      const auto words = t.tokens(it.begin, it.end);
      const std::string name = words.size() > 1 && identStart(words[1].first[0]) ? words[1].first : "";
      const std::string body = it.brace == std::string::npos ? "" : text.substr(it.brace + 1, it.end - it.brace - 1);
      static const std::regex kPass(R"(\bpass\s+([A-Za-z_]\w*)[^{]*\{([^}]*)\}?)");
      for (auto m = std::sregex_iterator(body.begin(), body.end(), kPass); m != std::sregex_iterator(); ++m) {
        EffectPass p;
        p.technique = name.empty() ? it.first : name;
        p.pass = (*m)[1];
        p.line = t.lineOf(it.brace + 1 + size_t(m->position(0)));
        const std::string states = (*m)[2];
        size_t b = 0;
        for (size_t e; (e = states.find(';', b)) != std::string::npos; b = e + 1) {
          const std::string st = states.substr(b, e - b);
          const size_t eq = st.find('=');
          if (eq != std::string::npos) p.states.emplace_back(trim(st.substr(0, eq)), squeeze(st.substr(eq + 1)));
        }
        out.passes.push_back(p);
      }
      blank(it.begin, it.end);
      out.edits.push_back({line, "technique \"" + (name.empty() ? it.first : name) + "\" stripped" +
                                     (it.closed ? "" : " to the end of the file (its block is not closed)") +
                                     ": its pass's render states are the host's pipeline state"});
      continue;
    }
    std::vector<std::pair<std::string, size_t>> head_tokens;
    {
      size_t head_end = std::min({it.end, it.eq, it.brace, it.paren});
      size_t k = it.begin;
      for (const auto& [a, b] : it.annotations) {
        if (a >= head_end) break;
        auto part = t.tokens(k, a);
        head_tokens.insert(head_tokens.end(), part.begin(), part.end());
        k = b + 1;
      }
      auto part = t.tokens(k, head_end);
      head_tokens.insert(head_tokens.end(), part.begin(), part.end());
    }
    if (it.first == "struct" && it.brace != std::string::npos) {
      const std::string sname = head_tokens.size() >= 2 ? head_tokens[1].first : "";
      std::vector<StructField> fields;
      size_t b = it.brace + 1;
      for (size_t e = b; e < it.brace_end; ++e) {
        if (text[e] != ';') continue;
        const Declarator d = declarator(t.tokens(b, e));
        if (!d.name.empty()) fields.push_back({d.name, d.semantic, d.semantic_pos});
        b = e + 1;
      }
      structs[sname] = fields;
      continue;
    }
    if (it.function) {
      const Declarator d = declarator(head_tokens);
      if (d.name == vertex_entry) vertex_function = &it;
      // The second of two consecutive identical declarations with an initialiser.
      static const std::regex kDeclaration(R"(^(const )?[A-Za-z_]\w* [A-Za-z_]\w* ?=(.*);$)");
      std::string previous;
      size_t start = it.brace + 1;
      for (size_t k = it.brace + 1; k < it.end;) {
        if (const size_t n = t.skipCommentOrString(k); n != k) {
          k = n;
          continue;
        }
        const char c = text[k];
        if (c == '{' || c == '}') {
          previous.clear();
          start = k + 1;
        } else if (c == ';') {
          const std::string stmt = squeeze(text.substr(start, k + 1 - start));
          std::smatch m;
          const bool repeat = stmt == previous && std::regex_match(stmt, m, kDeclaration) &&
                              m[2].str().find("++") == std::string::npos &&
                              m[2].str().find("--") == std::string::npos &&
                              !std::regex_search(m[2].str(), std::regex(R"((^|[^=!<>])=($|[^=]))"));
          if (repeat) {
            const size_t from = text.find_first_not_of(" \t\r\n", start);
            out.edits.push_back({t.lineOf(from), "the repeated declaration \"" + stmt +
                                                     "\" removed (identical to the statement before it; HLSL "
                                                     "refuses a name declared twice in one scope)"});
            blank(from, k + 1);
            previous.clear();
          } else {
            previous = stmt;
          }
          start = k + 1;
        }
        ++k;
      }
      continue;
    }
    const Declarator d = declarator(head_tokens);
    if (d.name.empty()) continue;
    if (d.type == "texture" || d.type == "texture1D" || d.type == "texture2D" || d.type == "texture3D" ||
        d.type == "textureCUBE") {
      out.textures.push_back({d.name, d.semantic, line});
      blank(it.begin, it.end);
      out.edits.push_back({line, "the DX9 texture declaration \"" + d.name + "\" stripped (glslang has no "
                                                                             "`texture` type): the host binds "
                                                                             "it through the samplers naming it"});
      continue;
    }
    if (it.eq != std::string::npos) {
      const auto init = t.tokens(it.eq + 1, it.end);
      if (!init.empty() && init[0].first == "sampler_state") {
        EffectSampler smp;
        smp.name = d.name;
        smp.line = line;
        const size_t ob = text.find('{', it.eq), cb = text.rfind('}', it.end);
        if (ob != std::string::npos && cb != std::string::npos && ob < cb) {
          const std::string body = text.substr(ob + 1, cb - ob - 1);
          size_t b = 0;
          for (size_t e; (e = body.find(';', b)) != std::string::npos; b = e + 1) {
            const std::string st = body.substr(b, e - b);
            const size_t eq = st.find('=');
            if (eq == std::string::npos) continue;
            const std::string key = upper(trim(st.substr(0, eq)));
            std::string value = squeeze(st.substr(eq + 1));
            if (key == "TEXTURE") {
              value.erase(std::remove_if(value.begin(), value.end(),
                                         [](char c) { return c == '<' || c == '>' || c == '(' || c == ')' || c == ' '; }),
                          value.end());
              smp.texture = value;
            } else {
              smp.states[key] = value;
            }
          }
        }
        out.samplers.push_back(smp);
        // Keep the trailing ';'.
        blank(it.eq, it.end - 1);
        out.edits.push_back({line, "the sampler_state initialiser of \"" + d.name +
                                       "\" cut (glslang cannot read it): its states are the host's sampler state"});
        continue;
      }
    }
    if (std::find(d.modifiers.begin(), d.modifiers.end(), "static") != d.modifiers.end()) continue;
    EffectGlobal g{d.type, d.name, d.semantic, "", line};
    for (const auto& [a, b] : it.annotations) {
      static const std::regex kObject(R"(\bObject\s*=\s*\"([^\"]*)\")");
      std::smatch m;
      const std::string ann = text.substr(a, b - a);
      if (std::regex_search(ann, m, kObject)) g.object = m[1];
    }
    out.globals.push_back(g);
  }

  // The vertex entry: its inputs, and its DX9 POSITION output read as SV_Position.
  if (vertex_function) {
    const Item& f = *vertex_function;
    int depth = 0;
    size_t close = f.paren;
    for (size_t k = f.paren; k < f.brace; ++k) {
      if (text[k] == '(') ++depth;
      if (text[k] == ')' && --depth == 0) {
        close = k;
        break;
      }
    }
    auto position_output = [&](const std::string& semantic, size_t pos) {
      const std::string u = upper(semantic);
      if (u != "POSITION" && u != "POSITION0") return;
      edits.push_back({pos, semantic.size(), "SV_Position"});
      out.edits.push_back({t.lineOf(pos), "the vertex shader's output semantic " + semantic +
                                              " read as SV_Position (DX9's clip-space position)"});
    };
    // Its return: a struct's fields, or its own semantic.
    const Declarator ret = declarator(t.tokens(f.begin, f.paren));
    if (auto s = structs.find(ret.type); s != structs.end())
      for (const StructField& fld : s->second) position_output(fld.semantic, fld.semantic_pos);
    const Declarator after = declarator([&] {
      auto toks = t.tokens(close + 1, f.brace);
      toks.insert(toks.begin(), {{"void", 0}, {"f", 0}});
      return toks;
    }());
    if (!after.semantic.empty()) position_output(after.semantic, after.semantic_pos);
    size_t b = f.paren + 1;
    depth = 0;
    for (size_t k = f.paren + 1; k <= close; ++k) {
      if (k < close && (text[k] != ',' || depth > 0)) {
        depth += text[k] == '(' ? 1 : text[k] == ')' ? -1 : 0;
        continue;
      }
      const Declarator p = declarator(t.tokens(b, k));
      b = k + 1;
      if (p.name.empty()) continue;
      const bool is_out = std::find(p.modifiers.begin(), p.modifiers.end(), "out") != p.modifiers.end();
      auto s = structs.find(p.type);
      if (is_out) {
        if (s != structs.end())
          for (const StructField& fld : s->second) position_output(fld.semantic, fld.semantic_pos);
        else
          position_output(p.semantic, p.semantic_pos);
      } else if (!p.semantic.empty() || s == structs.end()) {
        out.vertex_inputs.push_back({p.name, p.semantic});
      } else {
        for (const StructField& fld : s->second) out.vertex_inputs.push_back({p.name + "_" + fld.name, fld.semantic});
      }
    }
  }

  std::sort(edits.begin(), edits.end(), [](const Replacement& a, const Replacement& b) { return a.pos > b.pos; });
  out.text = text;
  for (const Replacement& r : edits) out.text.replace(r.pos, r.len, r.with);
  std::stable_sort(out.edits.begin(), out.edits.end(),
                   [](const SourceEdit& a, const SourceEdit& b) { return a.line < b.line; });
  return out;
}

}  // namespace xval::shaderfile
