// SPDX-License-Identifier: MIT
// Has a camera's stream frozen? A hung camera or detector keeps sending one frame's detections:
// each person it shows stays where it was while the people move, and the persons triangulated
// from it and the cameras that see the present are ghosts (a 13 s freeze of one of 3 cameras:
// 13 track ids for 2 people, MPJPE 59 -> 87 mm), which neither the camera agreement (51 % of its
// persons still matched) nor any other check said. Real detections never repeat bit for bit from
// one frame to the next (sensor noise alone changes them); a frame whose views all repeat their
// last one (a still scene under the simulated perfect detector) says nothing either way. A camera
// whose non-empty view repeats its last one, bit for bit, while another camera's view changed, for
// kMinFrozenFrames frames in a row is named.
#pragma once

#include <string>
#include <vector>

#include "core/camera.h"
#include "core/poses.h"
#include "datasets/sequence.h"

namespace rpt::engine {

// Frames in a row: longer than a person standing still under the perfect simulated detector
// (people wait up to 3 s, 75 frames at 25 fps) sees.
inline constexpr long kMinFrozenFrames = 100;

class FrozenViewCheck {
 public:
  explicit FrozenViewCheck(size_t num_cameras);
  // The next frame of the sequence, in order. Allocates nothing once its copies have grown to
  // the largest view.
  void Add(const SequenceFrame& frame);
  // Per camera: the longest run of frames its view repeated while another's changed.
  const std::vector<long>& longest() const { return longest_; }

 private:
  std::vector<Poses2D> last_;     // per camera: its view of the frame before
  std::vector<char> repeated_;    // per camera: this frame's view is the last one again (scratch)
  std::vector<long> run_, longest_;
};

// One line per camera whose longest run reached kMinFrozenFrames; `fps` > 0 adds the time.
std::vector<std::string> FrozenViewWarnings(const std::string& sequence, const std::vector<Camera>& cameras,
                                            const std::vector<long>& longest, double fps);

}  // namespace rpt::engine
