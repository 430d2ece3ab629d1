// SPDX-License-Identifier: MIT
#include "engine/render/render_video.h"

#include "core/errors.h"

namespace rpt::engine {

Mp4Writer::Mp4Writer(const std::filesystem::path& path, cv::Size size, double fps)
    : codecs_(LoadImageCodecs()), file_(path, io::NamedBy::kRpt, /*keep_extension=*/true) {
  for (const char* codec : {"avc1", "mp4v"}) {
    writer_ = codecs_.open_mp4(file_.path().string(), codec, fps, size.width, size.height);
    if (writer_ != nullptr) {
      codec_ = codec;
      return;
    }
  }
  throw InputError(path.string() + ": cannot write an MP4 video (neither H.264 'avc1' nor MPEG-4 'mp4v' is available " +
                   "to OpenCV's FFmpeg writer); write PNGs with --format png");
}

Mp4Writer::~Mp4Writer() {
  if (writer_ != nullptr) codecs_.close_mp4(writer_);  // unfinished: the staged file is removed
}

void Mp4Writer::Write(const cv::Mat& frame) {
  codecs_.write_frame(writer_, frame);
  ++frames_;
}

void Mp4Writer::Finish() {
  codecs_.close_mp4(writer_);
  writer_ = nullptr;
  file_.Commit();
}

}  // namespace rpt::engine
