#include "render/accel.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "geometry/float_rounding.h"
#include "render/ray_triangle.h"

namespace xval {

struct Accel::DoubleGeometry {
  const TriangleMesh* mesh;
  uint32_t id;
  float pad;  // outward padding of every box, in scene units
  const std::vector<uint32_t>* only;  // primitive -> triangle (nullptr: the same)
  uint32_t triangle(uint32_t prim) const { return only ? (*only)[prim] : prim; }
};

namespace {

// Embree reports errors through a C callback: remember the message, and
// checkDevice() turns it into an exception on our side of the call.
void embreeError(void* user, RTCError, const char* str) {
  *static_cast<std::string*>(user) = str ? str : "unknown error";
}

// The ray query's context: Embree passes it to the callbacks. Up to 16
// rays (a packet); the callback finds its ray's slot by the ray's id.
struct DoubleContext {
  RTCIntersectContext embree;  // must be first
  RayShear shear[16];
  double best_t[16];
  Hit hit[16];
};

// The float32 nearest to v, then one step outwards if that was on the
// wrong side of v (nearestFloat: the comparison needs the rounded value).
float roundUp(double v) {
  float f = nearestFloat(v);
  return double(f) < v ? std::nextafter(f, std::numeric_limits<float>::infinity()) : f;
}
float roundDown(double v) {
  float f = nearestFloat(v);
  return double(f) > v ? std::nextafter(f, -std::numeric_limits<float>::infinity()) : f;
}

void boundsFn(const RTCBoundsFunctionArguments* args) {
  auto* g = static_cast<const Accel::DoubleGeometry*>(args->geometryUserPtr);
  const auto& tri = g->mesh->triangles[g->triangle(args->primID)];
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-lo);
  for (int k = 0; k < 3; ++k) {
    lo = glm::min(lo, g->mesh->positions[tri[k]]);
    hi = glm::max(hi, g->mesh->positions[tri[k]]);
  }
  RTCBounds* b = args->bounds_o;
  b->lower_x = roundDown(lo.x) - g->pad, b->lower_y = roundDown(lo.y) - g->pad;
  b->lower_z = roundDown(lo.z) - g->pad;
  b->upper_x = roundUp(hi.x) + g->pad, b->upper_y = roundUp(hi.y) + g->pad;
  b->upper_z = roundUp(hi.z) + g->pad;
}

void intersectFn(const RTCIntersectFunctionNArguments* args) {
  auto* g = static_cast<const Accel::DoubleGeometry*>(args->geometryUserPtr);
  auto* ctx = reinterpret_cast<DoubleContext*>(args->context);
  const uint32_t triangle = g->triangle(args->primID);
  const auto& tri = g->mesh->triangles[triangle];
  const auto& P = g->mesh->positions;
  auto* ray = reinterpret_cast<RTCRayN*>(args->rayhit);
  for (unsigned lane = 0; lane < args->N; ++lane) {
    if (!args->valid[lane]) continue;
    const unsigned r = RTCRayN_id(ray, args->N, lane);  // our slot
    TriangleHit th;
    if (!intersectTriangle(ctx->shear[r], P[tri[0]], P[tri[1]], P[tri[2]], 0.0, ctx->best_t[r], th))
      continue;
    ctx->best_t[r] = th.t;
    ctx->hit[r] = {true, g->id, triangle, th.t, th.b1, th.b2};
    // Shrink Embree's float t_far conservatively (rounded up, padded).
    float& tfar = RTCRayN_tfar(ray, args->N, lane);
    tfar = std::min(tfar, roundUp(th.t * (1.0 + 1e-6)));
  }
}

}  // namespace

Accel::Accel(const std::vector<TriangleMesh>& meshes, Precision precision,
             const std::vector<std::optional<std::vector<uint32_t>>>& only)
    : precision_(precision), only_(only) {
  only_.resize(meshes.size());
  device_ = rtcNewDevice(nullptr);
  if (!device_) throw std::runtime_error("Embree: cannot create a device");
  rtcSetDeviceErrorFunction(device_, embreeError, &error_);
  scene_ = rtcNewScene(device_);
  rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_HIGH);

  // Padding for the double path: relative to the scene's size.
  double extent = 0.0;
  for (const auto& m : meshes)
    for (const auto& p : m.positions) extent = std::max(extent, glm::length(p));

  for (uint32_t id = 0; id < meshes.size(); ++id) {
    const TriangleMesh& m = meshes[id];
    RTCGeometry geom;
    if (precision == Precision::Float) {
      geom = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
      auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(
          geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float),
          m.positions.size()));
      for (size_t i = 0; i < m.positions.size(); ++i)
        for (int k = 0; k < 3; ++k) v[i * 3 + k] = float(m.positions[i][k]);
      const size_t prims = only_[id] ? only_[id]->size() : m.triangles.size();
      auto* ix = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(
          geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(uint32_t), prims));
      for (size_t i = 0; i < prims; ++i)
        for (int k = 0; k < 3; ++k) ix[i * 3 + k] = m.triangles[triangleOf(id, uint32_t(i))][k];
    } else {
      double_geoms_.push_back(std::make_unique<DoubleGeometry>(
          DoubleGeometry{&m, id, float(std::max(extent, 1e-30) * 1e-5), only_[id] ? &*only_[id] : nullptr}));
      geom = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_USER);
      rtcSetGeometryUserPrimitiveCount(geom, unsigned(only_[id] ? only_[id]->size() : m.triangles.size()));
      rtcSetGeometryUserData(geom, double_geoms_.back().get());
      rtcSetGeometryBoundsFunction(geom, boundsFn, nullptr);
      rtcSetGeometryIntersectFunction(geom, intersectFn);
    }
    rtcCommitGeometry(geom);
    rtcAttachGeometryByID(scene_, geom, id);
    rtcReleaseGeometry(geom);
  }
  rtcCommitScene(scene_);
  if (rtcGetDeviceError(device_) != RTC_ERROR_NONE || !error_.empty())
    throw std::runtime_error("Embree: building the scene failed: " + error_);
}

