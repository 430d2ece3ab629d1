// SPDX-License-Identifier: MIT
#include "datasets/calibration/image_size.h"

#include <cmath>

#include "core/errors.h"

namespace rpt {
namespace {

// Twice the principal point coordinate, rounded; InputError when it is no size.
int TwiceThePrincipalPoint(double c, const char* axis, const std::string& where) {
  const double size = std::round(2.0 * c);
  if (!(size >= 1.0 && size <= 1e6)) {
    throw InputError(where + ": no image size, and twice the principal point " + axis + " (" + std::to_string(2.0 * c) +
                     ") is none: give the image size");
  }
  return static_cast<int>(size);
}

}  // namespace

void CompleteImageSize(Camera* camera, int width, int height, const std::string& source, const std::string& where,
                       InputWarnings* warnings) {
  bool guessed = false;
  if (camera->width <= 0) {
    guessed |= width <= 0;
    camera->width = width > 0 ? width : TwiceThePrincipalPoint(camera->K(0, 2), "cx", where);
  }
  if (camera->height <= 0) {
    guessed |= height <= 0;
    camera->height = height > 0 ? height : TwiceThePrincipalPoint(camera->K(1, 2), "cy", where);
  }
  if (guessed && warnings != nullptr) {
    warnings->Add(source, "image sizes missing, taken as twice the principal point", "", 0);
  }
}

}  // namespace rpt
