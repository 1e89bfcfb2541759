// The data of report.html (validate/report/report.h) for its template
// (validate/report/report_page.mustache, rendered with kainjow::mustache): the
// helpers the page's parts share. The template escapes every value.
#pragma once

#include <kainjow/mustache.hpp>
#include <optional>
#include <string>
#include <vector>

#include "validate/results/results.h"

namespace xval::page {

// A verdict's class in the page's style sheet (report_page.mustache):
// "pass", "fail", "err" or "nexp".
std::string verdictClass(const std::string& verdict);

std::string upperCase(const std::string& s);

// A list, and an optional value as a list of none or one, so that
// {{#key}}..{{.}}..{{/key}} shows it only when there is one. Every object
// sets each key its part of the template reads: a key left out would be
// looked up in the enclosing objects.
kainjow::mustache::data list();
kainjow::mustache::data maybe(const std::optional<std::string>& v);
kainjow::mustache::data strings(const std::vector<std::string>& v);
// Key-value members (results.json's provenance, a case's left_out) as a
// list of objects, each with the key under `key` and the value under `value`.
kainjow::mustache::data members(const results::Named<std::string>& named, const char* key, const char* value);

// A case: the verdict the compare step decided and stored (validation/
// case_verdict.h; the schema requires it of every results.json case), as
// the pairs' verdicts read ("not compared").
std::string caseVerdict(const results::Case& c);

// A geometry check (validate/results/geometry_checks.h): its name
// ("reference-blender-import (geometry)") and its verdict as the pairs'
// verdicts read.
std::string checkName(const results::GeometryCheck& g);
std::string checkVerdict(const results::GeometryCheck& g);

}  // namespace xval::page
