// The page's shared data helpers (validate/report/report_data.h).
#include "validate/report/report_data.h"

#include <algorithm>
#include <cctype>

#include "validate/report/report_pixels.h"
#include "validate/results/case_verdict.h"
#include "validate/results/geometry_checks.h"

namespace xval::page {

namespace mu = kainjow::mustache;

std::string verdictClass(const std::string& v) {
  return v == "pass" ? "pass" : v == "fail" ? "fail" : v == "error" ? "err" : v == "finding" ? "find" : "nexp";
}

std::string upperCase(const std::string& s) {
  std::string upper;
  for (char ch : s) upper += char(std::toupper(static_cast<unsigned char>(ch)));
  return upper;
}

mu::data list() { return mu::data(mu::data::type::list); }

mu::data maybe(const std::optional<std::string>& v) {
  mu::data l = list();
  if (v) l << mu::data(*v);
  return l;
}

mu::data strings(const std::vector<std::string>& v) {
  mu::data l = list();
  for (const std::string& s : v) l << mu::data(s);
  return l;
}

mu::data members(const results::Named<std::string>& named, const char* key, const char* value) {
  mu::data l = list();
  for (const auto& [k, v] : named) {
    mu::data member;
    member.set(key, k);
    member.set(value, v);
    l << member;
  }
  return l;
}

std::string caseVerdict(const results::Case& c) {
  std::string v = validation::verdictName(*c.verdict);
  std::replace(v.begin(), v.end(), '_', ' ');
  return v;
}

std::string checkVerdict(const results::GeometryCheck& g) { return verdictWords(g.verdict); }

std::string checkName(const results::GeometryCheck& g) { return validation::geometryCheckName(g.against, g.renderer); }

}  // namespace xval::page
