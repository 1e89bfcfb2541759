// Running an external tool (POV-Ray, Blender) with a time-out.
//
// The tool runs with its own working directory, no shell (argv is passed
// as is, so nothing in it is interpreted), stdin from /dev/null, stdout and
// stderr into a log file (opened with O_NOFOLLOW: never through a planted
// link). It runs in a process group of its own, killed whole when the
// time-out expires, and, once main() has called installInterruptHandler(),
// when xval is interrupted.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace xval {

struct ProcessResult {
  bool started = false;    // false: the executable was not found / not runnable
  bool timed_out = false;
  int exit_code = -1;      // valid when it exited normally
  int signal = 0;          // non-zero when killed by a signal
  double seconds = 0.0;    // wall time
  double timeout_seconds = 0.0;  // the time-out it ran with, as given
  std::filesystem::path log;
  std::string error;       // why it could not start

  bool ok() const { return started && !timed_out && signal == 0 && exit_code == 0; }
  // One line saying what happened ("exit code 3", "timed out after 300 s",
  // "timed out after 0.3 s": the time-out as given, not rounded, ...).
  std::string describe() const;
};

// `progress` (optional): a file the tool appends to as it goes (a worker
// that renders many jobs writes a line per job); the time-out then counts
// from the last change of its size, i.e. it applies to each job.
ProcessResult runProcess(const std::vector<std::string>& argv, const std::filesystem::path& cwd,
                         const std::filesystem::path& log, double timeout_seconds,
                         const std::filesystem::path& progress = {});

// A program that may crash or hang on hostile input (xval-model-reader:
// Assimp reading a model file, geometry/assimp_read.h), run so that a
// crash or a hang costs that one input, never xval: like runProcess (no
// shell, its own process group, killed at the time-out and on an
// interrupt, no signal blocked, the interrupt signals at their default
// action, stdin /dev/null), with its stdout and stderr in in-memory files
// (its writes never block on this process) of which this one reads the
// output whole and the end of stderr. `argv[0]` is the program's path (no
// PATH search).
struct CapturedResult {
  ProcessResult process;    // how it ended (`log` is unused)
  std::string output;       // its stdout, when it exited with 0
  std::string diagnostics;  // the end of its stderr (at most kLogTailBytes), control characters blanked
  // The line of `diagnostics` saying what went wrong: a sanitizer's
  // "ERROR: ..." line, else the last non-empty one; empty if none.
  std::string summary() const;
};
// `max_output_bytes`: a larger output is an error (exit code 71), not read.
CapturedResult runCaptured(const std::vector<std::string>& argv, double timeout_seconds, size_t max_output_bytes);

// SIGINT, SIGTERM and SIGHUP (unless SIGHUP was ignored, as under nohup)
// are taken by a thread of their own: on the first one, every process
// group runProcess started and has not reaped is killed (SIGKILL), and
// xval then dies of the same signal. Call once, from main(), before any
// other thread starts (the signals are blocked in every thread). A
// process is registered under the same lock as the kill, taken across
// posix_spawn, so none is missed and none starts after an interrupt.
void installInterruptHandler();

// The quoted tail of a log is capped (a tool printing one 100 MiB line
// must not copy it into every record and report).
inline constexpr int kLogTailLines = 20;
inline constexpr size_t kLogTailBytes = 4096;

// The last `lines` lines of a text file, at most kLogTailBytes of it (the
// end of an over-long line, marked as cut), each prefixed "  | ".
std::string tailOfFile(const std::filesystem::path& file, int lines = kLogTailLines);

// A name no earlier attempt used (16 hex digits): the harnesses name a
// tool's output with it, so an image left or still being written by the
// tool of an earlier, interrupted attempt is never taken for this one's.
std::string attemptToken();

// Full path of an executable found on PATH, or empty.
std::filesystem::path findOnPath(const std::string& name);

}  // namespace xval
