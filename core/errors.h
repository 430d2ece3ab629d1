// SPDX-License-Identifier: MIT
// Error types thrown at the edges (readers, configuration). Kernels never throw.
#pragma once

#include <stdexcept>
#include <string>

#include "core/printable_text.h"

namespace rpt {

// Bad input data: missing file, malformed content, wrong shape, NaN, unknown name.
// The message names the file and the place (line, key, dataset path) where possible. Bytes of the
// message that would not print (values quoted from a damaged file) are escaped as \xNN.
class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& message) : std::runtime_error(PrintableText(message)) {}
  explicit InputError(const char* message) : InputError(std::string(message)) {}
};

// Bad configuration: unknown option, out-of-range value, inconsistent settings.
class ConfigError : public std::runtime_error {
 public:
  explicit ConfigError(const std::string& message) : std::runtime_error(PrintableText(message)) {}
  explicit ConfigError(const char* message) : ConfigError(std::string(message)) {}
};

// A file of rpt's own build is missing or unusable (e.g. the image and video module of `rpt render`
// moved away from rpt): neither the input's nor the configuration's fault, so exit code 1, but
// not an internal error either.
class InstallationError : public std::runtime_error {
 public:
  explicit InstallationError(const std::string& message) : std::runtime_error(PrintableText(message)) {}
};

}  // namespace rpt
