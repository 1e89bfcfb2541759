#include "gl/glsl_models.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

#include "colour/cie.h"
#include "colour/yiq.h"

namespace xval::gl {

namespace {

// What both stages share: the inputs' uniforms, the lights, the texture
// lookups and the models. The switches are the program's constants
// (variantConstants, ShaderVariant's fields): k_shading 0 flat, 1 gouraud,
// 2 phong; k_model: MODEL_<NAME>, the registry's id (shading/model/
// registry.h, written by modelIdConstants); k_light_kind 0 point,
// 1 directional, 2 spot; k_texture 0 none (u_base), 1 nearest, 2 bilinear,
// 3 trilinear (the sampler's LINEAR_MIPMAP_LINEAR on the GL mip chain).
const char* kVersion = R"GLSL(
#version 450 core
)GLSL";
const char* kCommon = R"GLSL(

uniform mat3 u_view;       // rows: right, up', forward (camera/camera.h)
uniform vec2 u_scale;      // 1 / (tan(fov/2) aspect), 1 / tan(fov/2)
uniform float u_near;      // the fitted near plane (reversed Z: depth = near / z)
uniform float u_ka, u_kd, u_ks, u_n, u_offset, u_factor;
uniform vec3 u_c0, u_c1, u_c2;
uniform float u_on_a, u_on_b;  // oren_nayar's A, B
uniform vec3 u_ambient;    // A: the ambient lights' summed colour (of the draw's light set)
uniform float u_ambient_luma;  // A_Y = lightLuma(A)
uniform vec3 u_base;
layout(binding = 0) uniform sampler2D u_tex;  // RGBA32F, row 0 = the image's top, read by texelFetch
layout(binding = 2) uniform usampler2D u_codes;  // k_texture_codes: RGBA8UI codes, as u_tex

struct Light {
  vec4 position_kind;    // xyz: position relative to the eye; w: unused (the kind is k_light_kind)
  vec4 direction_cos;    // xyz: unit direction the light travels; w: cos(cutoff)
  vec4 colour_luma;      // rgb: colour; w: lightLuma(colour)
  vec4 attenuation;      // constant, linear, quadratic; w: unused (k_light_attenuated)
};
// A uniform block, not a storage buffer: llvmpipe loads a storage buffer
// lane by lane in a fragment shader, a uniform block's constant index once.
layout(std140, binding = 0) uniform Lights { Light u_lights[k_light_array_size]; };

// clamp(x) and saturate(x), NaN -> 0 (shading/models.h)
float clamp0(float x) { return x > 0.0 ? x : 0.0; }
float saturate1(float x) { return x > 0.0 ? (x < 1.0 ? x : 1.0) : 0.0; }

// ---- lights (shading/lights.h) ---------------------------------------
// towardsLight: L and d of D = p_light - p, rescaled by the largest
// |component| where D.D is not a normal float; may_rescale false (a
// constant, k_light_may_rescale): D.D is known to be normal, not tested.
const float kFloatMin = 1.17549435e-38;
const float kFloatMax = 3.40282347e38;
void towardsLight(vec3 D, bool may_rescale, out vec3 L, out float d) {
  float dd = dot(D, D);
  if (!may_rescale || (dd >= kFloatMin && dd <= kFloatMax)) {
    d = sqrt(dd);
    L = D / d;
    return;
  }
  float s = max(abs(D.x), max(abs(D.y), abs(D.z)));
  if (!(s > 0.0) || !(s <= kFloatMax)) {
    d = s;
    L = vec3(0.0);
    return;
  }
  vec3 u = D / s;
  float lu = sqrt(dot(u, u));
  d = s * lu;
  L = u / lu;
}

// Light i: L towards it, att = 1 / (c + l d + q d^2), lit: inside a spot's
// cone. Its kind and whether it is attenuated are the program's constants.
void sampleLight(int i, vec3 p, out vec3 L, out float att, out bool lit) {
  Light l = u_lights[i];
  att = 1.0;
  lit = true;
  int kind = k_light_kind[i];
  if (kind == 1) {
    L = -l.direction_cos.xyz;
    return;
  }
  float dist;
  towardsLight(l.position_kind.xyz - p, k_light_may_rescale[i], L, dist);
  if (k_light_attenuated[i])
    att = 1.0 / (l.attenuation.x + l.attenuation.y * dist + l.attenuation.z * dist * dist);
  if (kind == 2) lit = dot(-L, l.direction_cos.xyz) >= l.direction_cos.w;
}

// ---- the listing's specular -----------------------------------------
// Reflection = normalize(2 N (N.L) - L); Specular = pow(saturate(R.V), n).
// n = 0 gives 1 (pow(0, 0) = 1, the reference's choice); a zero R gives 0.
float listingSpecular(vec3 N, vec3 L, float x, vec3 V) {
  if (u_n == 0.0) return 1.0;
  vec3 R = 2.0 * N * x - L;
  float len = length(R);
  if (!(len > 0.0)) return 0.0;
  float rv = saturate1(dot(R / len, V));
  return rv > 0.0 ? pow(rv, u_n) : 0.0;
}

)GLSL";
const char* kCommonModels = R"GLSL(
// ---- Forsyth's family, per unit light colour ---------------------------
vec3 forsyth(float x) {
  if (k_model == MODEL_LAMBERT) return u_c0 * clamp0(x);
  if (k_model == MODEL_WRAP_AROUND) return u_c0 * (clamp0(x + u_factor) / (1.0 + u_factor));
  if (k_model == MODEL_HEMISPHERICAL) return u_c2 + (u_c0 - u_c2) * ((x + 1.0) * 0.5);
  if (k_model == MODEL_BIDIRECTIONAL) return u_c0 * clamp0(x) + u_c2 * clamp0(-x);
  if (k_model == MODEL_TRILIGHT) return u_c0 * clamp0(x) + u_c1 * (1.0 - abs(x)) + u_c2 * clamp0(-x);
  return vec3(0.0);  // not of Forsyth's family: shade() does not call this
}

