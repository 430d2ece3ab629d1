// SPDX-License-Identifier: MIT
// The colours of tracks in everything rpt draws (rpt render's overlays, report.html's 3D view and
// camera views): one list, so that a person has the same colour in both. Tableau 10 without its
// grey (grey marks detections and the GT) and its red (red marks a missed GT person in the report:
// a red track read as missed), as RGB.
#pragma once

#include <array>
#include <cstdint>

namespace rpt::engine {

struct Rgb {
  std::uint8_t r, g, b;
};

inline constexpr std::array<Rgb, 8> kTrackPalette = {{{31, 119, 180},
                                                      {255, 127, 14},
                                                      {44, 160, 44},
                                                      {148, 103, 189},
                                                      {140, 86, 75},
                                                      {227, 119, 194},
                                                      {188, 189, 34},
                                                      {23, 190, 207}}};

// The palette index of a track id (non-negative, also for negative keys).
inline int TrackPaletteIndex(int key) {
  const int n = static_cast<int>(kTrackPalette.size());
  return ((key % n) + n) % n;
}

}  // namespace rpt::engine
