// The trade-off's tables, from a tradeoff.json document (run.h writes it):
//   markdownTable: DIR/tradeoff.md, one row per configuration: knobs, frame
//     time in ms "median (min..max, n)" (1 decimal), max and p99.9 (1
//     decimal), RMSE (2) and CIEDE2000 mean (3) against the converged
//     reference, and "**yes**" on the Pareto front;
//   tsvTable: DIR/tradeoff.tsv, the same rows with every figure at full
//     precision (seconds, errors in 1/65535), pareto 1/0.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace xval {

std::string markdownTable(const nlohmann::ordered_json& tradeoff);
std::string tsvTable(const nlohmann::ordered_json& tradeoff);

}  // namespace xval
