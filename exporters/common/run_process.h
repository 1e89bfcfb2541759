// Running an external tool (POV-Ray, Blender) with a time-out.
//
// The tool runs with its own working directory, no shell (argv is passed
// as is, so nothing in it is interpreted), stdin from /dev/null, stdout and
// stderr into a log file. It is killed (its whole process group) when the
// time-out expires.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace xval {

struct ProcessResult {
  bool started = false;    // false: the executable was not found / not runnable
  bool timed_out = false;
  int exit_code = -1;      // valid when it exited normally
  int signal = 0;          // non-zero when killed by a signal
  double seconds = 0.0;    // wall time
  std::filesystem::path log;
  std::string error;       // why it could not start

  bool ok() const { return started && !timed_out && signal == 0 && exit_code == 0; }
  // One line saying what happened ("exit code 3", "timed out after 300 s", ...).
  std::string describe() const;
};

ProcessResult runProcess(const std::vector<std::string>& argv, const std::filesystem::path& cwd,
                         const std::filesystem::path& log, double timeout_seconds);

// The last `lines` lines of a text file (for error messages).
std::string tailOfFile(const std::filesystem::path& file, int lines = 20);

// Full path of an executable found on PATH, or empty.
std::filesystem::path findOnPath(const std::string& name);

}  // namespace xval
