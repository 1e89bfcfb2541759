// The metric table (image/metric_table.h).
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <stdexcept>
#include <string>

#include "image/metric_table.h"

using namespace xval;

namespace {
Image grey(int w, int h, float v) {
  Image img(w, h, false);
  for (size_t i = 0; i < img.rgba.size(); i += 4)
    img.rgba[i] = img.rgba[i + 1] = img.rgba[i + 2] = v, img.rgba[i + 3] = 1.0f;
  return img;
}
}  // namespace

TEST(MetricTable, IdsAreUniqueAndNamed) {
  std::set<std::string> ids;
  for (const MetricInfo& m : metricTable()) {
    EXPECT_TRUE(ids.insert(m.id).second) << m.id;
    EXPECT_STRNE(m.label, "") << m.id;
    EXPECT_EQ(&metricById(m.id), &m);
  }
  EXPECT_TRUE(ids.count("flip") && ids.count("flip_p99"));
  try {
    metricById("nope");
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("'nope'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("rmse"), std::string::npos) << e.what();
  }
  EXPECT_EQ(labelWithUnit(metricById("rmse")), "RMSE (1/65535)");
  EXPECT_EQ(labelWithUnit(metricById("flip")), "mean FLIP");
  for (const std::string& id : metricIds(true)) EXPECT_EQ(metricById(id).better, Better::Lower) << id;
}

// Values come from the one measurement: 1/65535 scaling of the compare
// record, the perceptual and FLIP records as they are; the pair's JSON
// carries them as "values" beside the record's fields, a value that is not
// finite (PSNR of equal images) as null.
TEST(MetricTable, ValuesOfAPair) {
  const Image a = grey(12, 10, 0.5f), b = grey(12, 10, 0.5f + 30.0f / 65535.0f);
  const PairMeasures m = measurePair(a, b, Tolerance{});
  EXPECT_NEAR(metricById("max").value(m), 30.0, 1e-3);
  EXPECT_NEAR(metricById("rmse").value(m), 30.0, 1e-3);
  EXPECT_EQ(metricById("flip").value(m), m.flip.mean);
  EXPECT_GT(m.flip.mean, 0.0);
  const nlohmann::json j = pairJson(m, Tolerance{});
  EXPECT_TRUE(j.contains("ssim") && j.contains("max_abs_16bit"));  // the record's fields stay
  EXPECT_EQ(j["values"].size(), metricTable().size());
  EXPECT_EQ(j["values"]["flip"].get<double>(), m.flip.mean);
  const nlohmann::json same = metricValuesJson(measurePair(a, a, Tolerance{}));
  EXPECT_TRUE(same["psnr"].is_null());
  EXPECT_EQ(same["flip"].get<double>(), 0.0);
}

// Kept per-image measurements give the same values as the images alone.
TEST(MetricTable, MeasuredImagesGiveTheSameValues) {
  Image a = grey(16, 16, 0.3f), b = grey(16, 16, 0.3f);
  b.pixel(5, 5)[1] = 0.9f;
  const MeasuredImage ma = measuredImage(a), mb = measuredImage(b);
  EXPECT_EQ(metricValuesJson(measurePair(a, b, Tolerance{}, {}, &ma, &mb)),
            metricValuesJson(measurePair(a, b, Tolerance{})));
}

// eitherCovered: both images take the coverage of either; a pixel one image
// misses counts with its whole colour (over black).
TEST(MetricTable, EitherCoveredMeasuresTheUnion) {
  Image a = grey(4, 4, 0.5f), b = grey(4, 4, 0.5f);
  float* p = b.pixel(1, 1);
  p[0] = p[1] = p[2] = p[3] = 0.0f;  // b misses (1, 1)
  float* q = a.pixel(2, 2);
  q[0] = q[1] = q[2] = q[3] = 0.0f;
  float* r = b.pixel(2, 2);
  r[0] = r[1] = r[2] = r[3] = 0.0f;  // neither covers (2, 2)
  const auto [ea, eb] = eitherCovered(a, b);
  EXPECT_EQ(ea.pixel(1, 1)[3], 1.0f);
  EXPECT_EQ(eb.pixel(1, 1)[3], 1.0f);
  EXPECT_EQ(ea.pixel(2, 2)[3], 0.0f);
  const PairMeasures m = measurePair(ea, eb, Tolerance{});
  EXPECT_EQ(m.compare.covered_both, 15);
  EXPECT_NEAR(metricById("max").value(m), 0.5 * 65535.0, 1e-2);
  EXPECT_THROW(eitherCovered(a, grey(3, 4, 0.0f)), std::runtime_error);
}
