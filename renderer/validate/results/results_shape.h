// results.json read by the report (validate/report/report.h) checked against its
// documented schema, docs/results-schema.json, compiled into xval: a
// results.json edited by hand, cut short or written by another version is
// refused with the file, the field and what was expected
// ("results.json: cases[3].renders: missing (expected an object)"), never
// read past a missing field.
//
// The schema is the one statement of the format; the checker implements the
// draft-07 keywords it uses for shape: type, const, enum, required,
// properties, additionalProperties, propertyNames, items, minItems,
// maxItems, minimum, maximum, $ref (#/definitions/...), if/then/else and
// boolean schemas. `pattern` and `uniqueItems` are not checked (they
// constrain values the report only shows, escaped).
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace xval {

// Throws std::runtime_error "FILE: FIELD: ..." at the first field of
// `results` the schema does not allow.
void checkResultsShape(const nlohmann::ordered_json& results, const std::string& file);

}  // namespace xval
