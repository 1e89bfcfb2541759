#include "geometry/closed_surface.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <thread>
#include <vector>

#include "process/job_pool.h"

namespace xval {

namespace {

using glm::dvec3;

std::string tri(size_t t) { return "triangle " + std::to_string(t); }

// Condition 2, and the components: union-find over the triangles, joined
// across each edge.
struct Components {
  std::vector<uint32_t> parent;
  explicit Components(size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
  uint32_t find(uint32_t a) {
    while (parent[a] != a) a = parent[a] = parent[parent[a]];
    return a;
  }
  void join(uint32_t a, uint32_t b) {
    a = find(a), b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

std::string closedAndOriented(const TriangleMesh& m, Components& comp) {
  // The edges grouped by their lower vertex index (a counting sort), each
  // with its higher index, its triangle and the direction it runs.
  struct Edge {
    uint32_t hi, t;
    bool forward;  // the triangle runs lo -> hi
  };
  const size_t nv = m.positions.size();
  std::vector<uint32_t> start(nv + 1, 0);
  for (const glm::u32vec3& v : m.triangles)
    for (int k = 0; k < 3; ++k) ++start[std::min(v[k], v[(k + 1) % 3]) + 1];
  for (size_t i = 0; i < nv; ++i) start[i + 1] += start[i];
  std::vector<Edge> e(static_cast<size_t>(start[nv]));
  std::vector<uint32_t> fill(start.begin(), start.end() - 1);
  for (uint32_t t = 0; t < m.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const uint32_t a = m.triangles[t][k], b = m.triangles[t][(k + 1) % 3];
      e[fill[std::min(a, b)]++] = {std::max(a, b), t, a < b};
    }
  for (uint32_t lo = 0; lo < nv; ++lo) {
    Edge* first = e.data() + start[lo];
    Edge* last = e.data() + start[lo + 1];
    std::sort(first, last, [](const Edge& x, const Edge& y) { return x.hi < y.hi || (x.hi == y.hi && x.t < y.t); });
    for (Edge* i = first; i < last;) {
      Edge* j = i;
      while (j < last && j->hi == i->hi) ++j;
      auto edge = [&] { return "edge " + std::to_string(lo) + "-" + std::to_string(i->hi); };
      if (j - i != 2)
        return "not closed: " + edge() + " belongs to " + std::to_string(j - i) + " triangle(s), not 2 (" +
               tri(i->t) + ")";
      if (i[0].forward == i[1].forward)
        return "inconsistent winding: " + tri(i[0].t) + " and " + tri(i[1].t) + " run " + edge() +
               " the same way";
      comp.join(i[0].t, i[1].t);
      i = j;
    }
  }
  return {};
}

// Does direction x (from the corner's apex) lie in the closed corner
// spanned by p and q (normal n = p x q)? With slack `tol` relative.
bool inCorner(dvec3 x, dvec3 p, dvec3 q, dvec3 n, double tol) {
  const double nn = glm::dot(n, n);
  // x = alpha p + beta q + (normal part): alpha = (x x q) . n / |n|^2,
  // beta = (p x x) . n / |n|^2; scaled to lengths along p and q over |x|.
  const double scale = glm::length(x);
  const double alpha = glm::dot(glm::cross(x, q), n) / nn * glm::length(p) / scale;
  const double beta = glm::dot(glm::cross(p, x), n) / nn * glm::length(q) / scale;
  return alpha >= -tol && beta >= -tol;
}

// Two corners with apex v (T1: edge vectors p, q; T2: r, s) projected on
// T1's plane overlap beyond v? (One holds an edge direction of the other.)
bool cornersOverlapOnPlaneOf(dvec3 p, dvec3 q, dvec3 r, dvec3 s, double tol) {
  const dvec3 n1 = glm::cross(p, q);
  // T2's directions projected onto T1's plane; its normal there is the
  // projected one's (sign as it comes: inCorner does not depend on it).
  const dvec3 u1 = glm::normalize(n1);
  const dvec3 rp = r - glm::dot(r, u1) * u1, sp = s - glm::dot(s, u1) * u1;
  const dvec3 n2p = glm::cross(rp, sp);
  if (!(glm::length(n2p) > 1e-9 * glm::length(rp) * glm::length(sp))) return true;  // edge-on: unsure
  return inCorner(rp, p, q, n1, tol) || inCorner(sp, p, q, n1, tol) || inCorner(p, rp, sp, n2p, tol) ||
         inCorner(q, rp, sp, n2p, tol);
}

bool sharedVertexOnly(dvec3 v, dvec3 a, dvec3 b, dvec3 c, dvec3 d) {
  constexpr double kTol = 1e-9;
  const dvec3 p = a - v, q = b - v, r = c - v, s = d - v;
  const dvec3 n1 = glm::cross(p, q), n2 = glm::cross(r, s);
  // The quick case: T2's other corners strictly on one side of T1's plane
  // (or T1's of T2's), so that T2 meets the plane only at v.
  auto oneSide = [&](dvec3 n, dvec3 x, dvec3 y) {
    const double ex = glm::dot(n, x), ey = glm::dot(n, y);
    const double margin = kTol * glm::length(n) * std::max(glm::length(x), glm::length(y));
    return (ex > margin && ey > margin) || (ex < -margin && ey < -margin);
  };
  if (oneSide(n1, r, s) || oneSide(n2, p, q)) return true;
  const dvec3 u = glm::cross(n1, n2);
  if (glm::length(u) > 1e-3 * glm::length(n1) * glm::length(n2)) {
    // The planes cross in v + t u (well conditioned): a common direction is +u or -u.
    const bool plus = inCorner(u, p, q, n1, kTol) && inCorner(u, r, s, n2, kTol);
    const bool minus = inCorner(-u, p, q, n1, kTol) && inCorner(-u, r, s, n2, kTol);
    if (!plus && !minus) return true;
  }
  return !cornersOverlapOnPlaneOf(p, q, r, s, kTol) || !cornersOverlapOnPlaneOf(r, s, p, q, kTol);
}

// Separating-axis test for two triangles sharing no vertex: true when some
// axis separates them by more than gap (gap in units of length).
bool separated(const dvec3 A[3], const dvec3 B[3], double gap) {
  const dvec3 ea[3] = {A[1] - A[0], A[2] - A[1], A[0] - A[2]};
  const dvec3 eb[3] = {B[1] - B[0], B[2] - B[1], B[0] - B[2]};
  const dvec3 na = glm::cross(ea[0], ea[1]), nb = glm::cross(eb[0], eb[1]);
  auto by = [&](dvec3 axis) {
    const double len = glm::length(axis);
    if (!(len > 0.0)) return false;
    double a0 = glm::dot(A[0], axis), a1 = a0, b0 = glm::dot(B[0], axis), b1 = b0;
    for (int k = 1; k < 3; ++k) {
      const double x = glm::dot(A[k], axis), y = glm::dot(B[k], axis);
      a0 = std::min(a0, x), a1 = std::max(a1, x), b0 = std::min(b0, y), b1 = std::max(b1, y);
    }
    return b0 - a1 > gap * len || a0 - b1 > gap * len;
  };
  if (by(na) || by(nb)) return true;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (by(glm::cross(ea[i], eb[j]))) return true;
  for (int i = 0; i < 3; ++i)
    if (by(glm::cross(na, ea[i])) || by(glm::cross(nb, eb[i]))) return true;
  return false;
}

// The embedding test of one candidate pair (see the header).
bool meetOnlyAsIndexed(const TriangleMesh& m, uint32_t t1, uint32_t t2, double gap) {
  const glm::u32vec3 i1 = m.triangles[t1], i2 = m.triangles[t2];
  int shared = 0, s1[3], s2[3];
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b)
      if (i1[a] == i2[b]) s1[shared] = a, s2[shared] = b, ++shared;
  const dvec3 A[3] = {m.positions[i1[0]], m.positions[i1[1]], m.positions[i1[2]]};
  const dvec3 B[3] = {m.positions[i2[0]], m.positions[i2[1]], m.positions[i2[2]]};
  if (shared == 0) return separated(A, B, gap);
  if (shared == 1) {
    const int a = s1[0], b = s2[0];
    return sharedVertexOnly(A[a], A[(a + 1) % 3], A[(a + 2) % 3], B[(b + 1) % 3], B[(b + 2) % 3]);
  }
  if (shared == 2) {
    const dvec3 n1 = glm::normalize(glm::cross(A[1] - A[0], A[2] - A[0]));
    const dvec3 n2 = glm::normalize(glm::cross(B[1] - B[0], B[2] - B[0]));
    return !(glm::dot(n1, n2) < 0.0 && glm::length(glm::cross(n1, n2)) < 1e-6);
  }
  return false;  // the same three vertices twice
}

// Condition 3 over all candidate pairs.
std::string embedded(const TriangleMesh& m) {
  const size_t n = m.triangles.size();
  dvec3 lo(INFINITY), hi(-INFINITY);
  for (const dvec3& p : m.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
  const double extent = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z, 0.0});
  const double gap = 1e-10 * std::max({extent, glm::length(lo), glm::length(hi)});
  // Cells about as large as the mean triangle box; at most 2^13 per axis.
  std::vector<dvec3> bmin(n), bmax(n);
  double mean_side = 0.0;
  for (size_t t = 0; t < n; ++t) {
    const dvec3 a = m.positions[m.triangles[t][0]], b = m.positions[m.triangles[t][1]],
                c = m.positions[m.triangles[t][2]];
    bmin[t] = glm::min(glm::min(a, b), c) - gap, bmax[t] = glm::max(glm::max(a, b), c) + gap;
    const dvec3 side = bmax[t] - bmin[t];
    mean_side += std::max({side.x, side.y, side.z}) / double(n);
  }
  const double cell = std::max({mean_side, extent / 8000.0, 1e-300});
  auto cellOf = [&](double x, double o) { return uint64_t(std::clamp((x - o) / cell, 0.0, 8190.0)); };
  const dvec3 origin = lo - 2.0 * gap;
  // Entries (cell << 24 | triangle): triangles < 2^24 (the scene budget's
  // largest mesh); more, or too many entries, is "not checked".
  if (n >= (size_t(1) << 24)) return "not checked: more than 2^24 triangles";
  std::vector<uint64_t> entries;
  entries.reserve(n * 4);
  const size_t most = 64 * n + (size_t(1) << 20);
  for (size_t t = 0; t < n; ++t) {
    const uint64_t x0 = cellOf(bmin[t].x, origin.x), x1 = cellOf(bmax[t].x, origin.x);
    const uint64_t y0 = cellOf(bmin[t].y, origin.y), y1 = cellOf(bmax[t].y, origin.y);
    const uint64_t z0 = cellOf(bmin[t].z, origin.z), z1 = cellOf(bmax[t].z, origin.z);
    if ((x1 - x0 + 1) * (y1 - y0 + 1) * (z1 - z0 + 1) > most - entries.size())
      return "not checked: " + tri(t) + " spans too many grid cells";
    for (uint64_t z = z0; z <= z1; ++z)
      for (uint64_t y = y0; y <= y1; ++y)
        for (uint64_t x = x0; x <= x1; ++x) entries.push_back((((z << 13 | y) << 13 | x) << 24) | t);
  }
  std::sort(entries.begin(), entries.end());
  // The cells' runs of entries, split over the threads; the failure
  // reported is the one of the lowest cell (the same on any thread count).
  std::vector<size_t> run_start;
  for (size_t i = 0; i < entries.size(); ++i)
    if (i == 0 || (entries[i] >> 24) != (entries[i - 1] >> 24)) run_start.push_back(i);
  run_start.push_back(entries.size());
  const size_t runs = run_start.size() - 1;
  // Candidate pairs within the cells: bounded, or the check would be
  // quadratic (a million triangles around one vertex): "not checked".
  size_t pairs = 0;
  for (size_t r = 0; r < runs; ++r) {
    const size_t k = run_start[r + 1] - run_start[r];
    pairs += k * (k - 1) / 2;
  }
  if (pairs > 256 * n + (size_t(1) << 24))
    return "not checked: " + std::to_string(pairs) + " candidate pairs of triangles in the grid's cells";
  const unsigned threads = std::max(1u, std::min(8u, std::thread::hardware_concurrency()));
  std::vector<std::pair<uint32_t, uint32_t>> failed(threads, {UINT32_MAX, UINT32_MAX});
  std::vector<size_t> failed_run(threads, SIZE_MAX);
  auto work = [&](unsigned w) {
    for (size_t r = runs * w / threads; r < runs * (w + 1) / threads; ++r) {
      const size_t i = run_start[r], j = run_start[r + 1];
      const uint64_t c = entries[i] >> 24;
      for (size_t a = i; a < j; ++a)
        for (size_t b = a + 1; b < j; ++b) {
          const uint32_t t1 = uint32_t(entries[a] & 0xffffff), t2 = uint32_t(entries[b] & 0xffffff);
          const dvec3 omin = glm::max(bmin[t1], bmin[t2]), omax = glm::min(bmax[t1], bmax[t2]);
          if (omin.x > omax.x || omin.y > omax.y || omin.z > omax.z) continue;  // boxes apart
          // Each pair once: in the cell of its boxes' overlap's lowest corner.
          const uint64_t home = (cellOf(omin.z, origin.z) << 13 | cellOf(omin.y, origin.y)) << 13 |
                                cellOf(omin.x, origin.x);
          if (home != c) continue;
          if (!meetOnlyAsIndexed(m, t1, t2, gap)) {
            failed[w] = {t1, t2}, failed_run[w] = r;
            return;
          }
        }
    }
  };
  runJobPool(threads, int(threads), [&](size_t w) { work(unsigned(w)); });
  const size_t first = size_t(std::min_element(failed_run.begin(), failed_run.end()) - failed_run.begin());
  if (failed_run[first] != SIZE_MAX)
    return "not embedded: " + tri(failed[first].first) + " and " + tri(failed[first].second) +
           " may meet where they share no vertex";
  return {};
}

}  // namespace

std::string whyNotAnOutwardSolid(const TriangleMesh& m) {
  if (m.triangles.empty()) return "no triangles";
  for (size_t t = 0; t < m.triangles.size(); ++t) {  // condition 1
    const glm::u32vec3 v = m.triangles[t];
    if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2]) return "degenerate: " + tri(t) + " repeats a vertex";
    const dvec3 a = m.positions[v[0]], b = m.positions[v[1]], c = m.positions[v[2]];
    const double longest = std::max({glm::length(b - a), glm::length(c - b), glm::length(a - c)});
    if (!(glm::length(glm::cross(b - a, c - a)) > 1e-10 * longest * longest))
      return "degenerate: " + tri(t) + " has (almost) no area";
  }
  Components comp(m.triangles.size());
  if (std::string why = closedAndOriented(m, comp); !why.empty()) return why;
  // Condition 4: per component, the signed volume about its first vertex.
  std::vector<double> volume(m.triangles.size(), 0.0), magnitude(m.triangles.size(), 0.0);
  std::vector<uint32_t> apex(m.triangles.size(), UINT32_MAX);
  for (uint32_t t = 0; t < m.triangles.size(); ++t) {
    const uint32_t r = comp.find(t);
    if (apex[r] == UINT32_MAX) apex[r] = m.triangles[t][0];
    const dvec3 o = m.positions[apex[r]];
    const dvec3 a = m.positions[m.triangles[t][0]] - o, b = m.positions[m.triangles[t][1]] - o,
                c = m.positions[m.triangles[t][2]] - o;
    const double term = glm::dot(a, glm::cross(b, c)) / 6.0;
    volume[r] += term, magnitude[r] += std::abs(term);
  }
  for (uint32_t r = 0; r < m.triangles.size(); ++r)
    if (comp.parent[r] == r && !(volume[r] > 1e-9 * magnitude[r]))
      return "not outward: the component of " + tri(r) + " has signed volume " + std::to_string(volume[r]) +
             " (not positive beyond its rounding)";
  return embedded(m);  // condition 3, the dearest, last
}

}  // namespace xval