// ---- minnaert, oren_nayar, blinn_phong, per unit light colour (shading/models.h) ------
// Minnaert: clamp(x)^k clamp(y)^(k-1); 0 where x <= 0; x where k = 1; 0
// where y <= 0 otherwise (GLSL's pow is undefined for a zero base and a
// non-positive exponent: those cases never reach it).
float minnaertTerm(float x, float y) {
  if (!(x > 0.0)) return 0.0;
  if (u_n == 1.0) return x;
  if (!(y > 0.0)) return 0.0;
  return pow(x, u_n) * pow(y, u_n - 1.0);
}
// Oren-Nayar: s = L.V - x clamp(y); qualitative x (A + B max(s, 0) / max(x, y)),
// cycles x (A + B t), t = s / max(x, y) where s > 0, else s.
float orenNayarTerm(float x, float y, float lv) {
  if (!(x > 0.0)) return 0.0;
  float yc = clamp0(y);
  float s = lv - x * yc;
  float t = s > 0.0 ? s / max(x, yc) : (k_on_cycles ? s : 0.0);
  return x * (u_on_a + u_on_b * t);
}
// Blinn-Phong: clamp(N.H)^n, H = normalize(L + V) (0 where L + V = 0); n = 0 gives 1.
float blinnSpecular(vec3 N, vec3 L, vec3 V) {
  if (u_n == 0.0) return 1.0;
  vec3 s = L + V;
  float len = length(s);
  if (!(len > 0.0)) return 0.0;
  float nh = saturate1(dot(N, s / len));
  return nh > 0.0 ? pow(nh, u_n) : 0.0;
}

