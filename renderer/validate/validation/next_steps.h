// What `xval validate` prints on stderr for every case that does not pass
// (case_verdict.h): for a failing or error case, the crosscheck command
// that looks closer at each pair, how to accept a documented difference (a
// declared tolerance) and, when a renderer with a golden set for the scene
// is the one to blame, the command that stores its images anew; for a case
// that compared nothing, why (the renderers left out, with their reasons).
// And the command that runs a case again (results.json's `reproduce`, the
// report's "Reproduce:" line).
//
// Every printed command runs as printed: it carries what the run was given
// beyond its scenes (runOptions), its paths are relative to the working
// folder when below it, else absolute (shellPath), and every word is
// shell-quoted (process/shell_word.h), so a pasted command cannot run
// anything a scene or folder name contains.
#pragma once

#include <filesystem>
#include <string>

#include <vector>

#include "validate/results/results.h"

#include "validate/validation/plan.h"

namespace xval::validation {

// The options a command about `scene_file` needs to do what the run did:
// --renderer-file FILE for each renderer of the run defined by a file (and
// golden-NAME's NAME: Plan::renderer_files), and --tolerances FILE when the
// rule (validate/tolerances.h) would not find the run's tolerance file for
// that scene alone. "" or " --opt value ...".
std::string runOptions(const Plan& plan, const std::filesystem::path& scene_file);

// `xval validate SCENE -o OUT/<scene>.validate [--renderers LIST] ...`: case
// `ps` of the run again, into a folder of its own, with the run's
// renderers (--renderers when they are not validate's default ones) and
// runOptions.
std::string reproduceCommand(const Plan& plan, const PlannedScene& ps);

// `cases`: results.json's cases (validate/results/results.h), each with its
// stored verdict. The golden-update step
// is printed for a renderer R of the case (not a golden set, not a
// geometry check) only when R is to blame, i.e. a majority deviates from R
// (the case's `deviating`) or R's pair with its own golden set failed (its
// images changed since they were stored), AND R's golden set holds an
// image of the scene: otherwise storing R's images is not the step.
void printNextSteps(const Plan& plan, const std::vector<results::Case>& cases);

}  // namespace xval::validation
