#include "process/run_process.h"

#include "files/utf8_text.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <mutex>
#include <random>
#include <set>
#include <thread>
#include <vector>

extern char** environ;


namespace xval {

namespace {

// The process groups started and not yet reaped, and whether an interrupt
// has come (after which nothing starts).
std::mutex g_children_lock;
std::set<pid_t> g_children;
bool g_interrupted = false;

sigset_t interruptSignals() {
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, SIGINT);
  sigaddset(&set, SIGTERM);
  struct sigaction old;
  if (sigaction(SIGHUP, nullptr, &old) == 0 && old.sa_handler != SIG_IGN) sigaddset(&set, SIGHUP);
  return set;
}

void forget(pid_t pid) {
  std::lock_guard<std::mutex> g(g_children_lock);
  g_children.erase(pid);
}

// After an interrupt the tool just reaped was killed by it: this thread
// must not go on to record that as the tool's failure (or do anything
// else) while the interrupt thread ends the process.
void waitIfInterrupted() {
  bool interrupted;
  {
    std::lock_guard<std::mutex> g(g_children_lock);
    interrupted = g_interrupted;
  }
  while (interrupted) pause();
}

// Starts `exe` with `argv` and the file actions `fa` in a process group of
// its own (a time-out or an interrupt kills all of it), with no signal
// blocked and the interrupt signals at their default action whatever this
// process does with them; registered for the interrupt under the same
// lock as the kill, so none is missed and none starts after an interrupt.
// Returns posix_spawn's error, or EINTR after an interrupt.
int spawnInOwnGroup(const std::string& exe, const std::vector<std::string>& argv,
                    const posix_spawn_file_actions_t& fa, pid_t& pid) {
  posix_spawnattr_t attr;
  posix_spawnattr_init(&attr);
  posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETPGROUP | POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF);
  posix_spawnattr_setpgroup(&attr, 0);
  sigset_t none, defaults;
  sigemptyset(&none);
  sigemptyset(&defaults);
  for (int sig : {SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGPIPE}) sigaddset(&defaults, sig);
  posix_spawnattr_setsigmask(&attr, &none);
  posix_spawnattr_setsigdefault(&attr, &defaults);
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  int rc;
  {
    std::lock_guard<std::mutex> g(g_children_lock);
    rc = g_interrupted ? EINTR : posix_spawn(&pid, exe.c_str(), &fa, &attr, args.data(), environ);
    if (rc == 0) g_children.insert(pid);
  }
  posix_spawnattr_destroy(&attr);
  return rc;
}

}  // namespace

void installInterruptHandler() {
  static std::once_flag once;
  std::call_once(once, [] {
    const sigset_t set = interruptSignals();
    // A blocked signal whose action is "ignore" is discarded, not queued
    // for sigwait: give each the default action first.
    for (int sig : {SIGINT, SIGTERM, SIGHUP})
      if (sigismember(&set, sig)) signal(sig, SIG_DFL);
    pthread_sigmask(SIG_BLOCK, &set, nullptr);
    std::thread([set] {
      int sig = 0;
      while (sigwait(&set, &sig) != 0) {
      }
      std::vector<pid_t> killed;
      {
        std::lock_guard<std::mutex> g(g_children_lock);
        g_interrupted = true;
        for (pid_t p : g_children)
          if (kill(-p, SIGKILL) == 0) killed.push_back(p);
      }
      // No wait: a process sent SIGKILL runs no more of its own code, so it
      // writes nothing more; its zombie is reaped by init once xval is gone.
      std::fprintf(stderr, "xval: interrupted (%s): killed %zu external process group%s\n", strsignal(sig),
                   killed.size(), killed.size() == 1 ? "" : "s");
      // Die of the same signal, as an uncaught one would have.
      signal(sig, SIG_DFL);
      sigset_t one;
      sigemptyset(&one);
      sigaddset(&one, sig);
      pthread_sigmask(SIG_UNBLOCK, &one, nullptr);
      raise(sig);
      _exit(128 + sig);
    }).detach();
  });
}

std::string attemptToken() {
  static std::mutex m;
  static std::mt19937_64 gen{(uint64_t(std::random_device{}()) << 32) ^ std::random_device{}() ^
                             uint64_t(getpid())};
  std::lock_guard<std::mutex> g(m);
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(gen()));
  return buf;
}

std::string ProcessResult::describe() const {
  if (!started) return "could not start: " + error;
  if (timed_out) {
    // %g: the time-out with the digits it was given (0.3, 2, 600), never 0.
    char t[32];
    std::snprintf(t, sizeof t, "%g", timeout_seconds);
    return std::string("timed out after ") + t + " s and was killed";
  }
  if (signal) return std::string("killed by signal ") + std::to_string(signal) + " (" +
                     strsignal(signal) + ")";
  return "exit code " + std::to_string(exit_code);
}

