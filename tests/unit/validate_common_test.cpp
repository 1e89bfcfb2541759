// validate/common: number text and the provenance record's compiler.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include <nlohmann/json.hpp>

#include "text/number_text.h"
#include "validate/common/provenance.h"
#include "support/temp_files.h"

using namespace xval;

TEST(NumberText, Fixed) {
  EXPECT_EQ(fixed(1.0 / 3.0, 2), "0.33");
  EXPECT_EQ(fixed(2.5, 0), "2");  // printf rounds half to even here
  EXPECT_EQ(fixed(-1.25, 3), "-1.250");
  EXPECT_EQ(fixed(std::numeric_limits<double>::infinity(), 2), "inf");
  EXPECT_EQ(fixed(-std::numeric_limits<double>::infinity(), 2), "-inf");
  EXPECT_EQ(fixed(std::nan(""), 2), "nan");
  EXPECT_EQ(fixed(1e300, 1).size(), 303u);  // no truncation
  EXPECT_EQ(fixed(nlohmann::json(0.125), 1), "0.1");
  EXPECT_EQ(fixed(nlohmann::json(nullptr), 1), "n/a");
  EXPECT_EQ(fixed(nlohmann::json("3"), 1), "n/a");
  EXPECT_EQ(fixed(nlohmann::ordered_json(7), 2), "7.00");
}

// Tolerances keep their declared digits: 0.1/65535 on 99.99% is not "0 on 100.0%".
TEST(NumberText, Significant) {
  EXPECT_EQ(significant(0.1 / 65535.0 * 65535.0), "0.1");
  EXPECT_EQ(significant(100.0 * 0.9999), "99.99");
  EXPECT_EQ(significant(2.0), "2");
  EXPECT_EQ(significant(100.0 * 0.999), "99.9");
  EXPECT_EQ(significant(std::nan("")), "nan");
  EXPECT_EQ(significant(nlohmann::json(nullptr)), "n/a");
  EXPECT_EQ(significant(nlohmann::json(0.25)), "0.25");
}

// The compiler that built this test is the one named, by its own macros.
TEST(Provenance, NamesTheRealCompiler) {
  const std::string c = compilerDescription();
#if defined(__clang__)
  EXPECT_EQ(c.rfind("clang ", 0), 0u) << c;
  EXPECT_NE(c.find(__clang_version__), std::string::npos) << c;
#elif defined(__GNUC__)
  EXPECT_EQ(c.rfind("g++ ", 0), 0u) << c;
  EXPECT_NE(c.find(__VERSION__), std::string::npos) << c;
#endif
}

TEST(Provenance, CollectsTheRecord) {
  const auto scratch = xval::test::freshTempDir("xval_provenance_test") / "provenance.log";
  const Provenance p = collectProvenance(scratch);
  EXPECT_EQ(p.date_utc.size(), 20u) << p.date_utc;  // 2026-12-01T11:46:44Z
  EXPECT_EQ(p.date_utc.back(), 'Z');
  EXPECT_EQ(p.date(), p.date_utc.substr(0, 10));
  EXPECT_FALSE(p.cpu.empty());
  EXPECT_EQ(p.compiler, compilerDescription());
  EXPECT_FALSE(p.openimageio.empty());
  // Dirty exactly when tracked files have changes (or unknown).
  const bool dirty = p.git_commit.size() > 6 && p.git_commit.compare(p.git_commit.size() - 6, 6, "-dirty") == 0;
  if (p.git_commit != "unknown") {
    EXPECT_EQ(dirty, p.git_modified_files != 0) << p.git_commit;
  }
  EXPECT_FALSE(std::filesystem::exists(scratch));
}
