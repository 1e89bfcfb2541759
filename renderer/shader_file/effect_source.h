// An HLSL effect file (NVIDIA FX Composer / DirectX 9 style) made into
// what glslang's HLSL front end reads, by edits the tool makes and reports,
// never by hand-editing the user's file (docs/shaders.md, "What the tool
// edits").
//
// glslang compiles HLSL shader code, not the effect framework around it.
// prepareEffect reads the file's top-level items and:
//   - strips each `technique` block (technique, technique9/10/11): its
//     one pass's render states are returned (EffectPass) for the host to
//     apply or refuse; a block left unclosed at the end of the file (the
//     paper's listing as printed ends so) is stripped to the end;
//   - strips DX9 `texture NAME : SEMANTIC <...>;` declarations, returning
//     each name and semantic (EffectTexture);
//   - cuts a sampler's `= sampler_state { ... }` initialiser, leaving
//     `sampler2D NAME;`, returning its states (EffectSampler);
//   - removes the second of two consecutive identical declarations with an
//     initialiser (`float3 L = normalize(P - X);` twice): HLSL refuses a
//     name declared twice in one scope, and the repeat computes the same
//     value. Only a statement without assignment, ++ or -- in its
//     initialiser qualifies (it could change something otherwise);
//   - reads the vertex entry's DX9 output semantic POSITION (POSITION0) as
//     SV_Position: in DX9 it is the clip-space position, which glslang 12
//     otherwise treats as a plain varying (nothing would be drawn).
// Every edit replaces text by blanks of the same lines (newlines kept), so
// the compiler's line numbers are the user's file's. The globals (type,
// name, semantic, the `Object` annotation) are returned for binding by
// semantic, and the vertex entry's inputs with their semantics.
//
// A parse the scanner cannot finish (an unclosed comment, string or block
// other than a technique) throws std::runtime_error naming the line.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace xval::shaderfile {

struct SourceEdit {
  int line = 0;  // 1-based, in the user's file
  std::string what;
};

// A global variable declared at the top level (not static: a uniform).
struct EffectGlobal {
  std::string type, name, semantic;  // semantic as written ("" for none)
  std::string object;                // the annotation `string Object = "..."` ("" for none)
  int line = 0;
};

struct EffectTexture {
  std::string name, semantic;
  int line = 0;
};

struct EffectSampler {
  std::string name;
  std::string texture;                        // its `Texture = <NAME>` ("" for none)
  std::map<std::string, std::string> states;  // the other states, keys upper-cased, values as written
  int line = 0;
};

// The states of a technique's pass, keys as written (ZEnable, CullMode, ...).
struct EffectPass {
  std::string technique, pass;
  std::vector<std::pair<std::string, std::string>> states;
  int line = 0;
};

// One input of the vertex entry as the compiled GLSL names it (the
// parameter's name, or PARAM_FIELD for a field of a struct parameter),
// and its semantic as written.
struct EntryInput {
  std::string glsl_name, semantic;
};

struct PreparedEffect {
  std::string text;  // what glslang reads: the file with the edits, same line count
  std::vector<SourceEdit> edits;
  std::vector<EffectGlobal> globals;
  std::vector<EffectTexture> textures;
  std::vector<EffectSampler> samplers;
  std::vector<EffectPass> passes;  // one per pass of every technique stripped
  std::vector<EntryInput> vertex_inputs;
};

PreparedEffect prepareEffect(const std::string& text, const std::string& vertex_entry);

}  // namespace xval::shaderfile
