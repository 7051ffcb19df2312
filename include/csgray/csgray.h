// The csgray library: exact CSG parts, previews ray traced from the exact
// shapes, printable meshes, and their check. docs/library.md describes it.
#pragma once

#include "csgray/check.h"
#include "csgray/error.h"
#include "csgray/material.h"
#include "csgray/mesh.h"
#include "csgray/region.h"
#include "csgray/render.h"
#include "csgray/scene.h"
#include "csgray/script.h"
#include "csgray/solid.h"
#include "csgray/types.h"

namespace csgray {

// "0.1.0"
CSGRAY_API const char* version();

}  // namespace csgray
