// A case's geometry checks in `xval validate` (geometry_checks.h).
#include "validate/results/geometry_checks.h"

namespace xval::validation {

using J = nlohmann::ordered_json;

J geometryCheckCompared(const std::string& renderer, const std::string& against, const GeometryMetrics& m,
                        const GeometryTolerance& tol) {
  J j = {{"renderer", renderer}, {"against", against}, {"verdict", m.pass ? "pass" : "fail"}};
  if (!m.pass) j["reason"] = m.why;
  j["metrics"] = J(metricsJson(m));
  j["bounds"] = J(boundsJson(tol));
  return j;
}

J geometryCheckNotExpressible(const std::string& renderer, const std::string& against, const std::string& why) {
  return {{"renderer", renderer}, {"against", against}, {"verdict", "not_expressible"}, {"reason", why}};
}

J geometryCheckError(const std::string& renderer, const std::string& against, const std::string& why) {
  return {{"renderer", renderer}, {"against", against}, {"verdict", "error"}, {"reason", why}};
}

bool geometryChecksPass(const J& checks) {
  for (const J& c : checks) {
    const std::string v = c.at("verdict").get<std::string>();
    if (v != "pass" && v != "not_expressible") return false;
  }
  return true;
}

int geometryChecksWith(const J& checks, const std::string& verdict) {
  int n = 0;
  for (const J& c : checks) n += c.at("verdict").get<std::string>() == verdict;
  return n;
}

std::string geometryCheckName(const std::string& against, const std::string& renderer) {
  return against + "-" + renderer + " (geometry)";
}

}  // namespace xval::validation
