// render() and writeImage(): the renderer and the image files of the
// csgray command (raytrace/renderer.h, io/image_file.h).
#include "csgray/render.h"

#include <algorithm>
#include <stdexcept>
#include <thread>

#include "api/access.h"
#include "api/errors.h"
#include "io/image_file.h"
#include "raytrace/renderer.h"
#include "scene/value_checks.h"

namespace csgray {

namespace {

// The command line's limits on the size of an image.
constexpr int kMaxSide = 16384;
constexpr long kMaxPixels = 64L * 1024 * 1024;

void checkOptions(const RenderOptions& o) {
  detail::checkWhole("render", "width", o.width, 1, kMaxSide);
  detail::checkWhole("render", "height", o.height, 1, kMaxSide);
  if (long(o.width) * o.height > kMaxPixels)
    throw std::invalid_argument("render: the image has more than " + std::to_string(kMaxPixels) +
                                " pixels");
  detail::checkWhole("render", "threads", o.threads, 0, 1024);
  detail::checkWhole("render", "samples", o.samples, 0, 1024);
}

}  // namespace

Image render(const Scene& scene, const RenderOptions& options) {
  return detail::guarded([&] {
    checkOptions(options);
    const detail::Scene& s = detail::Access::of(scene);
    detail::checkHasObjects(s);
    detail::RenderOptions o(options.width, options.height, options.threads);
    // As the command: a bare part is antialiased at its edges unless the
    // samples are given.
    const bool cadSamples = options.samples == 0 && s.cadLook;
    o.samples = cadSamples ? detail::kCadLookSamples : std::max(options.samples, 1);
    o.adaptive = options.adaptive || cadSamples;
    o.edges = options.edges;
    o.cancel = options.cancel;
    const detail::Image rendered = [&] {
      try {
        return detail::Renderer(s, o).render();
      } catch (const detail::RenderCancelled&) {
        throw Error(ErrorCode::Cancelled, "render: cancelled");
      }
    }();
    Image image;
    image.width = rendered.width;
    image.height = rendered.height;
    image.rgb.assign(rendered.rgb.begin(), rendered.rgb.end());
    return image;
  });
}

void writeImage(const Image& image, const std::string& path) {
  if (image.width < 1 || image.height < 1 ||
      image.rgb.size() != std::size_t(image.width) * std::size_t(image.height) * 3)
    throw Error(ErrorCode::InvalidArgument,
                "writeImage: the image must have width · height · 3 values, width and height >= 1");
  // A name whose extension is no format is a bad argument, as writeMesh's
  // (asks OpenImageIO about formats other than PNG, loading it).
  detail::guarded(ErrorCode::InvalidArgument, [&] {
    if (std::string problem = detail::imageFormatProblem(path); !problem.empty())
      throw std::invalid_argument("cannot write " + path + ": " + problem);
  });
  detail::guarded(ErrorCode::IoError, [&] {
    if (std::string problem = detail::imageOutputProblem(path); !problem.empty())
      throw std::runtime_error("cannot write " + path + ": " + problem);
    const int threads = std::max(1, int(std::thread::hardware_concurrency()));
    detail::writeImage(path, image.width, image.height, image.rgb.data(),
                       detail::ImageData::LinearColor, threads);
  });
}

}  // namespace csgray