std::filesystem::path findOnPath(const std::string& name) {
  if (name.find('/') != std::string::npos)
    return access(name.c_str(), X_OK) == 0 ? std::filesystem::path(name) : std::filesystem::path();
  const char* path = std::getenv("PATH");
  if (!path) return {};
  std::string p = path;
  size_t start = 0;
  while (start <= p.size()) {
    size_t end = p.find(':', start);
    if (end == std::string::npos) end = p.size();
    std::filesystem::path candidate = std::filesystem::path(p.substr(start, end - start)) / name;
    std::error_code ec;
    if (!p.substr(start, end - start).empty() && std::filesystem::is_regular_file(candidate, ec) &&
        access(candidate.c_str(), X_OK) == 0)
      return candidate;
    start = end + 1;
  }
  return {};
}

ProcessResult runProcess(const std::vector<std::string>& argv, const std::filesystem::path& cwd,
                         const std::filesystem::path& log, double timeout_seconds,
                         const std::filesystem::path& progress) {
  ProcessResult r;
  r.log = log;
  r.timeout_seconds = timeout_seconds;
  std::filesystem::path exe = findOnPath(argv.at(0));
  if (exe.empty()) {
    r.error = "'" + argv[0] + "' not found on PATH";
    return r;
  }
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&fa, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_NOFOLLOW, 0644);
  posix_spawn_file_actions_adddup2(&fa, 1, 2);
  // posix_spawn_file_actions_addchdir_np: glibc >= 2.29.
  posix_spawn_file_actions_addchdir_np(&fa, cwd.c_str());
  pid_t pid = -1;
  auto t0 = std::chrono::steady_clock::now();
  const int rc = spawnInOwnGroup(exe.string(), argv, fa, pid);
  posix_spawn_file_actions_destroy(&fa);
  if (rc == EINTR) {
    r.error = exe.string() + ": not started: xval is being interrupted";
    return r;
  }
  if (rc != 0) {
    r.error = exe.string() + ": " + std::strerror(rc);
    return r;
  }
  r.started = true;
  int status = 0;
  double since = 0.0;        // when the time-out's count started (seconds after t0)
  off_t progress_size = -1;  // the progress file's size then
  for (;;) {
    pid_t w = waitpid(pid, &status, WNOHANG);
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (w == pid) break;
    struct stat st;
    if (!progress.empty() && stat(progress.c_str(), &st) == 0 && st.st_size != progress_size) {
      progress_size = st.st_size;
      since = r.seconds;
    }
    if (r.seconds - since > timeout_seconds) {
      r.timed_out = true;
      kill(-pid, SIGKILL);
      waitpid(pid, &status, 0);
      forget(pid);
      waitIfInterrupted();
      return r;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(r.seconds < 1.0 ? 5 : 50));
  }
  // The leader is reaped; kill what it left in its group (a tool's own
  // children must not outlive it and write later).
  kill(-pid, SIGKILL);
  forget(pid);
  waitIfInterrupted();
  if (WIFEXITED(status)) r.exit_code = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) r.signal = WTERMSIG(status);
  return r;
}

namespace {

// The bytes of an in-memory file from `from` to its end (at most `cap`).
std::string readBack(int fd, off_t from, size_t cap) {
  struct stat st;
  if (fstat(fd, &st) != 0 || st.st_size <= from) return {};
  std::string s(std::min<size_t>(size_t(st.st_size - from), cap), '\0');
  size_t got = 0;
  while (got < s.size()) {
    const ssize_t n = pread(fd, s.data() + got, s.size() - got, from + off_t(got));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    got += size_t(n);
  }
  s.resize(got);
  return s;
}


}  // namespace

std::string CapturedResult::summary() const {
  std::string last;
  size_t start = 0;
  while (start < diagnostics.size()) {
    size_t end = diagnostics.find('\n', start);
    if (end == std::string::npos) end = diagnostics.size();
    std::string line = diagnostics.substr(start, end - start);
    start = end + 1;
    const size_t at = line.find("ERROR: ");
    if (at != std::string::npos && line.find("Sanitizer") != std::string::npos) return line.substr(at + 7);
    if (line.find("runtime error:") != std::string::npos) return line;
    if (line.find_first_not_of(" \t") != std::string::npos) last = line;
  }
  return last;
}

