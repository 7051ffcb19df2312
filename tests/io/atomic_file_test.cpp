// Atomic writes: an output that is not a regular file (a FIFO, a device
// such as /dev/full) is refused before any work and again at the rename,
// so that nothing takes its place; and an output whose name is near the
// file system's limit is written, its temporary's name cut to fit.
#include "io/atomic_file.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "io/image_file.h"
#include "io/scratch_folder.h"

namespace csgray::detail {
namespace {

namespace fs = std::filesystem;

class AtomicFiles : public test::ScratchFolder {
 protected:
  // What is left in the folder besides `except`.
  int othersThan(const std::string& except) const {
    int n = 0;
    for (const auto& entry : fs::directory_iterator(path("")))
      n += entry.path().filename() != except;
    return n;
  }
};

TEST_F(AtomicFiles, ANewOrRegularFileMayBeWritten) {
  EXPECT_EQ(outputPathProblem(path("new.png")), "");
  std::ofstream(path("old.png")) << "old";
  EXPECT_EQ(outputPathProblem(path("old.png")), "");
}

TEST_F(AtomicFiles, WhatIsNotARegularFileIsRefusedBeforeTheWork) {
  std::string fifo = path("out.png");
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_EQ(outputPathProblem(fifo), "it is a FIFO, not a regular file");
  EXPECT_EQ(outputPathProblem(path("")), "it is a folder");
  // /dev is writable to root, who could otherwise replace /dev/full.
  EXPECT_EQ(outputPathProblem("/dev/full"), "it is a character device, not a regular file");
  EXPECT_EQ(imageOutputProblem("/dev/null"), "it is a character device, not a regular file");
}

TEST_F(AtomicFiles, AFifoMadeDuringTheWorkIsNotReplaced) {
  std::string target = path("out.txt");
  AtomicFile file(target);
  std::ofstream(file.tempPath()) << "data";
  ASSERT_EQ(::mkfifo(target.c_str(), 0600), 0);
  try {
    file.commit();
    ADD_FAILURE() << "the FIFO was replaced";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()),
              "cannot write " + target + ": it is a FIFO, not a regular file");
  }
  struct stat info {};
  ASSERT_EQ(::stat(target.c_str(), &info), 0);
  EXPECT_TRUE(S_ISFIFO(info.st_mode));
}

TEST_F(AtomicFiles, ANameAtTheLimitIsWrittenAndOneOverItRefused) {
  const long limit = ::pathconf(path("").c_str(), _PC_NAME_MAX);
  ASSERT_GT(limit, 20);
  for (long length : {limit - 6, limit - 4}) {  // with ".png", 2 bytes under and at the limit
    std::string name = std::string(std::size_t(length), 'n') + ".png";
    std::string target = path(name);
    EXPECT_EQ(outputPathProblem(target), "");
    AtomicFile file(target);
    EXPECT_LE(fs::path(file.tempPath()).filename().string().size(), std::size_t(limit));
    EXPECT_EQ(fs::path(file.tempPath()).extension(), ".png");
    std::ofstream(file.tempPath()) << "data";
    EXPECT_NO_THROW(file.commit());
    EXPECT_TRUE(fs::is_regular_file(target));
    EXPECT_EQ(othersThan(name), 0);
    fs::remove(target);
  }
  std::string over = path(std::string(std::size_t(limit) - 3, 'n') + ".png");
  EXPECT_EQ(outputPathProblem(over),
            "the file name is longer than " + std::to_string(limit) + " bytes");
}

// Two writes to the same long name at once get temporaries of their own.
TEST_F(AtomicFiles, CutTemporaryNamesStayUnique) {
  const long limit = ::pathconf(path("").c_str(), _PC_NAME_MAX);
  std::string target = path(std::string(std::size_t(limit) - 4, 'n') + ".png");
  AtomicFile a(target), b(target);
  EXPECT_NE(a.tempPath(), b.tempPath());
}

}  // namespace
}  // namespace csgray::detail
