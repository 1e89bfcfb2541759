// The job records of `xval validate` (job_record.h).
#include "validate/validation/job_record.h"

#include <unistd.h>

#include <nlohmann/json.hpp>

#include "files/atomic_write.h"
#include "files/utf8_text.h"
#include "renderers/registry.h"
#include "renderers/renderer.h"
#include "scene/json_reader.h"
#include "validate/validation/file_fields.h"

namespace xval::validation {

namespace {

namespace fs = std::filesystem;
using J = nlohmann::ordered_json;

std::string hostName() {
  char buf[256] = {0};
  if (gethostname(buf, sizeof buf - 1) != 0) return "unknown";
  return buf;
}

}  // namespace

void JobRecord::setToolTimes(const renderers::RenderInfo& info) {
  render_seconds = info.render_seconds;
  parse_seconds = info.parse_seconds;
  // RenderInfo::seconds is a process's wall time only for an outside tool (one with a log).
  process_seconds = info.log.empty() ? -1.0 : info.seconds;
}

JobRecord readRecord(const Plan& plan, const RenderJob& job) {
  JobRecord rec;
  const fs::path file = plan.dir / job.record();
  if (!fs::exists(file)) {
    rec.problem = file.string() + ": no record (the job has not run, or was interrupted)";
    return rec;
  }
  try {
    const J j = parseOrderedJsonText(readJsonFile(file, "job record"), file.string());
    FieldReader rd{file.string()};
    const std::string format = rd.str(j, "format");
    if (format != kRecordFormat)
      throw std::runtime_error(file.string() + ": format: \"" + format + "\": expected \"" + kRecordFormat + "\"");
    const std::string scene = rd.str(j, "scene"), renderer = rd.str(j, "renderer");
    if (scene != job.scene || renderer != job.renderer)
      throw std::runtime_error(file.string() + ": scene/renderer: \"" + scene + "\"/\"" + renderer +
                               "\": expected \"" + job.scene + "\"/\"" + job.renderer + "\"");
    rec.input_hash = rd.str(j, "input_hash");
    rec.seconds = rd.num(j, "seconds");
    if (j.contains("render_seconds")) rec.render_seconds = rd.num(j, "render_seconds");
    if (j.contains("process_seconds")) rec.process_seconds = rd.num(j, "process_seconds");
    if (j.contains("parse_seconds")) rec.parse_seconds = rd.num(j, "parse_seconds");
    if (j.contains("error")) rec.error = rd.str(j, "error");
    if (j.contains("not_expressible")) rec.not_expressible = rd.str(j, "not_expressible");
    if (!rec.error.empty() && !rec.not_expressible.empty())
      throw std::runtime_error(file.string() + ": error and not_expressible: expected at most one of them");
    rec.present = true;
  } catch (const std::exception& e) {
    rec.problem = e.what();
  }
  return rec;
}

bool isDone(const Plan& plan, const RenderJob& job, std::string* why) {
  auto no = [why](const std::string& w) {
    if (why) *why = w;
    return false;
  };
  JobRecord rec = readRecord(plan, job);
  if (!rec.present) return no(rec.problem);
  if (!rec.error.empty()) return no("the last render failed: " + rec.error);
  if (rec.input_hash != job.input_hash)
    return no((plan.dir / job.record()).string() + ": rendered from other inputs (input_hash " +
              rec.input_hash + ", the plan's is " + job.input_hash + ")");
  if (!rec.not_expressible.empty()) return true;  // a verdict: nothing was rendered
  std::vector<std::string> outputs{job.exr(), job.png()};
  // A geometry check's job also made the reference's passes (plan.h).
  if (const renderers::Renderer* r = renderers::registry().find(job.renderer); r && r->geometry_passes)
    outputs.push_back(job.reference_passes());
  for (const std::string& f : outputs)
    if (!fs::exists(plan.dir / f)) return no((plan.dir / f).string() + ": missing");
  return true;
}

void writeRecord(const Plan& plan, const RenderJob& job, const JobRecord& rec) {
  J j;
  j["format"] = kRecordFormat;
  j["job"] = job.index;
  j["scene"] = job.scene;
  j["renderer"] = job.renderer;
  j["input_hash"] = job.input_hash;
  j["seconds"] = rec.seconds;
  if (rec.render_seconds >= 0) j["render_seconds"] = rec.render_seconds;
  if (rec.process_seconds >= 0) j["process_seconds"] = rec.process_seconds;
  if (rec.parse_seconds >= 0) j["parse_seconds"] = rec.parse_seconds;
  // An error quotes a tool's log, whose bytes are the tool's: stored as
  // valid UTF-8 (files/utf8_text.h), so that the record of a failed render
  // can always be written.
  if (!rec.error.empty()) j["error"] = validUtf8(rec.error);
  if (!rec.not_expressible.empty()) j["not_expressible"] = validUtf8(rec.not_expressible);
  for (const std::string& n : rec.notes) j["notes"].push_back(validUtf8(n));
  j["host"] = hostName();
  j["finished_unix"] = nowUnix();
  writeFileAtomically(plan.dir / job.record(), j.dump(2) + "\n");
}

}  // namespace xval::validation
