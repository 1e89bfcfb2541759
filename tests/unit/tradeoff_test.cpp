// validate/tradeoff/sweep.h: the Pareto front on hand-made points, the sweep's
// rows, the tessellation scaling and the error of an image against a
// reference on hand-made images.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "scene_file/scene_loader.h"
#include "validate/tradeoff/sweep.h"

using namespace xval;

namespace {

std::vector<size_t> front(const std::vector<ParetoPoint>& p) { return paretoFront(p); }

Scene knotScene() {
  return loadScene(std::filesystem::path(XVAL_REFERENCE_DIR) / "scenes" / "table2_knot_yiq.json");
}

const TradeoffConfig* find(const std::vector<TradeoffConfig>& v, const std::string& id) {
  for (const auto& c : v)
    if (c.id == id) return &c;
  return nullptr;
}

}  // namespace

// (time, error): a staircase of 3 optimal points, with dominated points
// above and to the right of it; the front comes back sorted by time.
TEST(ParetoFront, StaircaseWithDominatedPoints) {
  std::vector<ParetoPoint> p = {
      {10.0, 1.0},   // 0: slow, accurate: optimal
      {1.0, 100.0},  // 1: fast, wrong: optimal
      {3.0, 10.0},   // 2: optimal
      {4.0, 10.0},   // 3: slower than 2, as wrong: dominated
      {3.0, 20.0},   // 4: as fast as 2, wronger: dominated
      {20.0, 50.0},  // 5: dominated by 0 and 2
  };
  EXPECT_EQ(front(p), (std::vector<size_t>{1, 2, 0}));
}

TEST(ParetoFront, EmptyAndSingle) {
  EXPECT_TRUE(front({}).empty());
  EXPECT_EQ(front({{2.0, 3.0}}), (std::vector<size_t>{0}));
}

// Equal points do not dominate each other: both stay.
TEST(ParetoFront, EqualPointsAreBothOptimal) {
  EXPECT_EQ(front({{1.0, 1.0}, {1.0, 1.0}, {2.0, 2.0}}), (std::vector<size_t>{0, 1}));
}

// One point better in both coordinates dominates all the others.
TEST(ParetoFront, OneDominatesAll) {
  EXPECT_EQ(front({{5, 5}, {1, 1}, {1, 5}, {5, 1}}), (std::vector<size_t>{1}));
}

// Same time, different errors: only the smaller error; same error,
// different times: only the faster.
TEST(ParetoFront, TiesInOneCoordinate) {
  EXPECT_EQ(front({{1, 3}, {1, 2}}), (std::vector<size_t>{1}));
  EXPECT_EQ(front({{2, 3}, {1, 3}}), (std::vector<size_t>{1}));
}

// Non-finite points are never optimal and dominate nothing.
TEST(ParetoFront, NonFinitePointsAreLeftOut) {
  const double nan = std::nan(""), inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(front({{nan, 0.0}, {1.0, 1.0}, {0.5, inf}, {2.0, 0.5}}), (std::vector<size_t>{1, 3}));
}

// Zero error is a valid point (the converged reference is left out by the
// caller, not here).
TEST(ParetoFront, ZeroErrorDominatesSlowerPoints) {
  EXPECT_EQ(front({{3.0, 0.0}, {4.0, 1.0}, {1.0, 5.0}}), (std::vector<size_t>{2, 0}));
}

TEST(Tradeoff, ValidSpp) {
  for (int n : {1, 4, 9, 16, 64, 144, 256}) EXPECT_TRUE(validSpp(n)) << n;
  for (int n : {0, 2, 8, 50, 255, 289, -4}) EXPECT_FALSE(validSpp(n)) << n;
}

TEST(Tradeoff, ScaledSegments) {
  EXPECT_EQ(scaledSegments(768, 4.0, 3), 3072);
  EXPECT_EQ(scaledSegments(40, 0.25, 3), 10);
  EXPECT_EQ(scaledSegments(10, 0.25, 3), 3);  // 2.5 rounds to 3 (and the minimum)
  EXPECT_EQ(scaledSegments(4, 0.1, 3), 3);
  EXPECT_EQ(scaledSegments(3, 0.5, 2), 2);
}

