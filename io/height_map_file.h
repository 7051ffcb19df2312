// The heights of OpenSCAD's surface(file=) (scene/height_map.h): a text
// file of numbers, or a PNG image's grey levels, as OpenSCAD 2021.01 reads
// them (its surface.cc).
#pragma once

#include <functional>
#include <string>

#include "scene/height_map.h"
#include "scene/texture.h"

namespace csgray::detail {

// A PNG file (told by its first 8 bytes, as OpenSCAD tells it) is read with
// loadImage and each pixel's height is 100/255 of its luminance (0.2126 R +
// 0.7152 G + 0.0722 B of its 8-bit sRGB codes, ITU-R BT.709), or with
// invert 100/255 · (1 − luminance), the top row of the image at the largest
// y. Any other file is text: rows of numbers separated by spaces or tabs,
// the first row at y = 0; empty lines and lines that begin with # are left
// out, and a row shorter than the longest is filled up with 0. invert does
// nothing to text, as in OpenSCAD. name is the file as the user named it,
// for messages; throws std::invalid_argument "name:line: what".
HeightMap readHeightMap(const std::string& path, const std::string& name, bool invert,
                        const std::function<TextureImage(const std::string&)>& loadImage);

// The heights of a text file's contents (the rule above).
HeightMap heightMapOfText(const std::string& text, const std::string& name);

}  // namespace csgray::detail