// ---- Cook-Torrance (shading/models.h cookTorranceSpecular) -------------
// k_ct_distribution 0 Beckmann, 1 GGX; k_ct_geometry 0 V-groove, 1 Smith;
// k_ct_fresnel 0 none, 1 Schlick (the models::Microfacet* enums' values).
uniform float u_ct_alpha, u_ct_f0;
float ctD(float c, float s2) {
  float a2 = u_ct_alpha * u_ct_alpha, c2 = c * c;
  if (k_ct_distribution == 0) {
    float e = exp(-s2 / (c2 * a2));
    return e > 0.0 ? e / (3.14159265358979 * a2 * c2 * c2) : 0.0;
  }
  float q = c2 * a2 + s2, r = u_ct_alpha / q;  // (alpha / q)^2: q^2 underflows at small alpha
  return r * r / 3.14159265358979;
}
float ctG1OverCos(float x, float s2) {  // Smith's G1(x) / x
  if (k_ct_distribution == 1) return 2.0 / (x + sqrt(x * x + u_ct_alpha * u_ct_alpha * s2));
  float as = u_ct_alpha * sqrt(s2);
  if (x >= 1.6 * as) return 1.0 / x;
  float a = x / as;
  return (3.535 + 2.181 * a) / ((1.0 + 2.276 * a + 2.577 * a * a) * as);
}
// S = pi F D G / (4 N.V)
float cookTorranceSpecular(vec3 n, vec3 l, vec3 v) {
  float nl = dot(n, l), nv = dot(n, v);
  if (!(nl > 0.0) || !(nv > 0.0)) return 0.0;
  vec3 sum = l + v;
  float len = length(sum);
  if (!(len > 0.0)) return 0.0;
  vec3 h = sum / len;
  float nh = dot(n, h), vh = 0.5 * len;  // V.H = |L + V| / 2: dot(v, h) cancels near L = -V
  if (!(nh > 0.0)) return 0.0;
  vec3 nxh = cross(n, h);
  float d = ctD(nh, dot(nxh, nxh));
  if (!(d > 0.0)) return 0.0;
  float g;
  if (k_ct_geometry == 1) {
    vec3 nxl = cross(n, l), nxv = cross(n, v);
    g = nl * ctG1OverCos(nl, dot(nxl, nxl)) * ctG1OverCos(nv, dot(nxv, nxv));
  } else {
    float k = 2.0 * nh / max(vh, 1.0 / 1024.0);
    g = min(1.0 / nv, min(k, k * nl / nv));
  }
  float m = 1.0 - vh, m2 = m * m;
  float f = k_ct_fresnel == 1 ? u_ct_f0 + (1.0 - u_ct_f0) * (m2 * m2 * m) : 1.0;
  return 3.14159265358979 * f * d * g * 0.25;
}

