// Assimp's read of a model file, in a process of its own.
//
// Assimp is a third-party parser of hostile input: it has crashed, hung
// and overrun buffers on malformed files (tests/fuzz/seeds/model). So it
// never runs in xval's process: xval-model-reader (model_reader_main.cpp,
// built beside xval) reads one file and writes what the loader needs to
// its standard output, and geometry/model_file.cpp runs it
// (process/run_process.h runCaptured: a time-out, its own process group,
// killed on an interrupt) and checks every byte it hands back.
//
// A fresh process, not a fork of xval's: a child forked from a process
// with other threads may find a lock held forever by a thread that does
// not exist in it (measured: a forked reader hung in the sanitizer
// allocator's lock, taken at the fork by a thread a library had just
// started; CI's sanitizer run timed out on it).
//
// The reader's output, fields of an 8-byte little-endian length and the
// bytes:
//   error      Assimp's error string (empty: it read a scene)
//   refusals   count, then each: the files GuardedIO refused
//   opened     count, then each: the files it opened, canonical
//   scene      the part of the scene the loader reads (assimp_dump.h;
//              empty with an error)
// Exit codes: 0 written; 64 bad arguments; 70 an exception (its message on
// stderr; "bad_alloc" when the memory cap was reached); 72 writing the
// output failed; 73 setting the memory cap failed.
#pragma once

#include <assimp/DefaultIOSystem.h>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "geometry/model_file.h"

namespace xval {

inline constexpr const char* kModelReader = "xval-model-reader";

// The model's folder and the files it may read: inside it, regular, within
// the size limits. Assimp opens every file through this, the model itself
// included; each refusal is kept for the error message.
class GuardedIO : public Assimp::DefaultIOSystem {
 public:
  GuardedIO(std::filesystem::path folder, const ModelLimits& limits)
      : folder_(std::move(folder)), limits_(limits) {}

  bool Exists(const char* file) const override { return allowed(file, nullptr).has_value(); }
  Assimp::IOStream* Open(const char* file, const char* mode) override;

  const std::vector<std::string>& refusals() const { return refusals_; }
  // The files opened, canonical, in order, each once.
  const std::vector<std::filesystem::path>& opened() const { return opened_; }

  // The file `name` names, when it may be read: inside the folder after
  // following symlinks, a regular file. Else nullopt and why.
  std::optional<std::filesystem::path> allowed(const std::string& name, std::string* why) const;

 private:
  std::filesystem::path folder_;
  ModelLimits limits_;
  long long total_ = 0;
  mutable std::vector<std::string> refusals_;
  std::vector<std::filesystem::path> opened_;
};

// What the reader writes for the model file `real` (canonical): the
// fields above. Runs Assimp in this process: the reader's job only.
std::string readWithAssimp(const std::filesystem::path& real, const ModelLimits& limits);

// The reader's command line for `real` under `limits` (every limit, in a
// fixed order, as decimal text), and back: "" or what is wrong with it.
std::vector<std::string> modelReaderArguments(const std::filesystem::path& reader, const std::filesystem::path& real,
                                              const ModelLimits& limits);
std::string parseModelReaderArguments(const std::vector<std::string>& args, std::filesystem::path& real,
                                      ModelLimits& limits);

// Whether the reader caps its own address space at
// ModelLimits::max_import_memory_bytes (RLIMIT_AS): not in a sanitizer
// build, whose shadow memory reserves far more.
bool modelReaderCapsMemory();

// One field of the output: 8 bytes of length, little-endian, then `bytes`.
void putField(std::string& out, const std::string& bytes);

}  // namespace xval
