#include "validate/geometry_check.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>
#include <stdexcept>

namespace xval::validation {

namespace {

struct Neighbourhood {
  bool silhouette = false;
  bool depth_edge = false;
};

Neighbourhood neighbourhood(const GeometryPasses& r, int x, int y) {
  const size_t p = size_t(y) * r.width + x;
  Neighbourhood n;
  auto at = [&](int dx, int dy) -> std::optional<size_t> {
    const int xx = x + dx, yy = y + dy;
    if (xx < 0 || yy < 0 || xx >= r.width || yy >= r.height) return std::nullopt;
    return size_t(yy) * r.width + xx;
  };
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx)
      if (const auto q = at(dx, dy); q && (r.hit[*q] != r.hit[p] || r.object[*q] != r.object[p])) n.silhouette = true;
  if (r.hit[p] < 0.5f) return n;
  // 1/z is affine across the image on a plane: its second difference
  // through p, along each of the four lines of the 3 x 3 block, is 0 up to
  // the surface's curvature, and large where the line crosses onto another
  // surface.
  const double w = 1.0 / r.depth[p];
  for (const auto& [dx, dy] : {std::pair{1, 0}, {0, 1}, {1, 1}, {1, -1}}) {
    const auto a = at(dx, dy), b = at(-dx, -dy);
    if (!a || !b || r.hit[*a] < 0.5f || r.hit[*b] < 0.5f) continue;
    if (std::abs(1.0 / r.depth[*a] + 1.0 / r.depth[*b] - 2.0 * w) > kDepthEdgeRatio * w) n.depth_edge = true;
  }
  return n;
}

}  // namespace

GeometryMetrics compareGeometry(const GeometryPasses& r, const GeometryPasses& b, const GeometryTolerance& tol) {
  if (r.width != b.width || r.height != b.height)
    throw std::runtime_error("geometry passes of " + std::to_string(b.width) + "x" + std::to_string(b.height) +
                             " against the reference's " + std::to_string(r.width) + "x" + std::to_string(r.height));
  GeometryMetrics m;
  for (int y = 0; y < r.height; ++y)
    for (int x = 0; x < r.width; ++x) {
      const size_t p = size_t(y) * r.width + x;
      const bool rh = r.hit[p] > 0.5f, bh = b.hit[p] > 0.5f;
      if (rh) ++m.covered;
      const Neighbourhood n = neighbourhood(r, x, y);
      if (rh != bh || (rh && r.object[p] != b.object[p])) {
        ++m.mask_off;
        if (n.silhouette) ++m.mask_off_silhouette;
        continue;
      }
      if (!rh) continue;
      ++m.compared;
      const double dz = std::abs(double(b.depth[p]) - r.depth[p]) / std::abs(double(r.depth[p]));
      m.max_depth_rel_all = std::max(m.max_depth_rel_all, dz);
      bool over = false;
      if (n.depth_edge) over = dz > tol.max_depth_rel;
      else m.max_depth_rel = std::max(m.max_depth_rel, dz);
      if (r.has_uv[p] > 0.5f) {
        const double duv = std::max(std::abs(double(b.u[p]) - r.u[p]), std::abs(double(b.v[p]) - r.v[p]));
        m.max_uv_all = std::max(m.max_uv_all, duv);
        if (n.depth_edge || r.edge[p] < kTriangleEdgeBarycentric) {
          over = over || duv > tol.max_uv;
        } else {
          ++m.uv_compared;
          m.max_uv = std::max(m.max_uv, duv);
        }
      }
      if (n.depth_edge) ++m.depth_edges;
      if (over) ++m.edge_over;
    }
  const double covered = double(std::max<long long>(m.covered, 1));
  if (m.covered == 0) m.why = "the reference hits no pixel: nothing to compare";
  else if (m.mask_off > m.mask_off_silhouette)
    m.why = std::to_string(m.mask_off - m.mask_off_silhouette) + " pixels off the silhouette disagree in hit or object";
  else if (m.mask_off_silhouette > tol.max_silhouette_fraction * covered)
    m.why = std::to_string(m.mask_off_silhouette) + " silhouette pixels disagree in hit or object (at most " +
            std::to_string(tol.max_silhouette_fraction * 100) + "% of " + std::to_string(m.covered) + ")";
  else if (m.max_depth_rel > tol.max_depth_rel)
    m.why = "relative depth error " + std::to_string(m.max_depth_rel) + " > " + std::to_string(tol.max_depth_rel);
  else if (m.max_uv > tol.max_uv)
    m.why = "uv error " + std::to_string(m.max_uv) + " > " + std::to_string(tol.max_uv);
  else if (m.edge_over > tol.max_edge_fraction * covered)
    m.why = std::to_string(m.edge_over) + " depth- or triangle-edge pixels over the depth or uv bound (at most " +
            std::to_string(tol.max_edge_fraction * 100) + "% of " + std::to_string(m.covered) + ")";
  m.pass = m.why.empty();
  return m;
}

nlohmann::json metricsJson(const GeometryMetrics& m) {
  return {{"covered", m.covered},
          {"mask_disagree", m.mask_off},
          {"mask_disagree_silhouette", m.mask_off_silhouette},
          {"compared", m.compared},
          {"max_depth_rel", m.max_depth_rel},
          {"max_depth_rel_all", m.max_depth_rel_all},
          {"uv_compared", m.uv_compared},
          {"max_uv", m.max_uv},
          {"max_uv_all", m.max_uv_all},
          {"depth_edges", m.depth_edges},
          {"edge_over", m.edge_over}};
}

nlohmann::json boundsJson(const GeometryTolerance& tol) {
  return {{"max_silhouette_fraction", tol.max_silhouette_fraction},
          {"max_depth_rel", tol.max_depth_rel},
          {"max_uv", tol.max_uv},
          {"max_edge_fraction", tol.max_edge_fraction},
          {"reason", tol.reason}};
}

nlohmann::json toJson(const GeometryMetrics& m, const GeometryTolerance& tol) {
  nlohmann::json j = {{"pass", m.pass}, {"why", m.why}};
  j.update(metricsJson(m));
  j["tolerance"] = boundsJson(tol);
  return j;
}

}  // namespace xval::validation