// ---- the model at one point (shading/shader.h), unsaturated -------------
// p: relative to the eye, n: unit normal, v: unit towards the eye, c: C.
vec3 shadeModel(vec3 p, vec3 n, vec3 v, vec3 c) {
  if (k_model == MODEL_CLASSIC_PHONG) {
    if (k_course) {
      vec3 acc = u_ka * u_ambient;
      for (int i = 0; i < k_light_count; ++i) {
        vec3 L; float att; bool lit;
        sampleLight(i, p, L, att, lit);
        vec3 w = att * u_lights[i].colour_luma.rgb;
        float term = u_ka;
        if (lit) {
          float x = dot(n, L);
          term += u_kd * clamp0(x);
          if (k_specular) term += u_ks * listingSpecular(n, L, x, v);
        }
        acc += w * term;
      }
      return c * acc;
    }
    vec3 diff = vec3(0.0), spec = vec3(0.0);
    for (int i = 0; i < k_light_count; ++i) {
      vec3 L; float att; bool lit;
      sampleLight(i, p, L, att, lit);
      if (!lit) continue;
      vec3 w = att * u_lights[i].colour_luma.rgb;
      float x = dot(n, L);
      diff += w * clamp0(x);
      if (k_specular) spec += w * listingSpecular(n, L, x, v);
    }
    return c * (u_ka * u_ambient + u_kd * diff) + u_ks * spec;
  }
  if (k_model == MODEL_YIQ_LUMA) {
    // Diffuse = saturate(A_Y + kd sum att Y(Lc) saturate(N.L)),
    // Specular = ks sum att Y(Lc) pow(saturate(R.V), n).
    float dsum = 0.0, ssum = 0.0;
    for (int i = 0; i < k_light_count; ++i) {
      vec3 L; float att; bool lit;
      sampleLight(i, p, L, att, lit);
      if (!lit) continue;
      float w = att * u_lights[i].colour_luma.w;
      float x = dot(n, L);
      dsum += w * saturate1(x);
      if (k_specular) ssum += w * listingSpecular(n, L, x, v);
    }
    float dl = saturate1(u_ambient_luma + u_kd * dsum);
    vec3 yiq = rgbToYiq(c);
    yiq.x = yiq.x * dl + u_ks * ssum - u_offset;  // WorkCol.y = WorkCol.y * Diffuse + Specular - 0.1
    return yiqToRgb(yiq);
  }
  if ((k_model == MODEL_MINNAERT) || (k_model == MODEL_OREN_NAYAR)) {
    vec3 diff = vec3(0.0);
    for (int i = 0; i < k_light_count; ++i) {
      vec3 L; float att; bool lit;
      sampleLight(i, p, L, att, lit);
      if (!lit) continue;
      float x = dot(n, L), y = dot(n, v);
      float o = (k_model == MODEL_MINNAERT) ? minnaertTerm(x, y) : orenNayarTerm(x, y, dot(L, v));
      diff += att * u_lights[i].colour_luma.rgb * o;
    }
    return c * (u_ambient + u_kd * diff);
  }
  // A Lambert diffuse and a highlight: blinn_phong's or cook_torrance's
  // (u_ka is 1 for cook_torrance).
  if ((k_model == MODEL_BLINN_PHONG) || (k_model == MODEL_COOK_TORRANCE)) {
    vec3 diff = vec3(0.0), spec = vec3(0.0);
    for (int i = 0; i < k_light_count; ++i) {
      vec3 L; float att; bool lit;
      sampleLight(i, p, L, att, lit);
      if (!lit) continue;
      vec3 w = att * u_lights[i].colour_luma.rgb;
      diff += w * clamp0(dot(n, L));
      if (k_specular)
        spec += w * ((k_model == MODEL_BLINN_PHONG) ? blinnSpecular(n, L, v) : cookTorranceSpecular(n, L, v));
    }
    return c * (u_ka * u_ambient + u_kd * diff) + u_ks * spec;
  }
  vec3 acc = u_ambient;
  for (int i = 0; i < k_light_count; ++i) {
    vec3 L; float att; bool lit;
    sampleLight(i, p, L, att, lit);
    if (!lit) continue;
    acc += att * u_lights[i].colour_luma.rgb * forsyth(dot(n, L));
  }
  return c * acc;
}

// ---- the luma-only mode (colour/luma_only.h) ---------------------------
// The model lit in grey (the draw's light set is then greyLights'), its
// luma replacing C's, C's chroma kept.
vec3 shade(vec3 p, vec3 n, vec3 v, vec3 c) {
  if (k_luma_only == 0) return shadeModel(p, n, v, c);
  bool cie = k_luma_only == 2;
  float yc = cie ? relativeXyz(c).y : rgbToYiq(c).x;
  vec3 g = shadeModel(p, n, v, vec3(yc));
  float yout = cie ? relativeXyz(g).y : yiqLightLuma(g);
  if (!cie) return c + vec3(yout - yc);
  vec3 t = relativeXyz(c);
  float d = labF(yout) - labF(yc);
  return rgbOfRelativeXyz(vec3(labFInverse(labF(t.x) + d), labFInverse(labF(t.y) + d), labFInverse(labF(t.z) + d)));
}

