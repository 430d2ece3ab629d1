// SPDX-License-Identifier: MIT
// MP4 files for `rpt render`, through OpenCV's video writer (FFmpeg backend, in the image and video
// module: image_codecs.h). H.264 ("avc1", plays in browsers and slide software) when the OpenCV
// build can encode it (Debian 12's can, through libx264), else MPEG-4 Part 2 ("mp4v").
#pragma once

#include <filesystem>
#include <opencv2/core.hpp>
#include <string>

#include "datasets/io/staged_output.h"
#include "engine/render/image_codecs.h"

namespace rpt::engine {

// The video is written under a temporary name beside `path` (io::StagedFile, ending in .mp4 so that
// FFmpeg picks the container) and renamed over `path` by Finish(): an interrupted render leaves the
// previous video intact, and a link at `path` is replaced, never written through.
class Mp4Writer {
 public:
  // Opens `path` for frames of `size` at `fps`; throws InputError naming the file when no codec
  // can write it, InstallationError when the image and video module cannot be loaded.
  Mp4Writer(const std::filesystem::path& path, cv::Size size, double fps);
  ~Mp4Writer();
  Mp4Writer(const Mp4Writer&) = delete;
  Mp4Writer& operator=(const Mp4Writer&) = delete;
  // Appends one frame (BGR, 8 bit, the size given at construction).
  void Write(const cv::Mat& frame);
  // Closes the video and puts it in place; throws InputError naming the file.
  void Finish();
  // The fourcc in use: "avc1" or "mp4v".
  const std::string& codec() const { return codec_; }
  long frames() const { return frames_; }

 private:
  const ImageCodecs& codecs_;
  io::StagedFile file_;
  void* writer_ = nullptr;  // the module's writer until Finish()
  std::string codec_;
  long frames_ = 0;
};

}  // namespace rpt::engine
