// A render job's record, OUT/<scene>/<renderer>.job.json (plan.h): what
// the job rendered from (input_hash), how long it took and, when the render
// failed, why, or that the renderer declared the scene not expressible
// (no images then). It is written last, after the job's EXR and PNG, under a
// temporary name and renamed: a record that says ok means the images are
// whole.
#pragma once

#include <string>
#include <vector>

#include "validate/validation/plan.h"

namespace xval::renderers {
struct RenderInfo;
}

namespace xval::validation {

// The record's "format" (also hashed into every input_hash).
inline constexpr const char* kRecordFormat = "xval-validate-job/1";

struct JobRecord {
  bool present = false;    // a readable record exists
  std::string input_hash;  // what it was rendered from
  double seconds = 0.0, render_seconds = -1.0;
  // An outside tool's own figures (-1: not reported): its whole process
  // (wall) and the scene's parsing as its log reports it, so
  // process - parse - render is its start-up and writing.
  double process_seconds = -1.0, parse_seconds = -1.0;
  void setToolTimes(const renderers::RenderInfo& info);
  std::string error;       // empty when the render succeeded
  // Why the renderer cannot express the scene, as it declared before
  // rendering (Renderer::cannot_express): a verdict, not an error; the job
  // rendered nothing. Empty when it can.
  std::string not_expressible;
  // What the model loader changed in the scene (geometry/scene_meshes.h,
  // meshNotes): the record says which triangles the render was not given.
  std::vector<std::string> notes;
  std::string problem;     // why the record cannot be used (missing, unreadable); empty when present
};

// Never throws: a record that cannot be used is not `present` and its
// `problem` says why (missing, unreadable, another job's).
JobRecord readRecord(const Plan& plan, const RenderJob& job);
// Writes the record of `job` (with the host and the time) atomically;
// throws std::runtime_error when it cannot.
void writeRecord(const Plan& plan, const RenderJob& job, const JobRecord& rec);
// True when the job need not run again; otherwise `why` says what is missing.
bool isDone(const Plan& plan, const RenderJob& job, std::string* why = nullptr);

}  // namespace xval::validation
