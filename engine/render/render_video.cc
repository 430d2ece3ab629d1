// SPDX-License-Identifier: MIT
#include "engine/render/render_video.h"

#include "core/errors.h"

namespace rpt::engine {

Mp4Writer::Mp4Writer(const std::filesystem::path& path, cv::Size size, double fps)
    : file_(path, io::NamedBy::kRpt, /*keep_extension=*/true) {
  for (const char* codec : {"avc1", "mp4v"}) {
    const int fourcc = cv::VideoWriter::fourcc(codec[0], codec[1], codec[2], codec[3]);
    if (writer_.open(file_.path().string(), cv::CAP_FFMPEG, fourcc, fps, size)) {
      codec_ = codec;
      return;
    }
  }
  throw InputError(path.string() + ": cannot write an MP4 video (neither H.264 'avc1' nor MPEG-4 'mp4v' is available " +
                   "to OpenCV's FFmpeg writer); write PNGs with --format png");
}

void Mp4Writer::Write(const cv::Mat& frame) {
  writer_.write(frame);
  ++frames_;
}

void Mp4Writer::Finish() {
  writer_.release();
  file_.Commit();
}

}  // namespace rpt::engine
