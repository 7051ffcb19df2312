// The base of every shape in this folder: a Primitive whose clone() (the
// copy that withFrame and withMaterial start from) is written once here
// for the shape T that derives from PrimitiveShape<T> (the curiously
// recurring template pattern), rather than once in each shape.
//
// Only clone() is shared: its body is the same for every shape. The ray
// overrides (objectSpans, objectContains, objectNormal) differ in every
// shape and stay its own, called through Primitive's vtable as before, so
// a ray costs what it did.
#pragma once

#include <memory>

#include "engine/primitive.h"

namespace csgray::detail {

template <class T>
class PrimitiveShape : public Primitive {
 protected:
  std::shared_ptr<Primitive> clone() const final {
    return std::make_shared<T>(static_cast<const T&>(*this));
  }
};

}  // namespace csgray::detail
