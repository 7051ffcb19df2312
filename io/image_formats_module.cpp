// The part of csgray that reads and writes images through OpenImageIO,
// built as a module that image_formats.cpp loads only when an image format
// other than PNG is written or read: Debian's OpenImageIO pulls
// in about 260 shared libraries, whose loading would otherwise cost every
// run ~0.2 s and ~100 MB before any work.
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

#include "io/file_bytes.h"
#include "io/image_formats.h"
#include "io/srgb.h"

namespace csgray::detail {

namespace {

// OIIO's error texts may run over several lines, some of which repeat
// others ("Read error: hit end of file", then "PNG read error: IHDR: Read
// error: hit end of file"); errors here are one line, each part once.
std::string oneLine(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    while (!line.empty() && std::isspace(static_cast<unsigned char>(line.back()))) line.pop_back();
    if (!line.empty()) lines.push_back(line);
  }
  std::string joined;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    bool repeated = false;
    for (std::size_t j = 0; j < lines.size() && !repeated; ++j)
      repeated =
          j != i && lines[j].find(lines[i]) != std::string::npos && (lines[j] != lines[i] || j < i);
    if (!repeated) joined += (joined.empty() ? "" : "; ") + lines[i];
  }
  return joined.empty() ? "unknown error" : joined;
}

// libpng, through which OIIO reads PNG files, prints its errors and
// warnings on standard error itself ("libpng error: ..."), and OIIO then
// reports them again. While an image is read, stdio's stderr (a variable
// that glibc lets a program set) writes into memory instead: csgray says
// what went wrong in one line of its own, from OIIO's errors, or from what
// was printed where OIIO has none. Reads take turns, since stderr is one
// for the whole process.
class CapturedStderr {
 public:
  CapturedStderr() : lock_(mutex()) {
    std::fflush(stderr);
    capture_ = open_memstream(&text_, &size_);
    if (capture_) std::swap(stderr, capture_);
  }
  ~CapturedStderr() {
    restore();
    std::free(text_);
  }
  CapturedStderr(const CapturedStderr&) = delete;
  CapturedStderr& operator=(const CapturedStderr&) = delete;

  // What was printed so far; printing goes to stderr again from here on.
  std::string text() {
    restore();
    return text_ ? std::string(text_, size_) : "";
  }

 private:
  static std::mutex& mutex() {
    static std::mutex m;
    return m;
  }
  void restore() {
    if (!capture_) return;
    std::swap(stderr, capture_);
    std::fclose(capture_);
    capture_ = nullptr;
  }

  std::lock_guard<std::mutex> lock_;
  FILE* capture_ = nullptr;
  char* text_ = nullptr;
  std::size_t size_ = 0;
};

// An image file in memory, written at any position as a file is (TIFF
// seeks back to patch offsets in its header; OpenImageIO's own vector
// proxy appends every write whatever the position, which breaks it).
class MemoryFile : public OIIO::Filesystem::IOProxy {
 public:
  MemoryFile() : IOProxy("", Write) {}
  const char* proxytype() const override { return "csgray memory"; }
  std::size_t write(const void* data, std::size_t size) override {
    const std::size_t written = pwrite(data, size, m_pos);
    m_pos += int64_t(written);
    return written;
  }
  std::size_t pwrite(const void* data, std::size_t size, int64_t offset) override {
    if (offset < 0) return 0;
    const std::size_t end = std::size_t(offset) + size;
    if (end > bytes_.size()) bytes_.resize(end);
    std::copy_n(static_cast<const char*>(data), size, bytes_.begin() + offset);
    return size;
  }
  std::size_t read(void* data, std::size_t size) override {
    const std::size_t got = pread(data, size, m_pos);
    m_pos += int64_t(got);
    return got;
  }
  std::size_t pread(void* data, std::size_t size, int64_t offset) override {
    if (offset < 0 || std::size_t(offset) >= bytes_.size()) return 0;
    const std::size_t got = std::min(size, bytes_.size() - std::size_t(offset));
    std::copy_n(bytes_.begin() + offset, got, static_cast<char*>(data));
    return got;
  }
  std::size_t size() const override { return bytes_.size(); }
  const std::string& bytes() const { return bytes_; }

 private:
  std::string bytes_;
};

bool keepsFloat(const std::string& formatName) {
  return formatName == "openexr" || formatName == "hdr" || formatName == "pfm";
}

std::string outputProblem(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  auto out = OIIO::ImageOutput::create(path);
  // OpenImageIO's "term" writer draws on the terminal, its "null" one
  // drops the pixels: neither makes a file.
  if (!out || out->format_name() == std::string("term") ||
      out->format_name() == std::string("null")) {
    (void)OIIO::geterror();
    return "unknown image format '" + ext + "'";
  }
  return "";
}