Accel::~Accel() {
  if (scene_) rtcReleaseScene(scene_);
  if (device_) rtcReleaseDevice(device_);
}

Hit Accel::intersect(glm::dvec3 origin, glm::dvec3 dir) const {
  return precision_ == Precision::Float ? intersectFloat(origin, dir)
                                        : intersectDouble(origin, dir);
}

namespace {
// An Embree ray from (o, d), rounded to float, with no hit yet.
RTCRayHit embreeRay(glm::dvec3 o, glm::dvec3 d) {
  RTCRayHit rh{};
  rh.ray.org_x = float(o.x), rh.ray.org_y = float(o.y), rh.ray.org_z = float(o.z);
  rh.ray.dir_x = float(d.x), rh.ray.dir_y = float(d.y), rh.ray.dir_z = float(d.z);
  rh.ray.tnear = 0.0f;
  rh.ray.tfar = std::numeric_limits<float>::infinity();
  rh.ray.mask = 0xFFFFFFFFu;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  return rh;
}
}  // namespace

Hit Accel::intersectFloat(glm::dvec3 o, glm::dvec3 d) const {
  RTCIntersectContext ctx;
  rtcInitIntersectContext(&ctx);
  RTCRayHit rh = embreeRay(o, d);
  rtcIntersect1(scene_, &ctx, &rh);
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return {};
  return {true, rh.hit.geomID, triangleOf(rh.hit.geomID, rh.hit.primID), rh.ray.tfar, rh.hit.u, rh.hit.v};
}

void Accel::intersectPacket(glm::dvec3 o, const glm::dvec3* dirs, const bool* valid, Hit* out) const {
  constexpr int N = kPacketSide * kPacketSide;
  static_assert(N == 16, "the float path uses Embree's 16-ray packets");
  // The double path traverses Embree's BVH as a packet too; every candidate
  // is decided by the double watertight test in intersectFn, per ray.
  const bool exact = precision_ == Precision::Double;
  DoubleContext dctx;
  if (exact) {
    for (int r = 0; r < N; ++r) {
      if (valid[r]) dctx.shear[r] = RayShear(o, dirs[r]);
      dctx.best_t[r] = std::numeric_limits<double>::infinity();
    }
  }
  RTCIntersectContext& ctx = dctx.embree;
  rtcInitIntersectContext(&ctx);
  ctx.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
  alignas(64) int mask[N];
  alignas(64) RTCRayHit16 rh;
  for (int r = 0; r < N; ++r) {
    mask[r] = valid[r] ? -1 : 0;
    const glm::dvec3 d = valid[r] ? dirs[r] : glm::dvec3(0, 0, 1);
    rh.ray.org_x[r] = float(o.x), rh.ray.org_y[r] = float(o.y), rh.ray.org_z[r] = float(o.z);
    rh.ray.dir_x[r] = float(d.x), rh.ray.dir_y[r] = float(d.y), rh.ray.dir_z[r] = float(d.z);
    rh.ray.tnear[r] = 0.0f;
    rh.ray.tfar[r] = std::numeric_limits<float>::infinity();
    rh.ray.time[r] = 0.0f;
    rh.ray.mask[r] = 0xFFFFFFFFu;
    rh.ray.id[r] = unsigned(r);
    rh.ray.flags[r] = 0;
    rh.hit.geomID[r] = RTC_INVALID_GEOMETRY_ID;
  }
  rtcIntersect16(mask, scene_, &ctx, &rh);
  if (exact) {
    for (int r = 0; r < N; ++r) out[r] = valid[r] ? dctx.hit[r] : Hit{};
    return;
  }
  for (int r = 0; r < N; ++r) {
    if (!valid[r] || rh.hit.geomID[r] == RTC_INVALID_GEOMETRY_ID) {
      out[r] = Hit{};
      continue;
    }
    out[r] = {true, rh.hit.geomID[r], triangleOf(rh.hit.geomID[r], rh.hit.primID[r]), rh.ray.tfar[r],
              rh.hit.u[r], rh.hit.v[r]};
  }
}

Hit Accel::intersectDouble(glm::dvec3 o, glm::dvec3 d) const {
  DoubleContext ctx;
  ctx.shear[0] = RayShear(o, d);
  ctx.best_t[0] = std::numeric_limits<double>::infinity();
  ctx.hit[0] = Hit{};
  rtcInitIntersectContext(&ctx.embree);
  RTCRayHit rh = embreeRay(o, d);
  rh.ray.id = 0;
  rtcIntersect1(scene_, &ctx.embree, &rh);
  return ctx.hit[0];
}

}  // namespace xval
