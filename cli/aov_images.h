// The depth and normal images (AOVs) that csgray render writes beside its
// colour image.
#pragma once

#include <string>

#include "io/atomic_file.h"
#include "raytrace/image.h"

namespace csgray::detail {

// The name of an AOV image beside the colour image: out.png and "depth"
// give out.depth.png.
std::string aovPath(const std::string& output, const std::string& aov);

// Writes a depth or normal image. Float formats keep the values (depth in
// model units, +inf where nothing was hit; normals in [-1, 1]); 8-bit
// formats get a picture of them: depth as nearest / depth (white at the
// nearest surface, black where nothing was hit), normals as (n + 1) / 2
// (black where nothing was hit).
// Into file's temporary (file is of path), which the caller commits with
// the colour image.
void writeAov(AtomicFile& file, const std::string& path, Image image, bool isDepth, int threads);

}  // namespace csgray::detail