// The Table 2 scene's sweep: the documented rows, each changing one knob
// from the base (or the corners'), the converged row last.
TEST(Tradeoff, SweepOfTheTable2Scene) {
  const Scene s = knotScene();
  const auto v = sweepConfigs(s, SweepSettings{});
  const TradeoffConfig base = baseConfig(s);
  EXPECT_EQ(v.front().id, "base");
  EXPECT_EQ(base.spp, 1);
  EXPECT_EQ(base.precision, Precision::Double);
  EXPECT_EQ(base.shading, ShadingMode::Phong);
  ASSERT_TRUE(base.texture_filter.has_value());
  EXPECT_EQ(*base.texture_filter, TextureFilter::Bilinear);
  for (const char* id : {"spp=4", "spp=16", "spp=64", "tess=0.25", "tess=0.5", "tess=2", "precision=float",
                         "shading=flat", "shading=gouraud", "filter=nearest", "corner:fast",
                         "corner:fast-gouraud", "corner:float-4spp", "corner:float-16spp", "corner:accurate"})
    EXPECT_NE(find(v, id), nullptr) << id;
  EXPECT_EQ(find(v, "spp=1"), nullptr);  // the base already has 1 spp
  EXPECT_EQ(v.back().id, "converged");
  EXPECT_EQ(v.back().spp, 64);
  EXPECT_EQ(v.back().tessellation_factor, 4.0);
  EXPECT_EQ(v.back().precision, Precision::Double);
  EXPECT_EQ(v.size(), 17u);
  // One-knob rows differ from the base in exactly their knob.
  const TradeoffConfig* t = find(v, "tess=0.5");
  EXPECT_EQ(t->spp, base.spp);
  EXPECT_EQ(t->precision, base.precision);
  EXPECT_EQ(t->tessellation_factor, 0.5);
  // No two rows but "converged" have the same knobs.
  for (size_t i = 0; i + 1 < v.size(); ++i)
    for (size_t j = i + 1; j + 1 < v.size(); ++j) EXPECT_FALSE(v[i].sameKnobs(v[j])) << v[i].id << " " << v[j].id;

  const auto q = sweepConfigs(s, SweepSettings{16, 2.0, true});
  EXPECT_EQ(find(q, "spp=64"), nullptr);
  EXPECT_EQ(find(q, "tess=2"), nullptr);
  EXPECT_EQ(find(q, "corner:accurate"), nullptr);
}

TEST(Tradeoff, ConvergenceChecksAreOneStepFiner) {
  const Scene s = knotScene();
  const auto c = convergenceChecks(s, SweepSettings{});
  ASSERT_EQ(c.size(), 2u);
  EXPECT_EQ(c[0].tessellation_factor, 8.0);
  EXPECT_EQ(c[0].spp, 64);
  EXPECT_EQ(c[1].tessellation_factor, 4.0);
  EXPECT_EQ(c[1].spp, 256);
  // At 256 spp there is no finer sampling: only the tessellation check.
  EXPECT_EQ(convergenceChecks(s, SweepSettings{256, 4.0, false}).size(), 1u);
}

TEST(Tradeoff, ApplyConfigScalesTheKnotAndSetsTheKnobs) {
  const Scene s = knotScene();
  TradeoffConfig c = baseConfig(s);
  c.tessellation_factor = 0.5, c.spp = 16, c.precision = Precision::Float, c.shading = ShadingMode::Flat;
  c.texture_filter = TextureFilter::Nearest;
  const Scene a = applyConfig(s, c);
  const auto& k = std::get<TorusKnot>(a.objects[0].shape);
  EXPECT_EQ(k.segments_along, 384);
  EXPECT_EQ(k.segments_around, 20);
  EXPECT_EQ(a.render.spp, 16);
  EXPECT_EQ(a.render.precision, Precision::Float);
  EXPECT_EQ(a.shading, ShadingMode::Flat);
  EXPECT_EQ(a.material.texture->filter, TextureFilter::Nearest);
}

// A factor that makes the mesh exceed the loader's limit is an error that
// names the scene file, the configuration and the field.
TEST(Tradeoff, ApplyConfigRefusesAnOversizedMesh) {
  const Scene s = knotScene();
  TradeoffConfig c = baseConfig(s);
  c.id = "tess=1000";
  c.tessellation_factor = 1000.0;
  try {
    applyConfig(s, c);
    FAIL() << "expected an error";
  } catch (const std::exception& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("table2_knot_yiq.json [tradeoff tess=1000]"), std::string::npos) << m;
    EXPECT_NE(m.find("segments_a"), std::string::npos) << m;
  }
}

