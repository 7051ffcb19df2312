// What a call of the public API throws, for the tests of the library.
#pragma once

#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <utility>

#include "csgray/error.h"

namespace csgray::test {

// What f throws: its code and message; a failure when it throws nothing.
inline std::pair<ErrorCode, std::string> errorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return {e.code(), e.what()};
  }
  ADD_FAILURE() << "no error";
  return {ErrorCode::Internal, ""};
}

}  // namespace csgray::test
