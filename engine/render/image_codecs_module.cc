// SPDX-License-Identifier: MIT
// librpt_image_codecs.so: OpenCV's image and video files behind the function table of
// image_codecs.h. The only file that links imgcodecs and videoio; rpt loads it with dlopen when
// `rpt render` runs (image_codecs.cc).
#include <opencv2/core/utils/logger.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/videoio.hpp>

#include "engine/render/image_codecs.h"

namespace {

cv::Mat ReadColor(const std::string& path) { return cv::imread(path, cv::IMREAD_COLOR); }

bool WritePng(const std::string& path, const cv::Mat& image) { return cv::imwrite(path, image); }

void* OpenMp4(const std::string& path, const char* fourcc, double fps, int width, int height) {
  auto writer = std::make_unique<cv::VideoWriter>();
  const int code = cv::VideoWriter::fourcc(fourcc[0], fourcc[1], fourcc[2], fourcc[3]);
  if (!writer->open(path, cv::CAP_FFMPEG, code, fps, cv::Size(width, height))) return nullptr;
  return writer.release();
}

void WriteFrame(void* writer, const cv::Mat& frame) { static_cast<cv::VideoWriter*>(writer)->write(frame); }

void CloseMp4(void* writer) {
  auto* w = static_cast<cv::VideoWriter*>(writer);
  w->release();
  delete w;
}

constexpr rpt::engine::ImageCodecs kCodecs{rpt::engine::kImageCodecsVersion, ReadColor, WritePng, OpenMp4,
                                           WriteFrame, CloseMp4};

}  // namespace

extern "C" __attribute__((visibility("default"))) const rpt::engine::ImageCodecs* rpt_image_codecs() {
  // A file that cannot be read is rpt's warning (one line per camera), not OpenCV's log line per
  // image on stderr.
  cv::utils::logging::setLogLevel(cv::utils::logging::LOG_LEVEL_ERROR);
  return &kCodecs;
}
