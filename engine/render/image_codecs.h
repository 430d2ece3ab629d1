// SPDX-License-Identifier: MIT
// Image and video files for `rpt render` (OpenCV's imgcodecs and videoio), loaded on first use from
// the module librpt_image_codecs.so (image_codecs_module.cc). Those two OpenCV modules bring about
// 220 shared libraries (FFmpeg, GStreamer, GDAL, ...): linked into rpt, loading them took about
// 0.2 s of every rpt process. Loaded only by `rpt render`, every other command starts without them.
#pragma once

#include <filesystem>
#include <opencv2/core.hpp>
#include <span>
#include <string>
#include <vector>

namespace rpt::engine {

// The module's functions. The module is built with rpt by the same compiler, so C++ types cross.
struct ImageCodecs {
  int version;  // kImageCodecsVersion of the module's build
  // The image at `path` as 8-bit BGR; empty when it cannot be read.
  cv::Mat (*read_color)(const std::string& path);
  // Writes `image` as a PNG file at `path` (which ends in .png); false when it cannot.
  bool (*write_png)(const std::string& path, const cv::Mat& image);
  // An MP4 writer (FFmpeg backend) for frames of width x height at `fps` with the codec `fourcc`
  // ("avc1", "mp4v"); null when that codec cannot write there.
  void* (*open_mp4)(const std::string& path, const char* fourcc, double fps, int width, int height);
  // Appends one frame (8-bit BGR, the writer's size).
  void (*write_frame)(void* writer, const cv::Mat& frame);
  // Finishes the video and frees the writer.
  void (*close_mp4)(void* writer);
};

// Raised whenever ImageCodecs changes: a module of another build is refused, not called.
inline constexpr int kImageCodecsVersion = 1;
// The module's one exported function: const ImageCodecs* rpt_image_codecs().
inline constexpr const char* kImageCodecsEntry = "rpt_image_codecs";
inline constexpr const char* kImageCodecsFile = "librpt_image_codecs.so";

// The module's functions, loaded on the first call (thread-safe), from the first of
// ImageCodecsPlaces() that loads. Throws InstallationError (core/errors.h) listing each place tried
// and why it failed.
const ImageCodecs& LoadImageCodecs();

// Where the module is looked for: beside the running executable (rpt and the module are built
// into one folder), then where this build put it (for the test programs).
std::vector<std::filesystem::path> ImageCodecsPlaces();

// The module at the first of `places` that loads (not cached: for tests). Throws as LoadImageCodecs.
const ImageCodecs& LoadImageCodecsFrom(std::span<const std::filesystem::path> places);

}  // namespace rpt::engine
