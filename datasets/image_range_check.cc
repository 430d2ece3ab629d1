// SPDX-License-Identifier: MIT
#include "datasets/image_range_check.h"

#include <algorithm>
#include <cmath>

#include "core/printable_text.h"

namespace rpt {
namespace {

// Detected joints further outside their camera's image than this share of its width (u) or
// height (v): detectors place joints inside the image, or a little beyond its edge.
constexpr double kMaxOutsideShare = 0.1;
// Joints of a camera before the pixel frame is judged from where all of them lie (a few persons'
// worth: one person in a corner does not look like a half-size image).
constexpr long kMinJointsForScale = 200;
// Every coordinate within this many pixels of the origin: normalised coordinates (0-1 or -1-1).
constexpr double kMaxNormalisedPixels = 1.5;
// This share of the joints at negative coordinates (beyond the image's left or top edge by more than
// kMaxOutsideShare): the origin is not the top-left corner. Detectors place next to none there;
// coordinates from the image centre put about half of them there.
constexpr double kMinNegativeShare = 0.05;

}  // namespace

ImageRangeCheck::ImageRangeCheck(const std::vector<Camera>& cameras) : cameras_(cameras), counts_(cameras.size()) {}

void ImageRangeCheck::Add(int camera, const Poses2D& view) {
  Counts& c = counts_[static_cast<size_t>(camera)];
  const double width = cameras_[static_cast<size_t>(camera)].width;
  const double height = cameras_[static_cast<size_t>(camera)].height;
  for (int p = 0; p < view.num_persons(); ++p) {
    const auto person = view.Person(p);
    for (int j = 0; j < view.num_joints; ++j) {
      if (!(person(2, j) > 0)) continue;
      const double u = person(0, j), v = person(1, j);
      ++c.detected;
      c.max_u = std::max(c.max_u, u);
      c.max_v = std::max(c.max_v, v);
      c.max_abs = std::max({c.max_abs, std::abs(u), std::abs(v)});
      const double below = std::max(-u / width, -v / height);
      const double beyond = std::max({below, (u - width) / width, (v - height) / height});
      c.negative += below > kMaxOutsideShare ? 1 : 0;
      if (!(beyond > kMaxOutsideShare)) continue;
      ++c.outside;
      c.farthest = std::max(c.farthest, beyond);
    }
  }
}

long ImageRangeCheck::detected() const {
  long total = 0;
  for (const Counts& c : counts_) total += c.detected;
  return total;
}

void ImageRangeCheck::AddWarnings(const std::string& source, InputWarnings* warnings) const {
  for (size_t i = 0; i < cameras_.size(); ++i) {
    const Camera& camera = cameras_[i];
    const Counts& c = counts_[i];
    const std::string size = std::to_string(camera.width) + "x" + std::to_string(camera.height);
    const bool judged = c.detected >= kMinJointsForScale;
    // Normalised coordinates are no pixels at all: said instead of the rules below, whose advice
    // (scale by 2, the image size) would not fix them.
    if (judged && c.max_abs <= kMaxNormalisedPixels) {
      warnings->Add(source,
                    "detected joints of camera " + QuoteName(camera.name) +
                        ", all within 1.5 pixels of the origin (normalised coordinates, 0-1 or -1-1? give pixels of "
                        "its " + size + " image: u times the width, v times the height)",
                    "largest |u| or |v|, in pixels", c.max_abs, c.detected);
      continue;
    }
    warnings->Add(source,
                  "detected joints beyond the " + size + " image of camera " + QuoteName(camera.name) +
                      " by more than a tenth of its side (the calibration's image size, or the detections' pixel "
                      "scale, wrong?)",
                  "farthest beyond the edge, in image sides", c.farthest, c.outside);
    if (judged && static_cast<double>(c.negative) >= kMinNegativeShare * static_cast<double>(c.detected)) {
      warnings->Add(source,
                    "detected joints of camera " + QuoteName(camera.name) +
                        " at negative coordinates (is the origin at the image centre? rpt's pixels count from the "
                        "top-left corner of the image, u to the right, v down)",
                    "share of the camera's detected joints", static_cast<double>(c.negative) / c.detected, c.negative);
      continue;
    }
    // The opposite of joints beyond the image: every joint in the top-left quarter (detections from
    // a smaller image: half-size, a 1080p proxy of a 2.7K video).
    if (judged && c.max_u < 0.55 * camera.width && c.max_v < 0.55 * camera.height) {
      warnings->Add(source,
                    "detected joints of camera " + QuoteName(camera.name) + ", all in the top-left quarter of its " +
                        size + " image (detections from a smaller image, such as a half-size or 1080p proxy video? scale them "
                        "to the calibration's image size)",
                    "largest u and v, in image sides", std::max(c.max_u / camera.width, c.max_v / camera.height),
                    c.detected);
    }
  }
}

}  // namespace rpt
