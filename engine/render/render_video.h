// SPDX-License-Identifier: MIT
// MP4 files for `rpt render`, through OpenCV's video writer (FFmpeg backend). H.264 ("avc1",
// plays in browsers and slide software) when the OpenCV build can encode it (Debian 12's can,
// through libx264), else MPEG-4 Part 2 ("mp4v").
#pragma once

#include <filesystem>
#include <opencv2/core.hpp>
#include <opencv2/videoio.hpp>
#include <string>

namespace rpt::engine {

class Mp4Writer {
 public:
  // Opens `path` for frames of `size` at `fps`; throws InputError naming the file when no codec
  // can write it.
  Mp4Writer(const std::filesystem::path& path, cv::Size size, double fps);
  // Appends one frame (BGR, 8 bit, the size given at construction).
  void Write(const cv::Mat& frame);
  // The fourcc in use: "avc1" or "mp4v".
  const std::string& codec() const { return codec_; }
  long frames() const { return frames_; }

 private:
  cv::VideoWriter writer_;
  std::string codec_;
  long frames_ = 0;
};

}  // namespace rpt::engine
