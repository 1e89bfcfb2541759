// Numbers as text (text/number_text.h).
#include "text/number_text.h"

#include <cmath>

#include <fmt/format.h>

namespace xval {

std::string fixed(double v, int digits) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  return fmt::format("{:.{}f}", v, digits);
}

std::string fixed(const nlohmann::json& j, int digits) {
  return j.is_number() ? fixed(j.get<double>(), digits) : "n/a";
}

std::string fixed(const std::optional<double>& v, int digits) { return v ? fixed(*v, digits) : "n/a"; }

std::string fixed(const nlohmann::ordered_json& j, int digits) {
  return j.is_number() ? fixed(j.get<double>(), digits) : "n/a";
}

std::string significant(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  return fmt::format("{:.6g}", v);
}

std::string significant(const nlohmann::json& j) { return j.is_number() ? significant(j.get<double>()) : "n/a"; }

std::string significant(const nlohmann::ordered_json& j) {
  return j.is_number() ? significant(j.get<double>()) : "n/a";
}

}  // namespace xval
