// SPDX-License-Identifier: MIT
#include "engine/render/render_overlay.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <opencv2/imgproc.hpp>
#include <utility>

#include "engine/track_palette.h"

namespace rpt::engine {
namespace {

const cv::Scalar kGrey(150, 150, 150);
const cv::Scalar kBlack(0, 0, 0);
const cv::Scalar kWhite(255, 255, 255);
constexpr int kShift = 4;  // sub-pixel bits of the drawing coordinates
constexpr double kSubpixel = 1 << kShift;


// Line widths and sizes grow with the image so that an HD frame reads like a VGA one.
struct Style {
  explicit Style(const cv::Mat& canvas) : scale(std::max(1.0, std::min(canvas.cols, canvas.rows) / 480.0)) {}
  int Px(double size) const { return std::max(1, static_cast<int>(std::lround(size * scale))); }
  double scale;
};

// Per joint of `names`, the size of its dot, marker and limbs relative to a body joint's: face and
// hand points (COCO-WholeBody's face_*, hand_*) a third, so that a face or hand shows its points
// instead of one solid disc.
std::vector<double> JointSizes(const JointNames& names) {
  std::vector<double> sizes(names.size(), 1.0);
  for (size_t j = 0; j < names.size(); ++j) {
    if (names[j].rfind("face_", 0) == 0 || names[j].rfind("hand_", 0) == 0) sizes[j] = 1.0 / 3.0;
  }
  return sizes;
}

// The limbs (pairs of joint indices) of core/joints.h that exist in `names`.
std::vector<std::pair<int, int>> LimbIndices(const JointNames& names) {
  std::vector<std::pair<int, int>> out;
  for (const LimbSpec& limb : LimbsFor(names)) {
    const int a = FindJoint(names, limb.a), b = FindJoint(names, limb.b);
    if (a >= 0 && b >= 0) out.emplace_back(a, b);
  }
  return out;
}

// Pixels far outside the image are not drawn (OpenCV's fixed-point coordinates would overflow).
bool Drawable(const Eigen::Vector2d& uv, const cv::Mat& canvas) {
  const double margin = 4.0 * std::max(canvas.cols, canvas.rows);
  return uv.allFinite() && uv.x() > -margin && uv.y() > -margin && uv.x() < canvas.cols + margin &&
         uv.y() < canvas.rows + margin;
}

cv::Point Fixed(const Eigen::Vector2d& uv) {
  return cv::Point(static_cast<int>(std::lround(uv.x() * kSubpixel)),
                   static_cast<int>(std::lround(uv.y() * kSubpixel)));
}

bool Projected(JointReprojection status) {
  return status == JointReprojection::kMeasured || status == JointReprojection::kNotDetected;
}

void DrawLine(cv::Mat* canvas, const Eigen::Vector2d& a, const Eigen::Vector2d& b, const cv::Scalar& colour,
              int thickness) {
  if (Drawable(a, *canvas) && Drawable(b, *canvas)) {
    cv::line(*canvas, Fixed(a), Fixed(b), colour, thickness, cv::LINE_AA, kShift);
  }
}

void DrawDetection(const Poses2D& view, int d, const JointNames& joints, const std::vector<std::pair<int, int>>& limbs,
                   const cv::Scalar& colour, const Style& style, cv::Mat* canvas) {
  const auto person = view.Person(d);
  const std::vector<double> sizes = JointSizes(joints);
  for (const auto& [a, b] : limbs) {
    if (person(2, a) > 0 && person(2, b) > 0) {
      DrawLine(canvas, person.col(a).head<2>(), person.col(b).head<2>(), colour, style.Px(1));
    }
  }
  for (int j = 0; j < static_cast<int>(joints.size()) && j < view.num_joints; ++j) {
    const Eigen::Vector2d uv = person.col(j).head<2>();
    if (!(person(2, j) > 0) || !Drawable(uv, *canvas)) continue;
    cv::drawMarker(*canvas, cv::Point(static_cast<int>(std::lround(uv.x())), static_cast<int>(std::lround(uv.y()))),
                   colour, cv::MARKER_TILTED_CROSS, style.Px(7 * sizes[j]), style.Px(1), cv::LINE_AA);
  }
}

// The reprojected person's limbs and joints; GT (`gt`) thin and black with squares.
void DrawReprojected(const ReprojectedPerson& person, const std::vector<std::pair<int, int>>& limbs,
                     const std::vector<double>& sizes, const cv::Scalar& colour, bool gt, const Style& style,
                     cv::Mat* canvas) {
  const auto size_of = [&](size_t j) { return j < sizes.size() ? sizes[j] : 1.0; };
  for (const auto& [a, b] : limbs) {
    if (Projected(person.status[a]) && Projected(person.status[b])) {
      const double size = std::min(size_of(a), size_of(b));
      DrawLine(canvas, person.uv_px.col(a), person.uv_px.col(b), colour, style.Px(gt ? 1 : 2.5 * size));
    }
  }
  for (size_t j = 0; j < person.status.size(); ++j) {
    const Eigen::Vector2d uv = person.uv_px.col(j);
    if (!Projected(person.status[j]) || !Drawable(uv, *canvas)) continue;
    if (gt) {
      const int half = style.Px(2.5 * size_of(j));
      const cv::Point c(static_cast<int>(std::lround(uv.x())), static_cast<int>(std::lround(uv.y())));
      cv::rectangle(*canvas, c - cv::Point(half, half), c + cv::Point(half, half), colour, cv::FILLED);
    } else {
      cv::circle(*canvas, Fixed(uv), static_cast<int>(std::lround(style.Px(4 * size_of(j)) * kSubpixel)), colour,
                 cv::FILLED, cv::LINE_AA, kShift);
    }
  }
}

// Per measured joint, a thin line from the detection to the projection.
void DrawErrors(const ReprojectedPerson& person, const Poses2D& view, const JointNames& prediction_joints,
                const JointNames& detection_joints, const cv::Scalar& colour, const Style& style, cv::Mat* canvas) {
  if (person.detection_idx < 0) return;
  const auto detection = view.Person(person.detection_idx);
  for (size_t j = 0; j < person.status.size() && j < prediction_joints.size(); ++j) {
    if (person.status[j] != JointReprojection::kMeasured) continue;
    const int d = FindJoint(detection_joints, prediction_joints[j]);
    if (d >= 0) DrawLine(canvas, detection.col(d).head<2>(), person.uv_px.col(j), colour, style.Px(1));
  }
}

// `text` at `origin` (its baseline's left end), moved inside the image where it would stick out, and
// up (or, at the top, down) past the labels already in `placed` it would overlap; its box is added.
void PutText(cv::Mat* canvas, const std::string& text, cv::Point origin, const cv::Scalar& colour, const Style& style,
             std::vector<cv::Rect>* placed) {
  const double font_scale = 0.45 * style.scale;
  int baseline = 0;
  const cv::Size size = cv::getTextSize(text, cv::FONT_HERSHEY_SIMPLEX, font_scale, style.Px(3), &baseline);
  const auto inside = [&](cv::Point p) {
    return cv::Point(std::clamp(p.x, 0, std::max(0, canvas->cols - size.width)),
                     std::clamp(p.y, size.height, std::max(size.height, canvas->rows - baseline)));
  };
  const auto box = [&](cv::Point p) { return cv::Rect(p.x, p.y - size.height, size.width, size.height + baseline); };
  const auto overlaps = [&](cv::Point p) {
    return std::any_of(placed->begin(), placed->end(), [&](const cv::Rect& r) { return (r & box(p)).area() > 0; });
  };
  origin = inside(origin);
  const int step = size.height + baseline;
  int direction = -1;  // up, until the image's top stops it
  for (int tries = 0; tries < 8 && overlaps(origin); ++tries) {  // a crowd: at most 8 lines away
    cv::Point next = inside({origin.x, origin.y + direction * step});
    if (next.y == origin.y) {
      direction = 1;
      next = inside({origin.x, origin.y + step});
    }
    origin = next;
  }
  placed->push_back(box(origin));
  cv::putText(*canvas, text, origin, cv::FONT_HERSHEY_SIMPLEX, font_scale, kWhite, style.Px(3), cv::LINE_AA);
  cv::putText(*canvas, text, origin, cv::FONT_HERSHEY_SIMPLEX, font_scale, colour, style.Px(1), cv::LINE_AA);
}

// "track 3: 4.2 px" above the person's highest projected joint.
void DrawLabel(const ReprojectedPerson& person, const cv::Scalar& colour, const Style& style, cv::Mat* canvas,
               std::vector<cv::Rect>* placed) {
  int top = -1;
  for (size_t j = 0; j < person.status.size(); ++j) {
    if (!Projected(person.status[j]) || !Drawable(person.uv_px.col(j), *canvas)) continue;
    if (top < 0 || person.uv_px(1, j) < person.uv_px(1, top)) top = static_cast<int>(j);
  }
  if (top < 0) return;
  char text[96];
  const std::string who =
      person.track_id >= 0 ? "track " + std::to_string(person.track_id) : "person " + std::to_string(person.person_idx);
  if (person.num_measured > 0) {
    std::snprintf(text, sizeof(text), "%s: %.1f px", who.c_str(), person.mean_error_px);
  } else {
    std::snprintf(text, sizeof(text), "%s: no detection", who.c_str());
  }
  const cv::Point origin(static_cast<int>(person.uv_px(0, top)) - style.Px(20),
                         static_cast<int>(person.uv_px(1, top)) - style.Px(10));
  PutText(canvas, text, origin, colour, style, placed);
}

// `text` as is when it is at most `width` pixels wide (as `width_of` measures), else cut in the
// middle with "..." until it fits (the start and the end of a long name tell cameras apart).
template <class WidthOf>
std::string FitText(const std::string& text, int width, const WidthOf& width_of) {
  if (width_of(text) <= width) return text;
  std::string head = text.substr(0, text.size() / 2), tail = text.substr(text.size() / 2);
  while (!head.empty() || !tail.empty()) {
    if (head.size() >= tail.size()) {
      head.pop_back();
      while (!head.empty() && (static_cast<unsigned char>(head.back()) & 0xC0) == 0x80) head.pop_back();  // whole UTF-8
    } else {
      tail.erase(0, 1);
      while (!tail.empty() && (static_cast<unsigned char>(tail.front()) & 0xC0) == 0x80) tail.erase(0, 1);
    }
    const std::string cut = head + "..." + tail;
    if (width_of(cut) <= width) return cut;
  }
  return "...";
}

// The image corner for a legend of `size`: of the four, the one whose box holds the fewest of the
// drawn points (reprojected predictions and GT, detections; a person's label counts as 5), so that it
// covers nobody where it can; top left of equals.
cv::Point LegendCorner(const OverlayInput& input, const std::vector<cv::Rect>& labels, const cv::Size& size,
                       const cv::Size& image) {
  const cv::Point corners[4] = {{0, 0},
                                {image.width - size.width, 0},
                                {0, image.height - size.height},
                                {image.width - size.width, image.height - size.height}};
  long covered[4] = {0, 0, 0, 0};
  const auto count = [&](double u, double v) {
    if (!std::isfinite(u) || !std::isfinite(v)) return;
    for (int c = 0; c < 4; ++c) {
      covered[c] += u >= corners[c].x && u < corners[c].x + size.width && v >= corners[c].y &&
                    v < corners[c].y + size.height;
    }
  };
  const auto count_person = [&](const ReprojectedPerson& p) {
    for (size_t j = 0; j < p.status.size(); ++j) {
      if (p.status[j] == JointReprojection::kMeasured || p.status[j] == JointReprojection::kNotDetected) {
        count(p.uv_px(0, j), p.uv_px(1, j));
      }
    }
  };
  for (const ReprojectedPerson& p : input.reprojection->predictions) count_person(p);
  for (const ReprojectedPerson& p : input.reprojection->gt) count_person(p);
  if (input.detections != nullptr) {
    for (int d = 0; d < input.detections->num_persons(); ++d) {
      const auto person = input.detections->Person(d);
      for (int j = 0; j < input.detections->num_joints; ++j) {
        if (person(2, j) > 0) count(person(0, j), person(1, j));
      }
    }
  }
  for (const cv::Rect& label : labels) {
    for (int c = 0; c < 4; ++c) covered[c] += (label & cv::Rect(corners[c], size)).area() > 0 ? 5 : 0;
  }
  int best = 0;
  for (int c = 1; c < 4; ++c) best = covered[c] < covered[best] ? c : best;
  return corners[best];
}

void DrawLegend(const OverlayInput& input, const std::vector<cv::Rect>& labels, const Style& style, cv::Mat* canvas) {
  const ViewError view_error = MeanPredictionError(*input.reprojection);
  char error[96];
  if (view_error.joints > 0) {
    std::snprintf(error, sizeof(error), "reprojection error %.1f px (mean, %ld joints)", view_error.mean_px,
                  view_error.joints);
  } else {
    std::snprintf(error, sizeof(error), "no joint matched a detection");
  }
  struct Line {
    std::string text;
    int glyph;  // 0 none, 1 reprojection, 2 detection, 3 GT
  };
  const int line_height = style.Px(18), glyph_width = style.Px(30), pad = style.Px(6);
  const auto text_width_of = [&](const std::string& text) {
    int baseline = 0;
    return cv::getTextSize(text, cv::FONT_HERSHEY_SIMPLEX, 0.45 * style.scale, style.Px(1), &baseline).width;
  };
  // The title on one line where it fits the image, else a line per part, each cut to fit.
  std::vector<Line> lines;
  std::string joined;
  for (const std::string& part : input.title) joined += (joined.empty() ? "" : "   ") + part;
  const int max_width = std::max(1, canvas->cols - 2 * pad);
  if (text_width_of(joined) <= max_width) {
    lines.push_back({joined, 0});
  } else {
    for (const std::string& part : input.title) lines.push_back({FitText(part, max_width, text_width_of), 0});
  }
  lines.insert(lines.end(), {{"reprojected 3D (colour = track)", 1}, {"2D detection (grey: unmatched)", 2}});
  if (input.gt_joints != nullptr) lines.push_back({"reprojected ground truth", 3});
  lines.push_back({error, 0});
  int text_width = 0;
  for (const Line& line : lines) {
    text_width = std::max(text_width, text_width_of(line.text) + (line.glyph ? glyph_width + pad : 0));
  }
  const cv::Size size(std::min(text_width + 2 * pad, canvas->cols),
                      std::min(static_cast<int>(lines.size()) * line_height + 2 * pad, canvas->rows));
  const cv::Point corner = LegendCorner(input, labels, size, canvas->size());
  cv::Mat region = (*canvas)(cv::Rect(corner, size));
  cv::addWeighted(region, 0.3, cv::Mat(region.size(), region.type(), kWhite), 0.7, 0, region);
  const cv::Scalar sample = PersonColour(0, 0);
  for (size_t i = 0; i < lines.size(); ++i) {
    const int y = corner.y + pad + static_cast<int>(i + 1) * line_height - style.Px(5);
    int x = corner.x + pad;
    const Eigen::Vector2d a(x, y - style.Px(4)), b(x + glyph_width - pad, y - style.Px(4));
    if (lines[i].glyph == 1) {
      DrawLine(canvas, a, b, sample, style.Px(2.5));
      cv::circle(*canvas, cv::Point(static_cast<int>(b.x()), static_cast<int>(b.y())), style.Px(4), sample, cv::FILLED,
                 cv::LINE_AA);
    } else if (lines[i].glyph == 2) {
      DrawLine(canvas, a, b, kGrey, style.Px(1));
      cv::drawMarker(*canvas, cv::Point(static_cast<int>(b.x()), static_cast<int>(b.y())), kGrey,
                     cv::MARKER_TILTED_CROSS, style.Px(7), style.Px(1), cv::LINE_AA);
    } else if (lines[i].glyph == 3) {
      DrawLine(canvas, a, b, kBlack, style.Px(1));
    }
    if (lines[i].glyph) x += glyph_width + pad;
    cv::putText(*canvas, lines[i].text, cv::Point(x, y), cv::FONT_HERSHEY_SIMPLEX, 0.45 * style.scale, kBlack,
                style.Px(1), cv::LINE_AA);
  }
}

}  // namespace

cv::Scalar PersonColour(int track_id, int person_idx) {
  const Rgb colour = kTrackPalette[TrackPaletteIndex(track_id >= 0 ? track_id : person_idx)];
  return cv::Scalar(colour.b, colour.g, colour.r);  // OpenCV's BGR
}

cv::Mat BlankCanvas(const Camera& camera) { return cv::Mat(camera.height, camera.width, CV_8UC3, kWhite); }

void DrawOverlay(const OverlayInput& input, cv::Mat* canvas) {
  const Style style(*canvas);
  const ViewReprojection& reprojection = *input.reprojection;
  if (input.gt_joints != nullptr) {
    const auto limbs = LimbIndices(*input.gt_joints);
    const std::vector<double> sizes = JointSizes(*input.gt_joints);
    for (const ReprojectedPerson& p : reprojection.gt) DrawReprojected(p, limbs, sizes, kBlack, /*gt=*/true, style, canvas);
  }
  if (input.detections != nullptr && input.detection_joints != nullptr) {
    const auto limbs = LimbIndices(*input.detection_joints);
    for (int d = 0; d < input.detections->num_persons(); ++d) {
      const int p = d < static_cast<int>(reprojection.prediction_of_detection.size())
                        ? reprojection.prediction_of_detection[d]
                        : -1;
      const cv::Scalar colour = p >= 0 ? PersonColour(reprojection.predictions[p].track_id, p) : kGrey;
      DrawDetection(*input.detections, d, *input.detection_joints, limbs, colour, style, canvas);
    }
    for (const ReprojectedPerson& p : reprojection.predictions) {
      DrawErrors(p, *input.detections, *input.prediction_joints, *input.detection_joints,
                 PersonColour(p.track_id, p.person_idx), style, canvas);
    }
  }
  const auto limbs = LimbIndices(*input.prediction_joints);
  const std::vector<double> sizes = JointSizes(*input.prediction_joints);
  for (const ReprojectedPerson& p : reprojection.predictions) {
    DrawReprojected(p, limbs, sizes, PersonColour(p.track_id, p.person_idx), /*gt=*/false, style, canvas);
  }
  std::vector<cv::Rect> labels;  // placed so far: a crowd's labels are moved apart
  for (const ReprojectedPerson& p : reprojection.predictions) {
    DrawLabel(p, PersonColour(p.track_id, p.person_idx), style, canvas, &labels);
  }
  DrawLegend(input, labels, style, canvas);
}

}  // namespace rpt::engine
