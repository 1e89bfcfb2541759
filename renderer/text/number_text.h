// Numbers as text for tables and reports (Markdown, TSV, HTML).
//
// Written with libfmt, whose output is printf's for these formats.
//
// fixed(v, digits): v with `digits` digits after the point ("%.*f"), so
// fixed(0.125, 2) == "0.12" (the exact binary value rounded half to even,
// as printf does) and fixed(0.1251, 2) == "0.13"; the
// non-finite values as "inf", "-inf" and "nan".
// fixed(j, digits): the same for a JSON number; "n/a" for anything else
// (null is how a results file writes a value that does not exist, e.g.
// an error over no pixels).
// significant(v): v with the digits it has, up to 6 significant ones
// ("%.6g"): significant(0.1) == "0.1", significant(99.99) == "99.99",
// significant(2) == "2"; for tolerances, whose declared values are short
// decimals (0.1/65535 on 99.99% must not print as "0 on 100.0%").
#pragma once

#include <optional>
#include <string>

#include <nlohmann/json.hpp>

namespace xval {

std::string fixed(double v, int digits);
std::string fixed(const nlohmann::json& j, int digits);
std::string fixed(const nlohmann::ordered_json& j, int digits);
// "n/a" for none (an infinite or absent number).
std::string fixed(const std::optional<double>& v, int digits);
std::string significant(double v);
std::string significant(const nlohmann::json& j);
std::string significant(const nlohmann::ordered_json& j);

}  // namespace xval