CapturedResult runCaptured(const std::vector<std::string>& argv, double timeout_seconds, size_t max_output_bytes) {
  CapturedResult f;
  ProcessResult& r = f.process;
  r.timeout_seconds = timeout_seconds;
  const std::string& exe = argv.at(0);
  const int out_fd = memfd_create("xval-captured-output", MFD_CLOEXEC);
  const int err_fd = memfd_create("xval-captured-stderr", MFD_CLOEXEC);
  if (out_fd < 0 || err_fd < 0) {
    r.error = std::string("memfd_create: ") + std::strerror(errno);
    if (out_fd >= 0) close(out_fd);
    if (err_fd >= 0) close(err_fd);
    return f;
  }
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_adddup2(&fa, out_fd, 1);  // dup2 clears close-on-exec on 1 and 2
  posix_spawn_file_actions_adddup2(&fa, err_fd, 2);
  pid_t pid = -1;
  const auto t0 = std::chrono::steady_clock::now();
  const int rc = spawnInOwnGroup(exe, argv, fa, pid);
  posix_spawn_file_actions_destroy(&fa);
  if (rc != 0) {
    r.error = exe + ": " + (rc == EINTR ? std::string("not started: xval is being interrupted") : std::strerror(rc));
    close(out_fd);
    close(err_fd);
    return f;
  }
  r.started = true;
  int status = 0;
  auto pause_for = std::chrono::microseconds(100);
  for (;;) {
    const pid_t w = waitpid(pid, &status, WNOHANG);
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (w == pid) break;
    if (r.seconds > timeout_seconds) {
      r.timed_out = true;
      kill(-pid, SIGKILL);
      waitpid(pid, &status, 0);
      break;
    }
    std::this_thread::sleep_for(pause_for);
    pause_for = std::min(pause_for * 2, std::chrono::microseconds(20000));
  }
  kill(-pid, SIGKILL);  // anything it left in its group
  forget(pid);
  waitIfInterrupted();
  if (!r.timed_out) {
    if (WIFEXITED(status)) r.exit_code = WEXITSTATUS(status);
    if (WIFSIGNALED(status)) r.signal = WTERMSIG(status);
  }
  struct stat st;
  const off_t err_size = fstat(err_fd, &st) == 0 ? st.st_size : 0;
  const off_t err_from = err_size > off_t(kLogTailBytes) ? err_size - off_t(kLogTailBytes) : 0;
  f.diagnostics = readBack(err_fd, err_from, kLogTailBytes);
  for (char& c : f.diagnostics)
    if ((unsigned char)c < 0x20 && c != '\t' && c != '\n') c = ' ';
  if (r.ok()) {
    if (fstat(out_fd, &st) != 0) {
      r.exit_code = 71;
      f.diagnostics += "\nxval: cannot read the output: " + std::string(std::strerror(errno));
    } else if (size_t(st.st_size) > max_output_bytes) {
      r.exit_code = 71;
      f.diagnostics += "\nxval: its output is " + std::to_string(st.st_size) + " bytes; the limit is " +
                       std::to_string(max_output_bytes);
    } else {
      f.output = readBack(out_fd, 0, size_t(st.st_size));
      if (f.output.size() != size_t(st.st_size)) {
        r.exit_code = 71;
        f.diagnostics += "\nxval: read " + std::to_string(f.output.size()) + " of its " +
                         std::to_string(st.st_size) + " output bytes";
        f.output.clear();
      }
    }
  }
  close(out_fd);
  close(err_fd);
  return f;
}

std::string tailOfFile(const std::filesystem::path& file, int lines) {
  // Read only the last kLogTailBytes: a log may be any size.
  const int fd = open(file.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC);
  if (fd < 0) return "  | (no log at " + file.string() + ")\n";
  struct stat st;
  std::string text;
  bool cut = false;
  if (fstat(fd, &st) == 0 && S_ISREG(st.st_mode)) {
    const off_t size = st.st_size;
    const off_t from = size > off_t(kLogTailBytes) ? size - off_t(kLogTailBytes) : 0;
    cut = from > 0;
    text.resize(size_t(size - from));
    const ssize_t n = pread(fd, text.data(), text.size(), from);
    text.resize(n > 0 ? size_t(n) : 0);
  }
  close(fd);
  // A log is bytes and the cut may fall inside a character: the quote
  // starts on a character boundary and holds valid UTF-8 only
  // (files/utf8_text.h), as the records and results.json it goes into must.
  if (cut) text.erase(0, utf8CharacterStart(text, 0));
  text = validUtf8(text);
  // The last `lines` lines; the first is partial when the cut fell inside it.
  std::vector<std::string> all;
  size_t start = 0;
  while (start < text.size()) {
    size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    all.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  const size_t first = all.size() > size_t(lines) ? all.size() - size_t(lines) : 0;
  std::string out;
  for (size_t k = first; k < all.size(); ++k) {
    std::string line = all[k];
    // Keep messages readable text: no control characters but tab.
    for (char& c : line)
      if ((unsigned char)c < 0x20 && c != '\t') c = ' ';
    out += "  | " + std::string(k == 0 && cut ? "[... cut: only the last " + std::to_string(kLogTailBytes) +
                                                      " bytes of the log are quoted] "
                                                : "") +
           line + "\n";
  }
  return out.empty() ? "  | (log is empty)\n" : out;
}

}  // namespace xval
