// SPDX-License-Identifier: MIT
#include "engine/camera_agreement.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/printable_text.h"
#include "core/text.h"

namespace rpt::engine {

CameraAgreementCheck::CameraAgreementCheck(const SequenceHeader& header, const JointNames& output_joints,
                                           long num_frames)
    : header_(header), stride_(num_frames < 0 ? 10 : std::max(1L, num_frames / kAgreementFrames)) {
  for (const std::string& name : output_joints) detection_joint_.push_back(FindJoint(header.detection_joints, name));
  for (const Camera& camera : header.cameras) cameras_.push_back({camera.name, 0, 0});
  projected_.resize(output_joints.size());
  visible_.resize(output_joints.size());
}

void CameraAgreementCheck::Add(long index, const SequenceFrame& frame, const Poses3D& persons) {
  if (index % stride_ != 0 || frame.views.size() != header_.cameras.size()) return;
  for (size_t c = 0; c < header_.cameras.size(); ++c) {
    if (frame.views[c].unavailable) continue;
    ++cameras_[c].frames;
    cameras_[c].frames_with_detections += frame.views[c].num_persons() > 0 ? 1 : 0;
  }
  const int num_joints = persons.num_joints;
  for (int p = 0; p < persons.num_persons(); ++p) {
    const auto person = persons.Person(p);
    int triangulated = 0;
    for (int j = 0; j < num_joints; ++j) {
      triangulated += person(3, j) > 0 && persons.Provenance(p, j) == JointProvenance::kTriangulated ? 1 : 0;
    }
    if (triangulated < kMinAgreementJoints) continue;
    for (size_t c = 0; c < header_.cameras.size(); ++c) {
      if (frame.views[c].unavailable) continue;  // no data: it did not look
      if (frame.views[c].num_persons() > 0) ++cameras_[c].while_detecting;
      const Camera& camera = header_.cameras[c];
      double min_u = std::numeric_limits<double>::infinity(), min_v = min_u, max_u = -min_u, max_v = -min_u;
      double sum_u = 0, sum_v = 0;
      int seen = 0;
      for (int j = 0; j < num_joints; ++j) {
        visible_[j] = person(3, j) > 0 && detection_joint_[j] >= 0 &&
                      camera.Project(person.col(j).head<3>(), &projected_[j]) && projected_[j].allFinite();
        if (!visible_[j]) continue;
        const Eigen::Vector2d& uv = projected_[j];
        min_u = std::min(min_u, uv.x()), max_u = std::max(max_u, uv.x());
        min_v = std::min(min_v, uv.y()), max_v = std::max(max_v, uv.y());
        sum_u += uv.x(), sum_v += uv.y();
        ++seen;
      }
      if (seen < 3) continue;
      const double centre_u = sum_u / seen, centre_v = sum_v / seen;
      if (!(centre_u >= 0 && centre_u < camera.width && centre_v >= 0 && centre_v < camera.height)) continue;
      const double diagonal = std::max(1.0, std::hypot(max_u - min_u, max_v - min_v));
      const Poses2D& view = frame.views[c];
      if (view.num_persons() == 0) {
        ++cameras_[c].in_view_without_detections;
        continue;
      }
      ++cameras_[c].in_view;
      bool agrees = false;
      for (int d = 0; d < view.num_persons() && !agrees; ++d) {
        const auto detection = view.Person(d);
        double sum = 0;
        int shared = 0;
        for (int j = 0; j < num_joints; ++j) {
          if (!visible_[j]) continue;
          const int k = detection_joint_[j];
          if (!(detection(2, k) > 0)) continue;
          sum += std::hypot(projected_[j].x() - detection(0, k), projected_[j].y() - detection(1, k));
          ++shared;
        }
        agrees = shared >= 3 && sum / shared <= kAgreementDistance * diagonal;
      }
      cameras_[c].agreeing += agrees ? 1 : 0;
    }
  }
}

std::vector<std::string> CameraAgreementWarnings(const std::string& sequence, const std::vector<CameraAgreement>& cameras) {
  std::vector<std::string> lines;
  for (const CameraAgreement& camera : cameras) {
    if (camera.frames_with_detections == 0) {  // nothing to match: its detections are missing, not misplaced
      if (camera.in_view_without_detections < kMinAgreementPersons) continue;
      lines.push_back(PrintableText(sequence + ", camera " + QuoteName(camera.camera) + ": no detections in any of the " +
                                    std::to_string(camera.frames) + " frames compared, while " +
                                    std::to_string(camera.in_view_without_detections) +
                                    " 3D persons were in its view: is its detector output missing, or its name "
                                    "another camera's?"));
      continue;
    }
    if (camera.frames_with_detections >= kMinAgreementPersons && camera.while_detecting >= kMinAgreementPersons &&
        static_cast<double>(camera.in_view) <= kMinInViewShare * static_cast<double>(camera.while_detecting)) {
      lines.push_back(PrintableText(
          sequence + ", camera " + QuoteName(camera.camera) + ": it detected persons in " +
          std::to_string(camera.frames_with_detections) + " of the " + std::to_string(camera.frames) +
          " frames compared, but " + (camera.in_view == 0 ? "none" : "only " + std::to_string(camera.in_view)) +
          " of the " + std::to_string(camera.while_detecting) +
          " 3D persons of those frames fall in its image: is its calibration right? (its position: the camera "
          "centre given where the world-to-camera t belongs, or the other way round; R transposed; the units of t)"));
      continue;
    }
    if (camera.in_view < kMinAgreementPersons) continue;
    const double share = static_cast<double>(camera.agreeing) / static_cast<double>(camera.in_view);
    if (share > kMinAgreementShare) continue;  // half or fewer: a COLMAP quaternion read in the wrong order gave 50 %
    lines.push_back(PrintableText(sequence + ", camera " + QuoteName(camera.camera) + ": only " +
                                  PercentText(share) + " of the " + std::to_string(camera.in_view) +
                                  " 3D persons in its view (in frames where it detected someone) match its detections "
                                  "(expected most): is its calibration right, its pixel scale (detections from a "
                                  "resized image?), or is its name another camera's?"));
  }
  return lines;
}

}  // namespace rpt::engine
