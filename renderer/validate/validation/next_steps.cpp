// The next steps of failing cases (next_steps.h).
#include "validate/validation/next_steps.h"

#include <cstdio>
#include <string>

#include "renderers/registry.h"
#include "validate/validation/case_verdict.h"

namespace xval::validation {

namespace {

std::string shellQuote(const std::string& v) {
  std::string q = "'";
  for (char c : v) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

}  // namespace

void printNextSteps(const Plan& plan, const nlohmann::ordered_json& cases) {
  for (const auto& jc : cases) {
    const std::string scene = jc["scene"].get<std::string>(), file = jc["file"].get<std::string>();
    const CaseVerdict v = parseCaseVerdict(jc["verdict"].get<std::string>(), scene + ": verdict");
    if (v == CaseVerdict::Pass) continue;
    if (v == CaseVerdict::NotCompared) {
      // Nothing to look closer at: say why nothing was compared.
      std::fprintf(stderr, "NOT COMPARED %s (%s)\n", scene.c_str(), jc["attribution"].get<std::string>().c_str());
      const nlohmann::ordered_json left_out = jc.value("left_out", nlohmann::ordered_json::object());
      for (const auto& [id, why] : left_out.items())
        std::fprintf(stderr, "  %s left out: %s\n", id.c_str(), why.get<std::string>().c_str());
      continue;
    }
    std::fprintf(stderr, "%s %s (%s)\n", v == CaseVerdict::Error ? "ERROR" : "FAIL", scene.c_str(),
                 jc["attribution"].get<std::string>().c_str());
    // Every renderer of the case that rendered it, but the reference.
    for (const auto& [id, render] : jc["renders"].items())
      if (id != renderers::registry().reference().id && !render.contains("not_expressible"))
        std::fprintf(stderr, "  look closer: xval crosscheck %s --renderer %s -o %s\n", shellQuote(file).c_str(),
                     id.c_str(), shellQuote((plan.dir / (scene + "." + id)).string()).c_str());
    std::fprintf(stderr,
                 "  accept a documented difference: declare it, with its measured reason, in the\n"
                 "  `tolerances` field of %s (defaults: %s)\n"
                 "  after an intended change of the reference renderer, store its images anew:\n"
                 "  xval golden update %s --renderer reference\n",
                 file.c_str(), plan.tolerances.c_str(), shellQuote(file).c_str());
  }
}

}  // namespace xval::validation
