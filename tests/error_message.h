// SPDX-License-Identifier: MIT
// The message of the exception a call throws, for asserting on error texts.
#pragma once

#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "core/errors.h"

namespace rpt::test {

// The message of the `Error` that `f` throws; records a test failure when it throws none.
template <typename Error = InputError>
std::string ErrorMessage(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected an exception of the expected type";
  return "<no exception of the expected type>";
}

inline std::string InputErrorOf(const std::function<void()>& f) { return ErrorMessage<InputError>(f); }
inline std::string ConfigErrorOf(const std::function<void()>& f) { return ErrorMessage<ConfigError>(f); }

}  // namespace rpt::test
