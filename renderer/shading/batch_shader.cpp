// Highway's dynamic dispatch: this file is compiled once per SIMD target
// (foreach_target.h re-includes it), and shadeBatch picks the best one the
// CPU has at run time.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "shading/batch_shader.cpp"
#include <hwy/foreach_target.h>  // must come before highway.h
#include <hwy/highway.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "shading/batch_shader.h"
#include "shading/models.h"

HWY_BEFORE_NAMESPACE();
namespace xval {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using DF = hn::ScalableTag<float>;
using DI = hn::RebindToSigned<DF>;
using DU = hn::RebindToUnsigned<DF>;
using VF = hn::Vec<DF>;
using VI = hn::Vec<DI>;
using MF = hn::Mask<DF>;

struct V3 {
  VF x, y, z;
};
// Every helper rounds exactly as the scalar glm expression it mirrors.
HWY_INLINE V3 add(V3 a, V3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
HWY_INLINE V3 sub(V3 a, V3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
HWY_INLINE V3 mul(VF s, V3 a) { return {s * a.x, s * a.y, s * a.z}; }
HWY_INLINE V3 mul(V3 a, V3 b) { return {a.x * b.x, a.y * b.y, a.z * b.z}; }
HWY_INLINE VF dot(V3 a, V3 b) { return (a.x * b.x + a.y * b.y) + a.z * b.z; }  // glm: (x + y) + z
HWY_INLINE V3 splat(DF d, glm::vec3 v) { return {hn::Set(d, v.x), hn::Set(d, v.y), hn::Set(d, v.z)}; }
// models::saturate: NaN -> 0.
HWY_INLINE VF saturate(DF d, VF x) {
  return hn::IfThenElseZero(x > hn::Zero(d), hn::IfThenElse(x < hn::Set(d, 1.0f), x, hn::Set(d, 1.0f)));
}
HWY_INLINE VF clamp0(DF d, VF x) { return hn::IfThenElseZero(x > hn::Zero(d), x); }

// Gathers component c of a float3 array at vertex indices idx.
HWY_INLINE VF gather3(DF d, const float* base, VI idx3, int c) {
  return hn::GatherIndex(d, base + c, idx3);
}
// One vertex record (kBatchVertexFloats floats: p, n, u, v) of every lane.
struct VertexV {
  V3 p, n;
  VF u, v;
};
// The records of the vertices `index`, by 64-bit gathers of float pairs
// (p.x p.y, p.z n.x, n.y n.z, u v): half the elements of gathering each
// float alone. The lower and the upper lanes' pairs are gathered apart (a
// vector holds half as many 64-bit lanes) and split into floats again by
// ConcatEven/ConcatOdd (little endian: a pair's first float is its even
// 32-bit lane). Byte offsets in 64 bits (no overflow for a large mesh),
// by GatherOffset (it copies bytes where it is emulated: no aliasing).
HWY_INLINE VertexV gatherVertex(DF d, const float* vertices, VI index) {
  static_assert(kBatchVertexFloats == 8, "a record is 4 pairs, 32 bytes");
  const hn::Half<DI> dh;
  const hn::Rebind<std::int64_t, decltype(dh)> d64;
  const std::int64_t* words = reinterpret_cast<const std::int64_t*>(vertices);
  const auto lo = hn::ShiftLeft<5>(hn::PromoteTo(d64, hn::LowerHalf(dh, index)));
  const auto hi = hn::ShiftLeft<5>(hn::PromoteTo(d64, hn::UpperHalf(dh, index)));
  VF even[4], odd[4];
  for (int q = 0; q < 4; ++q) {
    const auto at = hn::Set(d64, std::int64_t(8 * q));
    const VF wlo = hn::BitCast(d, hn::GatherOffset(d64, words, lo + at));
    const VF whi = hn::BitCast(d, hn::GatherOffset(d64, words, hi + at));
    even[q] = hn::ConcatEven(d, whi, wlo), odd[q] = hn::ConcatOdd(d, whi, wlo);
  }
  return {{even[0], odd[0], even[1]}, {odd[1], even[2], odd[2]}, even[3], odd[3]};
}

// The records of the vertices index[0..N), for 16 lanes of AVX-512: each
// record (8 floats, 32 bytes) by one 256-bit load, lane q's in the lower
// half and lane q + 8's in the upper half of vector q, then the 8 x 8
// transposition of each half (unpack, shuffle, and a two-source permute
// that puts lanes 0-3, 4-7, 8-11, 12-15 in order). The same floats as
// gatherVertex, in 40 instructions instead of 8 gathers of 8 pairs (a
// gather is microcoded, element by element, on the CPUs measured).
// Other targets: gatherVertex.
#if HWY_ARCH_X86 && HWY_TARGET <= HWY_AVX3
HWY_INLINE VertexV loadVertices(DF d, const float* vertices, const std::int32_t* index) {
  static_assert(kBatchVertexFloats == 8, "a record is one 256-bit load");
  static_assert(hn::MaxLanes(DF()) == 16, "16 lanes: two records per vector");
  __m512 r[8];
  for (int q = 0; q < 8; ++q) {
    const __m256 lo = _mm256_loadu_ps(vertices + size_t(std::uint32_t(index[q])) * kBatchVertexFloats);
    const __m256 hi = _mm256_loadu_ps(vertices + size_t(std::uint32_t(index[q + 8])) * kBatchVertexFloats);
    r[q] = _mm512_insertf32x8(_mm512_castps256_ps512(lo), hi, 1);
  }
  __m512 t[8], s[8];
  for (int q = 0; q < 8; q += 2)
    t[q] = _mm512_unpacklo_ps(r[q], r[q + 1]), t[q + 1] = _mm512_unpackhi_ps(r[q], r[q + 1]);
  // Per 128-bit block: s[4h + 2g + w] holds, for records 4h..4h+3 (and
  // those + 8 in the upper half), component 2g + w (block 0) and 4 + 2g +
  // w (block 1).
  for (int h = 0; h < 2; ++h)
    for (int g = 0; g < 2; ++g) {
      const __m512 a = t[4 * h + g], b = t[4 * h + 2 + g];
      s[4 * h + 2 * g] = _mm512_shuffle_ps(a, b, 0x44), s[4 * h + 2 * g + 1] = _mm512_shuffle_ps(a, b, 0xEE);
    }
  const __m512i first = _mm512_setr_epi32(0, 1, 2, 3, 16, 17, 18, 19, 8, 9, 10, 11, 24, 25, 26, 27);
  const __m512i second = _mm512_setr_epi32(4, 5, 6, 7, 20, 21, 22, 23, 12, 13, 14, 15, 28, 29, 30, 31);
  VF c[8];
  for (int k = 0; k < 4; ++k) {
    c[k].raw = _mm512_permutex2var_ps(s[k], first, s[4 + k]);
    c[4 + k].raw = _mm512_permutex2var_ps(s[k], second, s[4 + k]);
  }
  (void)d;
  return {{c[0], c[1], c[2]}, {c[3], c[4], c[5]}, c[6], c[7]};
}
#else
HWY_INLINE VertexV loadVertices(DF d, const float* vertices, const std::int32_t* index) {
  return gatherVertex(d, vertices, hn::Load(DI(), index));
}
#endif

// Texture::texel for texel index `at` (y * width + x).
HWY_INLINE V3 texel(DF d, const Texture& t, VI at) {
  if (!t.packed.empty()) {
    const DU du;
    const DI di;
    const auto c = hn::GatherIndex(du, t.packed.data(), at);
    const auto m = hn::Set(du, 255u);
    const auto r = hn::BitCast(di, hn::And(c, m)), g = hn::BitCast(di, hn::And(hn::ShiftRight<8>(c), m)),
               b = hn::BitCast(di, hn::ShiftRight<16>(c));
    if (t.codes_are_c_over_255) {  // code_value[c] == c / 255: divide instead of a table gather
      const VF k = hn::Set(d, 255.0f);
      return {hn::ConvertTo(d, r) / k, hn::ConvertTo(d, g) / k, hn::ConvertTo(d, b) / k};
    }
    const float* cv = t.code_value.data();
    return {hn::GatherIndex(d, cv, r), hn::GatherIndex(d, cv, g), hn::GatherIndex(d, cv, b)};
  }
  const VI a3 = at * hn::Set(DI(), 3);
  return {gather3(d, t.rgb.data(), a3, 0), gather3(d, t.rgb.data(), a3, 1), gather3(d, t.rgb.data(), a3, 2)};
}

// Texture::lookup<float>.
HWY_INLINE V3 lookup(DF d, const Texture& t, TextureFilter f, VF u, VF v) {
  const DI di;
  // Texture::lookup's frac, NaN (a non-finite u or v) -> 0.
  const VF fu0 = u - hn::Floor(u), fv0 = v - hn::Floor(v);
  const VF zero = hn::Zero(d), one1 = hn::Set(d, 1.0f);
  const VF fu = hn::IfThenElseZero(hn::And(fu0 >= zero, fu0 <= one1), fu0);
  const VF fv = hn::IfThenElseZero(hn::And(fv0 >= zero, fv0 <= one1), fv0);
  const VF w = hn::Set(d, float(t.width)), h = hn::Set(d, float(t.height));
  if (f == TextureFilter::Nearest) {
    const VI ix = hn::Min(hn::ConvertTo(di, fu * w), hn::Set(di, t.width - 1));
    const VI iy = hn::Min(hn::ConvertTo(di, fv * h), hn::Set(di, t.height - 1));
    return texel(d, t, iy * hn::Set(di, t.width) + ix);
  }
  const VF half = hn::Set(d, 0.5f), one = hn::Set(d, 1.0f);
  const VF x = fu * w - half, y = fv * h - half;
  const VF x0f = hn::Floor(x), y0f = hn::Floor(y);
  const VF wx = x - x0f, wy = y - y0f;
  VI x0 = hn::ConvertTo(di, x0f), y0 = hn::ConvertTo(di, y0f);
  VI x1 = x0 + hn::Set(di, 1), y1 = y0 + hn::Set(di, 1);
  const VI W = hn::Set(di, t.width), H = hn::Set(di, t.height), izero = hn::Zero(di);
  x0 = hn::IfThenElse(x0 < izero, x0 + W, x0);
  y0 = hn::IfThenElse(y0 < izero, y0 + H, y0);
  x1 = hn::IfThenElse(x1 < W, x1, x1 - W);
  y1 = hn::IfThenElse(y1 < H, y1, y1 - H);
  const VI r0 = y0 * W, r1 = y1 * W;
  const V3 t00 = texel(d, t, r0 + x0), t10 = texel(d, t, r0 + x1);
  const V3 t01 = texel(d, t, r1 + x0), t11 = texel(d, t, r1 + x1);
  const VF wx1 = one - wx, wy1 = one - wy;
  const V3 top = add(mul(wx1, t00), mul(wx, t10));
  const V3 bottom = add(mul(wx1, t01), mul(wx, t11));
  return add(mul(wy1, top), mul(wy, bottom));
}

constexpr size_t kMaxLanes = HWY_MAX_BYTES / sizeof(float);

// sampleLight<float> for every lane; lit lanes in `lit`.
HWY_INLINE void sampleLight(DF d, const PreparedLight<float>& l, V3 p, V3& L, VF& att, MF& lit) {
  using K = PreparedLight<float>::Kind;
  att = hn::Set(d, 1.0f);
  lit = hn::FirstN(d, hn::Lanes(d));  // all true
  if (l.kind == K::Directional) {
    L = splat(d, -l.direction);
    return;
  }
  const V3 D = sub(splat(d, l.position), p);
  const VF dd = dot(D, D);
  VF dist = hn::Sqrt(dd);
  L = {D.x / dist, D.y / dist, D.z / dist};
  const MF normal = hn::And(dd >= hn::Set(d, std::numeric_limits<float>::min()),
                            dd <= hn::Set(d, std::numeric_limits<float>::max()));
  if (!hn::AllTrue(d, normal)) {  // towardsLight's rescaling, lane by lane
    alignas(64) float dx[kMaxLanes], dy[kMaxLanes], dz[kMaxLanes], lx[kMaxLanes], ly[kMaxLanes],
        lz[kMaxLanes], ds[kMaxLanes];
    hn::Store(D.x, d, dx), hn::Store(D.y, d, dy), hn::Store(D.z, d, dz);
    hn::Store(L.x, d, lx), hn::Store(L.y, d, ly), hn::Store(L.z, d, lz), hn::Store(dist, d, ds);
    for (size_t k = 0; k < hn::Lanes(d); ++k) {
      const float q = dx[k] * dx[k] + dy[k] * dy[k] + dz[k] * dz[k];
      if (q >= std::numeric_limits<float>::min() && q <= std::numeric_limits<float>::max()) continue;
      glm::vec3 Lk;
      towardsLight(glm::vec3(dx[k], dy[k], dz[k]), Lk, ds[k]);
      lx[k] = Lk.x, ly[k] = Lk.y, lz[k] = Lk.z;
    }
    L = {hn::Load(d, lx), hn::Load(d, ly), hn::Load(d, lz)};
    dist = hn::Load(d, ds);
  }
  if (l.has_attenuation)
    att = hn::Set(d, 1.0f) / ((hn::Set(d, l.att_c) + hn::Set(d, l.att_l) * dist) + hn::Set(d, l.att_q) * dist * dist);
  if (l.kind == K::Spot) {
    const V3 minus_l = {hn::Neg(L.x), hn::Neg(L.y), hn::Neg(L.z)};
    lit = dot(minus_l, splat(d, l.direction)) >= hn::Set(d, l.cos_cutoff);
  }
}

// models::phongSpecular(reflect(n, L, x), v, shininess).
HWY_INLINE VF specular(DF d, float shininess, V3 n, V3 L, VF x, V3 v) {
  const VF two_x = hn::Set(d, 2.0f) * x;
  const V3 r = sub(mul(two_x, n), L);
  if (shininess == 0.0f) return hn::Set(d, 1.0f);
  const VF rdotv = dot(r, v);
  const V3 e = sub(r, v);
  const VF h = hn::Set(d, 0.5f) * dot(e, e);
  const MF need = hn::And(hn::And(rdotv > hn::Zero(d), h < hn::Set(d, 1.0f)),
                          hn::Not(hn::Set(d, shininess) * h > hn::Set(d, models::kSpecularCutoff<float>)));
  if (hn::AllFalse(d, need)) return hn::Zero(d);
  alignas(64) float hs[kMaxLanes], s[kMaxLanes];
  hn::Store(h, d, hs);
  hn::Store(hn::VecFromMask(d, need), d, s);
  for (size_t k = 0; k < hn::Lanes(d); ++k)
    s[k] = s[k] != 0.0f ? std::exp(shininess * std::log1p(-hs[k])) : 0.0f;
  return hn::Load(d, s);
}

// Hits per chunk: the kernel runs in three passes over a chunk so that
// the memory reads of many hits are in flight at once (the mesh and the
// texture each about the size of the L2 cache: a hit's vertex records and
// texels are often misses). Shading a hit in one pass chained a vertex miss,
// then a texel miss, then the lighting, hit after hit. Each value is still
// computed by the same operations; it only goes through memory (exactly)
// between the passes.
constexpr size_t kChunk = 256;
static_assert(kChunk % kMaxLanes == 0, "whole vectors per chunk");

void ShadeBatchImpl(const BatchShading& s, const BatchMesh& m, size_t count, const std::uint32_t* tri,
                    const float* b1p, const float* b2p, float* r_out, float* g_out, float* b_out) {
  const DF d;
  const size_t N = hn::Lanes(d);
  const VF one = hn::Set(d, 1.0f), zero = hn::Zero(d);
  alignas(64) std::int32_t idx[3][kChunk];
  alignas(64) float px[3][kChunk], nx[3][kChunk], uu[kChunk], vv_[kChunk];
  for (size_t k0 = 0; k0 < count; k0 += kChunk) {
    // Whole vectors: the arrays are padded to kBatchPad.
    const size_t end = std::min(count - k0, kChunk), vend = (end + N - 1) / N * N;
    // Pass 1: the hits' vertex indices, by scalar loads (independent, so
    // many in flight; a gather would put its latency in front of every
    // vertex gather).
    for (size_t q = 0; q < vend; ++q) {
      const glm::u32vec3& t = m.triangles[tri[k0 + q]];
      idx[0][q] = std::int32_t(t.x), idx[1][q] = std::int32_t(t.y), idx[2][q] = std::int32_t(t.z);
    }
    // Pass 2: the hit's position, normal and texture coordinates.
    for (size_t q = 0; q < vend; q += N) {
      const size_t k = k0 + q;
      const VF b1 = hn::LoadU(d, b1p + k), b2 = hn::LoadU(d, b2p + k);
      const VF b0 = (one - b1) - b2;
      // Phong mode: p, normal (renormalised; 0 stays 0), uv.
      const VertexV A = loadVertices(d, m.vertices.data(), idx[0] + q),
                    B = loadVertices(d, m.vertices.data(), idx[1] + q),
                    C = loadVertices(d, m.vertices.data(), idx[2] + q);
      const V3 p = add(add(mul(b0, A.p), mul(b1, B.p)), mul(b2, C.p));
      V3 n = add(add(mul(b0, A.n), mul(b1, B.n)), mul(b2, C.n));
      const VF len = hn::Sqrt(dot(n, n));
      const MF has_len = len > zero;
      n = {hn::IfThenElseZero(has_len, n.x / len), hn::IfThenElseZero(has_len, n.y / len),
           hn::IfThenElseZero(has_len, n.z / len)};
      hn::Store(p.x, d, px[0] + q), hn::Store(p.y, d, px[1] + q), hn::Store(p.z, d, px[2] + q);
      hn::Store(n.x, d, nx[0] + q), hn::Store(n.y, d, nx[1] + q), hn::Store(n.z, d, nx[2] + q);
      if (s.texture) {
        const VF u0 = A.u, v0 = A.v, u1 = B.u, v1 = B.v, u2 = C.u, v2 = C.v;
        hn::Store(((u0 - hn::Floor(u0)) + b1 * (u1 - u0)) + b2 * (u2 - u0), d, uu + q);
        hn::Store(((v0 - hn::Floor(v0)) + b1 * (v1 - v0)) + b2 * (v2 - v0), d, vv_ + q);
      }
    }
    // Pass 3: the texture colour (a short loop: the texel reads of several
    // vectors in flight), in place of u, v and a third array.
    alignas(64) float cb[kChunk];
    if (s.texture)
      for (size_t q = 0; q < vend; q += N) {
        const V3 c = lookup(d, *s.texture, s.filter, hn::Load(d, uu + q), hn::Load(d, vv_ + q));
        hn::Store(c.x, d, uu + q), hn::Store(c.y, d, vv_ + q), hn::Store(c.z, d, cb + q);
      }
    // Pass 4: the lighting.
    for (size_t q = 0; q < vend; q += N) {
    const size_t k = k0 + q;
    const V3 p = {hn::Load(d, px[0] + q), hn::Load(d, px[1] + q), hn::Load(d, px[2] + q)};
    const V3 n = {hn::Load(d, nx[0] + q), hn::Load(d, nx[1] + q), hn::Load(d, nx[2] + q)};
    const V3 to_eye = {zero - p.x, zero - p.y, zero - p.z};
    const VF inv = one / hn::Sqrt(dot(to_eye, to_eye));
    const V3 v = mul(to_eye, V3{inv, inv, inv});
    V3 c;
    if (s.texture) {
      c = {hn::Load(d, uu + q), hn::Load(d, vv_ + q), hn::Load(d, cb + q)};
    } else {
      c = splat(d, s.base);
    }
    V3 out;
    if (s.model == BatchShading::Model::YiqLuma) {
      VF dsum = zero, ssum = zero;
      for (const auto& l : s.lights) {
        V3 L;
        VF att;
        MF lit;
        sampleLight(d, l, p, L, att, lit);
        const VF w = att * hn::Set(d, l.color_luma);
        const VF x = dot(n, L);
        dsum = hn::IfThenElse(lit, dsum + w * saturate(d, x), dsum);
        if (s.specular) ssum = hn::IfThenElse(lit, ssum + w * specular(d, s.shininess, n, L, x, v), ssum);
      }
      const VF dl = saturate(d, hn::Set(d, s.ambient_luma) + hn::Set(d, s.kd) * dsum);
      const VF luma = (hn::Set(d, float(models::kRgbToYiq[0][0])) * c.x +
                       hn::Set(d, float(models::kRgbToYiq[0][1])) * c.y) +
                      hn::Set(d, float(models::kRgbToYiq[0][2])) * c.z;
      const VF dy = (luma * (dl - one) + hn::Set(d, s.ks) * ssum) - hn::Set(d, s.luma_offset);
      out = {c.x + dy, c.y + dy, c.z + dy};
    } else {  // classic Phong, variant paper
      V3 diff{zero, zero, zero}, spec{zero, zero, zero};
      for (const auto& l : s.lights) {
        V3 L;
        VF att;
        MF lit;
        sampleLight(d, l, p, L, att, lit);
        const V3 w = mul(att, splat(d, l.color));
        const VF x = dot(n, L);
        const V3 nd = add(diff, mul(w, V3{clamp0(d, x), clamp0(d, x), clamp0(d, x)}));
        diff = {hn::IfThenElse(lit, nd.x, diff.x), hn::IfThenElse(lit, nd.y, diff.y),
                hn::IfThenElse(lit, nd.z, diff.z)};
        if (s.specular) {
          const VF S = specular(d, s.shininess, n, L, x, v);
          const V3 ns = add(spec, mul(w, V3{S, S, S}));
          spec = {hn::IfThenElse(lit, ns.x, spec.x), hn::IfThenElse(lit, ns.y, spec.y),
                  hn::IfThenElse(lit, ns.z, spec.z)};
        }
      }
      const V3 lighting = add(mul(hn::Set(d, s.ka), splat(d, s.ambient)), mul(hn::Set(d, s.kd), diff));
      out = add(mul(c, lighting), mul(hn::Set(d, s.ks), spec));
    }
    hn::StoreU(saturate(d, out.x), d, r_out + k);
    hn::StoreU(saturate(d, out.y), d, g_out + k);
    hn::StoreU(saturate(d, out.z), d, b_out + k);
    }
  }
}

const char* TargetNameImpl() { return hwy::TargetName(HWY_TARGET); }

}  // namespace HWY_NAMESPACE
}  // namespace xval
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace xval {

HWY_EXPORT(ShadeBatchImpl);
HWY_EXPORT(TargetNameImpl);

void shadeBatch(const BatchShading& s, const BatchMesh& m, size_t count, const std::uint32_t* tri,
                const float* b1, const float* b2, float* r, float* g, float* b) {
  HWY_DYNAMIC_DISPATCH(ShadeBatchImpl)(s, m, count, tri, b1, b2, r, g, b);
}

BatchMesh batchMesh(const std::vector<glm::vec3>& p, const std::vector<glm::vec3>& n,
                    const std::vector<glm::vec2>& uv, const std::vector<glm::u32vec3>& triangles) {
  BatchMesh m;
  m.vertices.resize(p.size() * kBatchVertexFloats);
  for (size_t i = 0; i < p.size(); ++i) {
    float* v = &m.vertices[i * kBatchVertexFloats];
    v[0] = p[i].x, v[1] = p[i].y, v[2] = p[i].z, v[3] = n[i].x, v[4] = n[i].y, v[5] = n[i].z;
    v[6] = uv[i].x, v[7] = uv[i].y;
  }
  m.triangles = triangles.data();
  return m;
}

const char* batchShaderTarget() { return HWY_DYNAMIC_DISPATCH(TargetNameImpl)(); }

std::optional<BatchShading> batchShading(const Scene& scene, const Texture* texture, glm::dvec3 eye) {
  if (scene.shading != ShadingMode::Phong) return std::nullopt;
  if (scene.material.texture && scene.material.texture->filter == TextureFilter::Trilinear) return std::nullopt;
  if (!scene.normalize_normal) return std::nullopt;  // the listing's normalize(R) is the scalar path's
  if (scene.material.luma_only) return std::nullopt;  // the luma-only mode is Shader<float>'s
  BatchShading s;
  // The kernel's models; the others are shaded one hit at a time.
  switch (modelId(scene.material.model)) {
    case ModelId::YiqLuma: {
      const auto& y = std::get<YiqLuma>(scene.material.model);
      s.model = BatchShading::Model::YiqLuma;
      s.kd = float(y.kd), s.ks = float(y.ks), s.shininess = float(y.shininess);
      s.luma_offset = float(y.luma_offset);
      s.specular = y.ks != 0.0;
      break;
    }
    case ModelId::ClassicPhong: {
      const auto& c = std::get<ClassicPhong>(scene.material.model);
      if (c.variant != ClassicPhong::Variant::Paper) return std::nullopt;
      s.model = BatchShading::Model::ClassicPhong;
      s.ka = float(c.ka), s.kd = float(c.kd), s.ks = float(c.ks), s.shininess = float(c.shininess);
      s.specular = c.ks != 0.0;
      break;
    }
    case ModelId::Lambert:
    case ModelId::WrapAround:
    case ModelId::Hemispherical:
    case ModelId::BiDirectional:
    case ModelId::Trilight:
    case ModelId::Minnaert:     // issue #33's models: shaded one hit at a
    case ModelId::BlinnPhong:   // time by Shader<float>, the fast path's
    case ModelId::OrenNayar:    // scalar form
    case ModelId::CookTorrance: return std::nullopt;
  }
  prepareLights<float>(scene.lights, s.ambient, s.lights, eye);
  s.ambient_luma = models::lightLuma(s.ambient);
  s.texture = texture;
  s.filter = scene.material.texture ? scene.material.texture->filter : TextureFilter::Nearest;
  s.base = glm::vec3(scene.material.base_color);
  return s;
}

}  // namespace xval
#endif
