// The parts of report.html that show single pixels (validate/report/report.h
// assembles the page): the pixel classes' legend, each case's viewer (a
// swap between its renders and heat maps), the heat maps at full
// resolution with the worst unexplained and worst explained pixel of each
// pair marked, and the magnified crops around them
// (validate/pixel_crops.h). Every string from results.json is
// HTML-escaped; nothing is loaded from the network.
#pragma once

#include <filesystem>
#include <string>

#include "validate/results/results.h"

namespace xval {

// Whether a render has an image to show: it names one, did not fail (no
// `error`) and the file is in `dir`. A render without one is shown by its
// error text, never by an <img> of a missing file.
bool renderHasImage(const results::Render& render, const std::filesystem::path& dir);

// A pair's or a geometry check's stored verdict (validate/results/
// results.h) as the report words it: "error", "not expressible", "pass" or
// "fail".
std::string verdictWords(results::PairVerdict v);
std::string pairVerdict(const results::Pair& pair);

// The classes of image/pixel_classes.h: name, one-line explanation, a link
// to its section of the doc (doc_href: the doc relative to the page).
std::string pixelClassLegend(const std::string& doc_href);

// One case's viewer, heat maps and crops; `dir`: the folder results.json
// and the files it names are in (a heat map named there but missing is
// said so).
std::string casePixels(const results::Case& c, const std::filesystem::path& dir);

// The page's inline script for the viewers' buttons.
std::string swapScript();

}  // namespace xval