// ---- the texture (texture/texture.h): wrap, nearest or bilinear ---------
vec3 texel(int x, int y) {
  if (k_texture_codes) return codeValue(texelFetch(u_codes, ivec2(x, y), 0).rgb);
  return texelFetch(u_tex, ivec2(x, y), 0).rgb;
}
vec3 surfaceColour(vec2 uv) {
  if (k_texture == 0) return u_base;
  // The hardware's trilinear filter (GL_REPEAT wrapping) on the triangle's
  // own uv, unwrapped, so its derivatives across the pixel quad are smooth.
  if (k_texture == 3) return texture(u_tex, uv).rgb;
  ivec2 size = k_texture_codes ? textureSize(u_codes, 0) : textureSize(u_tex, 0);
  float fu = uv.x - floor(uv.x), fv = uv.y - floor(uv.y);
  if (!(fu >= 0.0 && fu <= 1.0)) fu = 0.0;  // NaN: a non-finite u
  if (!(fv >= 0.0 && fv <= 1.0)) fv = 0.0;
  if (k_texture == 1)
    return texel(min(int(fu * float(size.x)), size.x - 1), min(int(fv * float(size.y)), size.y - 1));
  float x = fu * float(size.x) - 0.5, y = fv * float(size.y) - 0.5;
  float x0f = floor(x), y0f = floor(y);
  float wx = x - x0f, wy = y - y0f;
  int x0 = int(x0f), y0 = int(y0f);
  int x1 = x0 + 1, y1 = y0 + 1;
  if (x0 < 0) x0 += size.x;
  if (y0 < 0) y0 += size.y;
  if (x1 >= size.x) x1 -= size.x;
  if (y1 >= size.y) y1 -= size.y;
  vec3 top = texel(x0, y0) * (1.0 - wx) + texel(x1, y0) * wx;
  vec3 bottom = texel(x0, y1) * (1.0 - wx) + texel(x1, y1) * wx;
  return top * (1.0 - wy) + bottom * wy;
}

vec3 unitOrZero(vec3 a) {
  float len = length(a);
  return len > 0.0 ? a / len : vec3(0.0);
}
)GLSL";

// An 8-bit code's value, c / 255 (Texture::codes_are_c_over_255), in the
// shaders and in the driver's check (codeValueCheckSource).
const char* kCodeValue = R"GLSL(
vec3 codeValue(uvec3 c) { return vec3(c) / 255.0; }
)GLSL";

// Camera-relative position to clip space, reversed Z with an infinite far
// plane: x_ndc = x / (z tan aspect), y_ndc = y / (z tan), depth = near / z
// (glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE), depth test GREATER).
// Gouraud: the model at the vertex (its texture colour at its uv).
const char* kVertex = R"GLSL(
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_uv;
layout(location = 3) in vec3 a_face_normal;
out vec3 v_position;
out vec3 v_normal;
out vec2 v_uv;
flat out vec3 v_face_normal;
out vec3 v_colour;

void main() {
  vec3 e = u_view * a_position;
  gl_Position = vec4(e.x * u_scale.x, e.y * u_scale.y, u_near, e.z);
  v_position = a_position;
  v_normal = a_normal;
  v_uv = a_uv;
  v_face_normal = a_face_normal;
  v_colour = vec3(0.0);
  if (k_shading == 1)
    v_colour = shade(a_position, a_normal, normalize(-a_position), surfaceColour(a_uv));
}
)GLSL";

// Per fragment: flat uses the triangle's normal, phong the interpolated one
// re-normalised (or, with the scene's normalize_normal off, as the paper's
// listing, as interpolated); V = normalize(eye - p) with the eye at the origin. The
// colour is written unsaturated (the box filter saturates each sample);
// alpha 1 marks a hit.
const char* kFragment = R"GLSL(
in vec3 v_position;
in vec3 v_normal;
in vec2 v_uv;
flat in vec3 v_face_normal;
in vec3 v_colour;
layout(location = 0) out vec4 o_colour;

void main() {
  if (k_shading == 1) {
    o_colour = vec4(v_colour, 1.0);
    return;
  }
  vec3 n = k_shading == 0 ? v_face_normal : k_normalize_normal ? unitOrZero(v_normal) : v_normal;
  vec3 v = normalize(-v_position);
  o_colour = vec4(shade(v_position, n, v, surfaceColour(v_uv)), 1.0);
}
)GLSL";