// Hand-made 2x2 images: errors over the pixels either image covers.
TEST(Tradeoff, ErrorOverTheUnionOfCoveredPixels) {
  Image ref(2, 2, false), img(2, 2, false);
  auto set = [](Image& im, int x, int y, float r, float g, float b, float a) {
    float* p = im.pixel(x, y);
    p[0] = r, p[1] = g, p[2] = b, p[3] = a;
  };
  set(ref, 0, 0, 0.5f, 0.5f, 0.5f, 1.0f);
  set(img, 0, 0, 0.5f, 0.5f, 0.5f, 1.0f);  // equal
  set(ref, 1, 0, 0.2f, 0.2f, 0.2f, 1.0f);
  set(img, 1, 0, 0.2f, 0.2f, 0.2f + 100.0f / 65535.0f, 1.0f);  // 100/65535 in blue
  set(ref, 0, 1, 0.1f, 0.0f, 0.0f, 0.5f);  // covered by the reference only
  // (1,1): covered by neither, not counted.
  const TradeoffError e = tradeoffError(img, ref);
  EXPECT_EQ(e.pixels, 3);
  EXPECT_NEAR(e.max_16bit, 0.1 * 65535.0, 0.05);
  EXPECT_NEAR(e.p999_16bit, 0.1 * 65535.0, 0.05);  // nearest rank of 3 values: the largest
  const double rmse = std::sqrt((100.0 * 100.0 + 6553.5 * 6553.5) / 9.0);
  EXPECT_NEAR(e.rmse_16bit, rmse, 0.05);
  EXPECT_GT(e.ciede2000_mean, 0.0);
  EXPECT_GT(e.ciede2000_max, 0.0);
  // An image against itself: all zero.
  const TradeoffError z = tradeoffError(ref, ref);
  EXPECT_EQ(z.max_16bit, 0.0);
  EXPECT_EQ(z.rmse_16bit, 0.0);
  EXPECT_EQ(z.ciede2000_mean, 0.0);
  EXPECT_THROW(tradeoffError(Image(2, 3, false), ref), std::runtime_error);
}

TEST(Tradeoff, ErrorMetricNames) {
  TradeoffError e;
  e.rmse_16bit = 1, e.p999_16bit = 2, e.max_16bit = 3, e.ciede2000_mean = 4;
  EXPECT_EQ(errorMetric(e, "rmse"), 1);
  EXPECT_EQ(errorMetric(e, "p999"), 2);
  EXPECT_EQ(errorMetric(e, "max"), 3);
  EXPECT_EQ(errorMetric(e, "ciede2000"), 4);
  EXPECT_THROW(errorMetric(e, "psnr"), std::runtime_error);
}

// With a tolerance, errors closer than it are not resolved: the faster of
// two such points dominates the slower; errors further apart still count.
TEST(ParetoFront, ErrorTolerance) {
  std::vector<ParetoPoint> p = {
      {1.0, 100.0},  // 0: fast
      {2.0, 99.0},   // 1: slower, 1 better: within the tolerance, dominated by 0
      {3.0, 50.0},   // 2: slower, much better: optimal
      {3.0, 52.0},   // 3: as slow as 2, 2 worse (within the tolerance): not dominated by 2
  };
  EXPECT_EQ(paretoFront(p, 0.0), (std::vector<size_t>{0, 1, 2}));
  EXPECT_EQ(paretoFront(p, 5.0), (std::vector<size_t>{0, 2, 3}));
  // A huge tolerance leaves the fastest point(s) only.
  EXPECT_EQ(paretoFront(p, 1e9), (std::vector<size_t>{0}));
  EXPECT_THROW(paretoFront(p, -1.0), std::runtime_error);
}

// The axes are the metric table's errors (image/metric_table.h): FLIP is
// one, measured over the same pixels as the others; a metric whose better
// direction is higher is no axis.
TEST(Tradeoff, AxesAreTheMetricTablesErrors) {
  Image ref(16, 16, false), img(16, 16, false);
  for (size_t i = 0; i < ref.rgba.size(); i += 4) {
    ref.rgba[i] = ref.rgba[i + 1] = ref.rgba[i + 2] = 0.5f, ref.rgba[i + 3] = 1.0f;
    img.rgba[i] = 0.6f, img.rgba[i + 1] = img.rgba[i + 2] = 0.5f, img.rgba[i + 3] = 1.0f;
  }
  const TradeoffError e = tradeoffError(img, ref);
  for (const std::string& id : metricIds(true)) EXPECT_TRUE(e.metrics.count(id)) << id;
  EXPECT_GT(errorMetric(e, "flip"), 0.0);
  EXPECT_EQ(errorMetric(e, "flip"), e.metrics.at("flip"));
  EXPECT_EQ(errorMetric(e, "rmse"), e.rmse_16bit);
  EXPECT_EQ(tradeoffError(ref, ref).metrics.at("flip"), 0.0);
  EXPECT_STREQ(tradeoffAxis("flip").id, "flip");
  EXPECT_THROW(tradeoffAxis("ssim"), std::runtime_error);  // higher is better: not an error
  try {
    tradeoffAxis("nope");
    FAIL() << "expected an error";
  } catch (const std::runtime_error& x) {
    EXPECT_NE(std::string(x.what()).find("flip"), std::string::npos) << x.what();  // lists the choices
  }
}
