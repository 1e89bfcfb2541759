// Writing files whole (files/atomic_write.h) and folders that are never
// links (files/output_folder.h).
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>
#include <vector>

#include "support/temp_files.h"
#include "files/atomic_write.h"
#include "files/output_folder.h"

namespace fs = std::filesystem;
using namespace xval;

namespace {
fs::path freshDir(const std::string& name) { return test::freshTempDir("xval_output_files_" + name + "_" + std::to_string(getpid())); }
std::string contents(const fs::path& f) {
  std::ifstream in(f);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}
size_t entries(const fs::path& d) {
  size_t n = 0;
  for (auto it = fs::directory_iterator(d); it != fs::directory_iterator(); ++it) ++n;
  return n;
}
}  // namespace

TEST(AtomicWrite, WritesTheBytesAndLeavesNoTemporary) {
  const fs::path d = freshDir("bytes");
  writeFileAtomically(d / "a.json", "{\"x\": 1}\n");
  EXPECT_EQ(contents(d / "a.json"), "{\"x\": 1}\n");
  writeFileAtomically(d / "a.json", "second\n");
  EXPECT_EQ(contents(d / "a.json"), "second\n");
  EXPECT_EQ(entries(d), 1u);
}

TEST(AtomicWrite, ReplacesAPlantedLinkNeverItsTarget) {
  const fs::path d = freshDir("link");
  { std::ofstream(d / "victim") << "precious\n"; }
  fs::create_symlink(d / "victim", d / "out.txt");
  writeFileAtomically(d / "out.txt", "new\n");
  EXPECT_EQ(contents(d / "victim"), "precious\n");
  EXPECT_FALSE(fs::is_symlink(d / "out.txt"));
  EXPECT_EQ(contents(d / "out.txt"), "new\n");
  // The same through the callback form (the image writers').
  fs::remove(d / "out.txt");
  fs::create_symlink(d / "victim", d / "out.png");
  writeFileAtomically(d / "out.png", [](const fs::path& tmp) {
    std::ofstream(tmp) << "png\n";
    return true;
  });
  EXPECT_EQ(contents(d / "victim"), "precious\n");
  EXPECT_EQ(contents(d / "out.png"), "png\n");
}

TEST(AtomicWrite, AFailingWriterLeavesTheOldFileAndNoTemporary) {
  const fs::path d = freshDir("fail");
  writeFileAtomically(d / "r.json", "old\n");
  try {
    writeFileAtomically(d / "r.json", [](const fs::path& tmp) -> bool {
      std::ofstream(tmp) << "half";
      throw std::runtime_error("encoder gave up");
    });
    FAIL() << "no error";
  } catch (const FileWriteError& e) {
    EXPECT_NE(std::string(e.what()).find((d / "r.json").string() + ": cannot write: encoder gave up"),
              std::string::npos)
        << e.what();
  }
  EXPECT_EQ(contents(d / "r.json"), "old\n");
  EXPECT_EQ(entries(d), 1u);
  // A writer that reports failure, and one that writes nothing.
  EXPECT_THROW(writeFileAtomically(d / "r.json", [](const fs::path&) { return false; }), FileWriteError);
  EXPECT_THROW(writeFileAtomically(d / "r.json", [](const fs::path&) { return true; }), FileWriteError);
  EXPECT_EQ(contents(d / "r.json"), "old\n");
  EXPECT_EQ(entries(d), 1u);
}

TEST(AtomicWrite, RefusesAFifoAFolderAndALinkToAFifo) {
  // A FIFO of the test's own stands for a device: were the check broken,
  // the test would replace only its own file, never one in /dev.
  const fs::path d = freshDir("device");
  fs::create_directories(d / "folder");
  ASSERT_EQ(mkfifo((d / "fifo").c_str(), 0600), 0);
  fs::create_symlink(d / "fifo", d / "to_fifo");
  for (const fs::path& target : {d / "fifo", d / "folder", d / "to_fifo"}) {
    try {
      writeFileAtomically(target, "x");
      FAIL() << target << ": no error";
    } catch (const FileWriteError& e) {
      EXPECT_NE(std::string(e.what()).find("it exists and is not a regular file"), std::string::npos) << e.what();
    }
  }
  EXPECT_TRUE(fs::is_symlink(d / "to_fifo"));
  EXPECT_TRUE(fs::is_fifo(d / "fifo"));
}