// The listing's RGBtoYIQ / YIQtoRGB in GLSL, from colour/yiq.h's matrices
// (8 decimals, as the listing prints them): each row a sum left to right,
// the first column of YIQ -> RGB (exactly 1) as yiq.x itself.
std::string yiqFunctions() {
  const auto& f = colour::kRgbToYiq;
  const auto& b = colour::kYiqToRgb;
  static_assert(colour::kYiqToRgb[0][0] == 1.0 && colour::kYiqToRgb[1][0] == 1.0 && colour::kYiqToRgb[2][0] == 1.0,
                "yiqToRgb writes the first column as yiq.x");
  auto term = [](double v, const char* x) {  // " + 0.95608445 * yiq.y" or " - 0.27137664 * yiq.y"
    return fmt::format(" {} {:.8f} * {}", v < 0 ? '-' : '+', std::abs(v), x);
  };
  std::string s = "// ---- YIQ (the listing's RGBtoYIQ / YIQtoRGB, coefficients verbatim) ----\n";
  s += "vec3 rgbToYiq(vec3 c) {\n  return vec3(";
  for (int r = 0; r < 3; ++r)
    s += fmt::format("{}{:.8f} * c.r + {:.8f} * c.g + {:.8f} * c.b{}", r ? "              " : "", f[r][0], f[r][1],
                     f[r][2], r < 2 ? ",\n" : ");\n}\n");
  s += "vec3 yiqToRgb(vec3 yiq) {  // without the listing's saturate: the frame saturates once\n  return vec3(";
  for (int r = 0; r < 3; ++r)
    s += std::string(r ? "              " : "") + "yiq.x" + term(b[r][1], "yiq.y") + term(b[r][2], "yiq.z") +
         (r < 2 ? ",\n" : ");\n}\n\n");
  return s;
}

// The luma-only mode's colour functions in GLSL, from colour/cie.h and
// colour/yiq.h (the same double constants, printed to 9 significant
// digits, float's round trip): relativeXyz, rgbOfRelativeXyz, labF,
// labFInverse (cube root as pow(t, 1/3) for t > the knee, where t > 0),
// and yiqLightLuma (colour/luma_only.h lightLuma for yiq).
std::string lumaOnlyFunctions() {
  std::string s = "// ---- CIE XYZ and L* (colour/cie.h) ----\n";
  auto matrix = [&](const char* name, const char* arg, auto entry) {
    s += fmt::format("vec3 {}(vec3 {}) {{\n  return vec3(", name, arg);
    for (int r = 0; r < 3; ++r)
      s += fmt::format("{}({:.9g} * {}.x + {:.9g} * {}.y) + {:.9g} * {}.z{}", r ? "              " : "", entry(r, 0), arg,
                       entry(r, 1), arg, entry(r, 2), arg, r < 2 ? ",\n" : ");\n}\n");
  };
  matrix("relativeXyz", "c", [](int r, int k) { return colour::kRgbToXyz[r][k] / colour::kWhiteXyz[r]; });
  matrix("rgbOfRelativeXyz", "t", [](int r, int k) { return colour::kXyzToRgb.m[r][k] * colour::kWhiteXyz[k]; });
  s += fmt::format("float labF(float t) {{ return t > {:.9g} ? pow(t, 1.0 / 3.0) : t * {:.9g} + {:.9g}; }}\n",
                   colour::kLabKnee, colour::kLabSlope, 4.0 / 29.0);
  s += fmt::format("float labFInverse(float u) {{ return u > {:.9g} ? u * u * u : (u - {:.9g}) / {:.9g}; }}\n",
                   colour::kLabDelta, 4.0 / 29.0, colour::kLabSlope);
  const double white = colour::kRgbToYiq[0][0] + colour::kRgbToYiq[0][1] + colour::kRgbToYiq[0][2];
  s += fmt::format("float yiqLightLuma(vec3 c) {{ return {:.9g} * c.r + {:.9g} * c.g + {:.9g} * c.b; }}\n\n",
                   colour::kRgbToYiq[0][0] / white, colour::kRgbToYiq[0][1] / white, colour::kRgbToYiq[0][2] / white);
  return s;
}

