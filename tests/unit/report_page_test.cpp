// report.html over its template (validate/report/report_page.mustache): every
// string results.json gives the page reaches it HTML-escaped, each in its
// place, whichever part of the template shows it.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "support/temp_files.h"
#include "validate/report/report.h"
#include "validate/results/results.h"

namespace xval {
namespace {

// A hostile text naming the field it is put in: markup, both quotes and an
// ampersand, which the page must show as text.
std::string hostile(const std::string& field) { return "<i class='x'>" + field + "&\"</i>"; }

std::string readFile(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(ReportPage, EveryStringFromTheResultsIsEscapedInItsPlace) {
  const std::filesystem::path dir = test::freshTempDir("xval_report_page_test");
  results::Results r;
  r.provenance = {{"openimageio", hostile("provenance")},
                  {"compiler", "g++"},
                  {"tolerances", "tolerances.json"},
                  {"git_commit", "unknown"},
                  {"settings_hash", "0123456789abcdef"}};
  r.wall_seconds = 1;
  r.renderers = {"reference", "povray"};
  results::Case c;
  c.scene = hostile("scene");
  c.file = "scene.json";
  c.reproduce = hostile("reproduce");
  results::Render reference;
  reference.seconds = 1;
  reference.image = "reference.png";
  reference.error = hostile("render error");
  results::Render povray;
  povray.not_expressible = hostile("render not expressible");
  c.renders = {{"reference", reference}, {"povray", povray}};
  c.left_out = {{"blender", hostile("left out")}};
  c.warnings = {{hostile("warning code"), hostile("warning subject"), hostile("warning message")}};
  results::Pair pair;
  pair.pair = "reference-povray";
  pair.verdict = results::PairVerdict::NotExpressible;
  pair.not_expressible = hostile("pair not expressible");
  c.pairs = {pair};
  results::GeometryCheck check;
  check.renderer = "blender-import";
  check.against = "reference";
  check.verdict = results::PairVerdict::NotExpressible;
  check.reason = hostile("geometry check");
  c.geometry_checks = {check};
  c.attribution = hostile("attribution");
  c.verdict = validation::CaseVerdict::Error;
  r.cases = {c};
  r.paper_claims = results::PaperClaims{{hostile("claim scene")},
                                        {{hostile("claim"), hostile("claim condition"), hostile("claim measured"), true}}};
  results::writeResults(dir / "results.json", r);
  writeReport(dir / "results.json", dir / "report.html");
  const std::string page = readFile(dir / "report.html");
  for (const char* field : {"provenance", "scene", "reproduce", "render error",
                            "render not expressible", "left out", "warning code", "warning subject",
                            "warning message", "pair not expressible", "geometry check", "attribution", "claim scene",
                            "claim", "claim condition", "claim measured"}) {
    EXPECT_EQ(page.find(hostile(field)), std::string::npos) << field << " is in the page unescaped";
    EXPECT_NE(page.find(htmlEscape(hostile(field))), std::string::npos) << field << " is not in the page";
  }
  EXPECT_EQ(page.find("<i class"), std::string::npos);
}

}  // namespace
}  // namespace xval
