// PNG files read without OpenImageIO. Loading OpenImageIO's module costs
// 0.4 s (its 260 shared libraries), ten times the render of a small
// textured part; PNG is the format of most textures and of OpenSCAD's
// surface() images, so csgray reads it itself, every kind the format has
// (W3C PNG Specification, 2nd edition = ISO/IEC 15948): grey, grey with
// alpha, RGB, RGBA and palette images, 1 to 16 bits a sample, interlaced
// (Adam7) or not.
#pragma once

#include <string>
#include <vector>

namespace csgray::detail {

// Do these bytes begin with the PNG signature?
bool hasPngSignature(const std::string& bytes);

// An image's colour as stored, before any transfer function: each sample
// is its code over the largest code of its bit depth, in [0, 1].
struct PngPixels {
  int width = 0, height = 0;
  bool grey = false;          // one value a pixel, else three (R, G, B)
  std::vector<float> values;  // row-major from the top row
};

// Decodes a whole PNG file. Alpha (an alpha channel or a tRNS chunk) is
// left out; a palette image gives the RGB of its entries; samples of 1, 2
// or 4 bits are spread over [0, 1] as 8-bit codes are. Images of more than
// maxPixels pixels are refused before their data are inflated. Throws
// std::runtime_error saying in a few words what is wrong (a bad chunk, a
// CRC mismatch, data that end early, ...).
PngPixels decodePng(const std::string& bytes, long maxPixels);

}  // namespace csgray::detail