// const int MODEL_<NAME> = <id>; for every model of the registry.
std::string modelIdConstants() {
  std::string s;
  for (size_t id = 0; id < kModelCount; ++id)
    s += "const int " + glslModelConstant(ModelId(id)) + " = " + std::to_string(id) + ";\n";
  return s;
}

// The variant's switches as constants (ShaderVariant); the light arrays
// have at least one entry (GLSL has no empty array), read only below
// k_light_count.
std::string variantConstants(const ShaderVariant& v) {
  if (v.light_attenuated.size() != v.light_kinds.size() || v.light_may_rescale.size() != v.light_kinds.size())
    throw std::logic_error("ShaderVariant: " + std::to_string(v.light_kinds.size()) + " light kinds but " +
                           std::to_string(v.light_attenuated.size()) + " attenuation flags and " +
                           std::to_string(v.light_may_rescale.size()) + " rescaling flags");
  auto b = [](bool x) { return x ? "true" : "false"; };
  std::string kinds, attenuated, may_rescale;
  for (size_t i = 0; i < std::max<size_t>(v.light_kinds.size(), 1); ++i) {
    const bool real = i < v.light_kinds.size();
    kinds += fmt::format("{}{}", i ? ", " : "", real ? v.light_kinds[i] : 0);
    attenuated += fmt::format("{}{}", i ? ", " : "", b(real && v.light_attenuated[i]));
    may_rescale += fmt::format("{}{}", i ? ", " : "", b(real && v.light_may_rescale[i]));
  }
  const size_t n = std::max<size_t>(v.light_kinds.size(), 1);
  return fmt::format(
      "const int k_shading = {};\n"
      "const int k_model = {};\n"
      "const bool k_course = {};\n"
      "const bool k_specular = {};\n"
      "const bool k_on_cycles = {};\n"
      "const int k_ct_distribution = {}, k_ct_geometry = {}, k_ct_fresnel = {};\n"
      "const int k_texture = {};\n"
      "const bool k_texture_codes = {};\n"
      "const bool k_normalize_normal = {};\n"
      "const int k_luma_only = {};\n"
      "const int k_light_count = {}, k_light_array_size = {};\n"
      "const int k_light_kind[{}] = int[]({});\n"
      "const bool k_light_attenuated[{}] = bool[]({});\n"
      "const bool k_light_may_rescale[{}] = bool[]({});\n",
      v.shading, glslModelConstant(v.model), b(v.course), b(v.specular), b(v.on_cycles), v.ct_distribution,
      v.ct_geometry, v.ct_fresnel, v.texture, b(v.texture_codes), b(v.normalize_normal), v.luma_only,
      v.light_kinds.size(), n, n, kinds, n, attenuated, n, may_rescale);
}

}  // namespace

std::string glslModelConstant(ModelId id) {
  std::string s = "MODEL_";
  for (char c : kModelNames[size_t(id)]) s += char(std::toupper((unsigned char)c));
  return s;
}

std::string codeValueCheckSource() {
  return std::string(kVersion) + kCodeValue + R"GLSL(
layout(local_size_x = 256) in;
layout(std430, binding = 0) writeonly buffer Values { float v[]; };
void main() {
  uint c = gl_GlobalInvocationID.x;
  v[c] = codeValue(uvec3(c)).x;
}
)GLSL";
}

std::string vertexShaderSource(const ShaderVariant& variant) {
  return std::string(kVersion) + modelIdConstants() + variantConstants(variant) + kCommon + yiqFunctions() +
         lumaOnlyFunctions() + kCodeValue + kCommonModels + kVertex;
}

std::string fragmentShaderSource(const ShaderVariant& variant) {
  return std::string(kVersion) + modelIdConstants() + variantConstants(variant) + kCommon + yiqFunctions() +
         lumaOnlyFunctions() + kCodeValue + kCommonModels + kFragment;
}

}  // namespace xval::gl