TEST(AtomicWrite, WritesSeveralFilesLastOneLast) {
  const fs::path d = freshDir("several");
  writeFilesAtomically(d, {"scene.bin", "scene.gltf"}, [](const fs::path& tmp) {
    std::ofstream(tmp / "scene.bin") << "bin";
    std::ofstream(tmp / "scene.gltf") << "{}";
    return true;
  });
  EXPECT_EQ(contents(d / "scene.bin"), "bin");
  EXPECT_EQ(contents(d / "scene.gltf"), "{}");
  EXPECT_EQ(entries(d), 2u);
  // One of the set missing: neither is replaced.
  EXPECT_THROW(writeFilesAtomically(d, {"scene.bin", "scene.gltf"},
                                    [](const fs::path& tmp) {
                                      std::ofstream(tmp / "scene.bin") << "new";
                                      return true;
                                    }),
               FileWriteError);
  EXPECT_EQ(contents(d / "scene.bin"), "bin");
  EXPECT_EQ(entries(d), 2u);
}

TEST(OutputFolder, RealFolderRefusesALinkOnTheWay) {
  const fs::path d = freshDir("real");
  fs::create_directories(d / "elsewhere");
  fs::create_symlink(d / "elsewhere", d / "out_case");
  EXPECT_THROW(makeRealFolder(d, d / "out_case"), OutputFolderError);
  EXPECT_THROW(makeRealFolder(d, d / "out_case" / "sub"), OutputFolderError);
  EXPECT_TRUE(fs::is_empty(d / "elsewhere"));
  makeRealFolder(d, d / "a" / "b");
  EXPECT_TRUE(fs::is_directory(d / "a" / "b"));
  EXPECT_THROW(makeRealFolder(d / "a", d), OutputFolderError);  // not inside
}

TEST(OutputFolder, RealFolderMadeByManyJobsAtOnceIsNoError) {
  // The three jobs of a scene create its case folder at the same moment.
  const fs::path d = freshDir("race");
  for (int round = 0; round < 50; ++round) {
    const fs::path target = d / ("case" + std::to_string(round)) / "sub";
    std::vector<std::thread> pool;
    std::vector<std::string> errors(8);
    for (int t = 0; t < 8; ++t)
      pool.emplace_back([&, t] {
        try {
          makeRealFolder(d, target);
        } catch (const std::exception& e) {
          errors[t] = e.what();
        }
      });
    for (auto& th : pool) th.join();
    for (const auto& e : errors) EXPECT_EQ(e, "") << "round " << round;
  }
}

TEST(OutputFolder, FreshFolderRemovesALinkNotItsTarget) {
  const fs::path d = freshDir("fresh");
  fs::create_directories(d / "elsewhere");
  { std::ofstream(d / "elsewhere" / "keep") << "k"; }
  fs::create_symlink(d / "elsewhere", d / "povray.work");
  makeFreshFolder(d / "povray.work");
  EXPECT_FALSE(fs::is_symlink(d / "povray.work"));
  EXPECT_TRUE(fs::is_empty(d / "povray.work"));
  EXPECT_TRUE(fs::exists(d / "elsewhere" / "keep"));
  { std::ofstream(d / "povray.work" / "old.png") << "o"; }
  makeFreshFolder(d / "povray.work");
  EXPECT_TRUE(fs::is_empty(d / "povray.work"));
}

TEST(OutputFolder, ASecondLockIsRefusedNamingTheHolder) {
  const fs::path d = freshDir("lock");
  {
    FolderLock first(d, FolderLock::Mode::Exclusive, "xval validate");
    try {
      FolderLock second(d, FolderLock::Mode::Exclusive, "xval validate");
      FAIL() << "second lock taken";
    } catch (const OutputFolderError& e) {
      EXPECT_NE(std::string(e.what()).find("pid " + std::to_string(getpid())), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(d.string() + ": another xval validate"), std::string::npos) << e.what();
    }
    EXPECT_THROW(FolderLock(d, FolderLock::Mode::Shared, "x"), OutputFolderError);
  }
  // Released: shared holders coexist, and exclude an exclusive one.
  FolderLock a(d, FolderLock::Mode::Shared, "x");
  FolderLock b(d, FolderLock::Mode::Shared, "x");
  EXPECT_THROW(FolderLock(d, FolderLock::Mode::Exclusive, "x"), OutputFolderError);
}

TEST(OutputFolder, ToolPathsWithCharactersToolsMisreadAreRefused) {
  for (const char* bad : {"/tmp/a\\b", "/tmp/x?y", "/tmp/new\nline"})
    EXPECT_THROW(checkToolPath(bad), OutputFolderError) << bad;
  EXPECT_NO_THROW(checkToolPath("/tmp/a b/$(x)/`y`;z\"w/it's"));
}
