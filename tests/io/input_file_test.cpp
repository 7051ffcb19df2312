// Files a user names as input (the script, meshes, texture images): a FIFO,
// a folder or a device is refused at once and by name (a FIFO would block
// open() for ever), regular files are read whole or up to a limit, and a
// corrupt texture image gives one error line naming the file, with nothing
// printed by the libraries that read it.
#include "io/input_file.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/image_file.h"
#include "io/scratch_folder.h"
#include "meshio/mesh_reader.h"
#include "script/script.h"

namespace csgray::detail {
namespace {

namespace fs = std::filesystem;

class InputFiles : public test::ScratchFolder {
 protected:
  void SetUp() override {
    ScratchFolder::SetUp();
    // An open() that waits on a FIFO ends the test with SIGALRM, not never.
    ::alarm(60);
  }
  void TearDown() override {
    ::alarm(0);
    ScratchFolder::TearDown();
  }
  std::string fifo(const std::string& name) const {
    std::string p = path(name);
    EXPECT_EQ(::mkfifo(p.c_str(), 0600), 0);
    return p;
  }
  void write(const std::string& p, const std::string& bytes) const {
    std::ofstream(p, std::ios::binary) << bytes;
  }
};

TEST_F(InputFiles, ARegularFileIsReadWhole) {
  write(path("a.txt"), "hello");
  InputFile file(path("a.txt"));
  EXPECT_EQ(file.problem(), "");
  EXPECT_EQ(file.size(), 5u);
  std::string bytes;
  EXPECT_TRUE(file.readUpTo(bytes, 100));
  EXPECT_EQ(bytes, "hello");
}

TEST_F(InputFiles, ReadingStopsAtTheLimit) {
  write(path("a.txt"), "hello");
  InputFile file(path("a.txt"));
  std::string bytes;
  EXPECT_TRUE(file.readUpTo(bytes, 3));
  EXPECT_EQ(bytes, "hel");
}

// Without O_NONBLOCK this test would never end: no one writes the FIFO.
TEST_F(InputFiles, AFifoIsRefusedWithoutWaitingForAWriter) {
  std::string p = fifo("pipe.lua");
  EXPECT_EQ(InputFile(p).problem(), "it is a FIFO, not a regular file");
  EXPECT_EQ(InputFile(p, /*devicesToo=*/true).problem(), "it is a FIFO, not a regular file");
}

TEST_F(InputFiles, FoldersMissingFilesAndDevicesAreNamed) {
  fs::create_directories(path("folder"));
  EXPECT_EQ(inputFileProblem(path("folder")), "it is a folder");
  EXPECT_EQ(inputFileProblem(path("missing")), "no such file");
  EXPECT_EQ(inputFileProblem("/dev/null"), "it is a character device, not a regular file");
}

TEST_F(InputFiles, ADeviceIsReadWhereAllowed) {
  InputFile zero("/dev/zero", /*devicesToo=*/true);
  ASSERT_EQ(zero.problem(), "");
  std::string bytes;
  EXPECT_TRUE(zero.readUpTo(bytes, 1000));
  EXPECT_EQ(bytes, std::string(1000, '\0'));
}

TEST_F(InputFiles, AMeshThatIsAFifoIsRefusedByName) {
  std::string p = fifo("part.stl");
  try {
    readMeshFile(p);
    ADD_FAILURE() << "a FIFO was read as a mesh";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "part.stl: it is a FIFO, not a regular file");
  }
}

TEST_F(InputFiles, AScriptThatIsAFifoIsRefusedByName) {
  std::string p = fifo("part.lua");
  try {
    runScriptFile(p);
    ADD_FAILURE() << "a FIFO was run as a script";
  } catch (const ScriptError& e) {
    EXPECT_EQ(std::string(e.what()), p + ": cannot open script: it is a FIFO, not a regular file");
  }
}

// The message of readTextureImage's error, and what was printed meanwhile.
struct TextureError {
  std::string message, printed;
};
TextureError textureError(const std::string& file) {
  TextureError error;
  ::testing::internal::CaptureStderr();
  try {
    readTextureImage(file);
    error.message = "(no error)";
  } catch (const std::runtime_error& e) {
    error.message = e.what();
  }
  error.printed = ::testing::internal::GetCapturedStderr();
  return error;
}

TEST_F(InputFiles, ATextureThatIsAFifoIsRefusedByName) {
  std::string p = fifo("bricks.png");
  EXPECT_EQ(textureError(p).message,
            "cannot read texture image " + p + ": it is a FIFO, not a regular file");
}

// libpng prints its errors itself, and OpenImageIO reads a JPEG or TIFF
// file cut short as if it were whole, noting an error: each corrupt image
// is one error line naming the file, and nothing else is printed.
TEST_F(InputFiles, ACorruptTextureImageIsOneErrorLineAndNothingPrinted) {
  const int w = 64, h = 64;
  std::vector<float> rgb(std::size_t(w) * h * 3);
  for (std::size_t i = 0; i < rgb.size(); ++i) rgb[i] = float((i * 7919) % 251) / 250.0f;
  for (const std::string ext : {"png", "jpg", "tif", "exr"}) {
    std::string good = path("good." + ext);
    writeImage(good, w, h, rgb.data());
    std::ifstream in(good, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    ASSERT_GT(bytes.size(), 100u) << ext;
    // Cut short in the pixels, cut short in the header, and with junk in the
    // compressed data of a PNG (whose chunks have checksums).
    std::vector<std::pair<std::string, std::string>> bad = {
        {"half." + ext, bytes.substr(0, bytes.size() / 2)}, {"head." + ext, bytes.substr(0, 40)}};
    if (ext == "png") {
      std::string junk = bytes;
      for (std::size_t i = junk.size() / 2; i < junk.size() / 2 + 12; ++i) junk[i] = char(0xA5);
      bad.emplace_back("junk.png", junk);
    }
    for (const auto& [name, content] : bad) {
      write(path(name), content);
      TextureError error = textureError(path(name));
      EXPECT_EQ(error.message.rfind("cannot read texture image " + path(name) + ": ", 0), 0u)
          << error.message;
      EXPECT_EQ(error.message.find('\n'), std::string::npos) << error.message;
      EXPECT_EQ(error.printed, "") << name;
    }
  }
}

}  // namespace
}  // namespace csgray::detail
