// JUnit XML from a results.json of `xval validate` or `xval crosscheck`,
// the test-report format every CI system reads.
//
// One <testsuite> per run (name = the run's name), one <testcase> per scene
// and pair: classname = the scene's name, name = the pair ("reference-povray").
//   passed            an empty <testcase/> (but for its properties)
//   outside tolerance <failure message="..."> with the pair's metrics and
//                     tolerance (p99.9, max, fraction within, mask
//                     disagreements off silhouettes, the tolerance and, when
//                     declared, its reason)
//   error             <error message="..."> (a render failed, a job has no
//                     usable record, ...), the renderers' errors in the text
//   not expressible   <skipped message="..."> with the renderer's reason
// A compared pair (passed or outside tolerance) whose metrics carry the
// metric table's values (metrics.values, image/metric_table.h) has them as
// <properties>, before its outcome: <property name="metric.ID"
// value="%.6g">, in table order ("not finite" for null).
// Then one <testcase> per geometry check of the case (results.json
// cases[].geometry_checks, validate/results/geometry_checks.h), name =
// "reference-blender-import (geometry)": pass empty, fail <failure> with
// the metrics against the bounds, error <error>, not expressible <skipped>.
// Then, when the case's verdict (cases[].verdict, validate/validation/
// case_verdict.h; a crosscheck's results have none) is not what those
// testcases say, one testcase for the case itself, name = "case", so that a
// case that is no pass never reads as one (nor as tests="0"):
//   not_compared      <failure type="not_compared"> naming why nothing was
//                     compared (the attribution, the renderers left out)
//   error             <error> when none of its testcases is one (a case of
//                     one renderer whose render failed), the renderers' errors
// time = the seconds of the two renders compared (their records; a
// geometry check: its job's). Every
// string is XML-escaped; control characters other than tab and newline,
// which XML 1.0 cannot carry, become U+FFFD.
// tests/junit/junit.xsd is the schema the output is checked against.
// Written as text, not with an XML library: pugixml 1.13 (Debian 12's
// libpugixml-dev) builds the same elements, attributes and texts, but
// writes an empty element as <a b="c" /> and leaves ' and > unescaped in
// attribute values, where this file's tests pin <a b="c"/>, &apos; and
// &gt; (JunitReport.*, GeometryChecks.JunitHasOneTestcasePerCheck, the
// cli.validate tests of not-compared cases); it has no option for either.
#pragma once

#include <string>

#include "validate/results/results.h"

namespace xval {

// From the results' types (validate/results/results.h: its reader has
// refused what is no results file, naming the field); every verdict is the
// stored one.
std::string junitXml(const results::Results& results, const std::string& suite_name);

std::string xmlEscape(const std::string& s);

}  // namespace xval
