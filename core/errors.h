// SPDX-License-Identifier: MIT
// Error types thrown at the edges (readers, configuration). Kernels never throw.
#pragma once

#include <stdexcept>
#include <string>

namespace rpt {

// Bad input data: missing file, malformed content, wrong shape, NaN, unknown name.
// The message names the file and the place (line, key, dataset path) where possible.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Bad configuration: unknown option, out-of-range value, inconsistent settings.
class ConfigError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace rpt