void write(const std::string& tempPath, const std::string& path, int width, int height,
           const float* rgb, ImageData data) {
  auto out = OIIO::ImageOutput::create(tempPath);
  if (!out) throw std::runtime_error("cannot write " + path + ": " + oneLine(OIIO::geterror()));
  // Encoded into memory, then written by csgray, where the format allows:
  // libjpeg, failing to write a file (a full disk), prints its own line
  // and ends the process, which leaves the temporary file behind; the BMP
  // and Targa writers do not notice, and report a file with holes as
  // written; others name the temporary instead of the file asked for.
  // Not TIFF: OpenImageIO 2.4 writes it to memory without its last
  // directory (unreadable), and it reports a failed write to a file itself.
  MemoryFile memory;
  const bool inMemory = out->format_name() != std::string("tiff") && out->supports("ioproxy") &&
                        out->set_ioproxy(&memory);
  bool linear = keepsFloat(out->format_name());
  OIIO::ImageSpec spec(width, height, 3, linear ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8);
  bool encode = !linear && data == ImageData::LinearColor;
  spec.attribute("oiio:ColorSpace", encode ? "sRGB" : "linear");
  std::vector<float> pixels(rgb, rgb + static_cast<size_t>(width) * height * 3);
  if (encode)
    for (float& v : pixels) v = encodeSrgb(v);
  // (In memory, the name is the file's own: DPX keeps it in its header.)
  if (!out->open(inMemory ? path : tempPath, spec) ||
      !out->write_image(OIIO::TypeDesc::FLOAT, pixels.data()) || !out->close()) {
    std::string why = out->geterror();
    throw std::runtime_error("cannot write " + path + ": " +
                             (why.empty() ? "write failed" : oneLine(why)));
  }
  if (inMemory) writeFileBytes(tempPath, path, memory.bytes().data(), memory.bytes().size());
}

TextureImage read(const std::string& path) {
  CapturedStderr printed;
  auto fail = [&](const std::string& why) {
    return std::runtime_error("cannot read texture image " + path + ": " +
                              oneLine(why.empty() ? printed.text() : why));
  };
  // Colours as stored: without this, OIIO multiplies them by alpha on
  // reading (PNG, TIFF, ...), which would darken translucent texels.
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  auto in = OIIO::ImageInput::open(path, &config);
  if (!in) throw fail(OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0) throw fail("the image is empty");
  if (long(spec.width) * spec.height > kMaxTexturePixels)
    throw fail(std::to_string(spec.width) + "x" + std::to_string(spec.height) +
               " pixels, more than a texture may have (" + std::to_string(kMaxTexturePixels) + ")");
  if (spec.depth > 1 || spec.deep) throw fail("volume and deep images are not textures");
  // Channels 0..2 as RGB, or channel 0 as grey (also for grey + alpha).
  int channels = spec.nchannels >= 3 ? 3 : 1;
  bool floatData = spec.format.basetype == OIIO::TypeDesc::FLOAT ||
                   spec.format.basetype == OIIO::TypeDesc::HALF ||
                   spec.format.basetype == OIIO::TypeDesc::DOUBLE;
  TextureImage image;
  image.width = spec.width;
  image.height = spec.height;
  std::size_t pixels = static_cast<std::size_t>(spec.width) * spec.height;
  image.rgb.resize(pixels * 3);
  // Read into the front of the buffer (packed, channels per pixel) and, for
  // grey, spread from the back so that no value is overwritten before use.
  // A read that succeeds may have met errors all the same (a JPEG or TIFF
  // file cut short reads as grey where its data end): they fail it too.
  bool whole = in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, image.rgb.data());
  whole = in->close() && whole;
  if (!whole || in->has_error()) throw fail(in->geterror());
  if (channels == 1)
    for (std::size_t i = pixels; i-- > 0;) {
      float grey = image.rgb[i];
      for (int c = 0; c < 3; ++c) image.rgb[i * 3 + c] = grey;
    }
  for (float& v : image.rgb) {
    // Integer formats hold sRGB code values (as writeImage writes them);
    // a NaN or infinity in a float file would spread through a render.
    if (!floatData)
      v = decodeSrgb(v);
    else if (!std::isfinite(v))
      v = 0.0f;
  }
  return image;
}

}  // namespace

}  // namespace csgray::detail

extern "C" __attribute__((visibility("default"))) const csgray::detail::ImageFormats*
csgray_image_formats() {
  // Qualified: unistd.h has a write and a read of its own.
  static const csgray::detail::ImageFormats formats{csgray::detail::outputProblem,
                                                    csgray::detail::write, csgray::detail::read};
  return &formats;
}
