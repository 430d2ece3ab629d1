// SPDX-License-Identifier: MIT
#include "datasets/readers/generic_common.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <set>
#include <unordered_set>

#include <re2/re2.h>

#include "core/errors.h"
#include "core/printable_text.h"
#include "core/text.h"
#include "datasets/io/number_text.h"

namespace rpt {
namespace path_template {

// One piece of a template: literal text, or a capture group with optional padding and offset.
// (Outside the anonymous namespace: PathMapper::Impl, a member of a class with linkage, holds them.)
struct TemplatePart {
  std::string literal;
  int group = -1;  // >= 0: a capture group
  int width = -1;  // >= 0: numeric, zero-padded
  long long offset = 0;
};

}  // namespace path_template

namespace {

using path_template::TemplatePart;

const std::unordered_set<std::string>& KnownNames() {
  static const std::unordered_set<std::string> names = [] {
    std::unordered_set<std::string> out;
    for (const auto& n : CocoWholeBodyJoints()) out.insert(n);
    for (const auto& n : DerivedJointNames()) out.insert(n);
    for (const auto& n : ExtraJointNames()) out.insert(n);
    return out;
  }();
  return names;
}

// "left_shoulder" -> "shoulder_left", "LShoulder" is not guessed.
std::string Suggestion(std::string_view name) {
  std::string lower(name);
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return std::tolower(c); });
  if (lower != name && IsKnownJointName(lower)) return lower;
  // left_shoulder, LEFT_SHOULDER, l_shoulder -> shoulder_left; left_big_toe -> foot_big_toe_left
  // (COCO-WholeBody style).
  for (const auto& [prefix, side] : std::vector<std::pair<std::string, std::string>>{
           {"left_", "left"}, {"right_", "right"}, {"l_", "left"}, {"r_", "right"}}) {
    if (lower.rfind(prefix, 0) != 0) continue;
    const std::string candidate = lower.substr(prefix.size()) + "_" + side;
    if (IsKnownJointName(candidate)) return candidate;
    if (IsKnownJointName("foot_" + candidate)) return "foot_" + candidate;
  }
  // OpenPose and Human3.6M style: LShoulder -> shoulder_left, RBigToe -> foot_big_toe_right,
  // RFoot -> ankle_right (Human3.6M's foot is the ankle), MidHip / Hip / mid_hip -> hip_middle.
  const auto snake = [](std::string_view camel) {
    std::string out;
    for (const char c : camel) {
      if (std::isupper(static_cast<unsigned char>(c)) && !out.empty()) out += '_';
      out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
    return out;
  };
  if (lower == "midhip" || lower == "hip" || lower == "mid_hip" || lower == "middle_hip") return "hip_middle";
  // MMPose's COCO-WholeBody names: face-0 .. face-67 -> face_00 .. face_67; left_hand_root ->
  // hand_root_left; left_thumb1, left_forefinger2, left_middle_finger3, left_ring_finger4,
  // left_pinky_finger1 -> hand_thumb_1_left, hand_index_2_left, ... (a whole-body user's file).
  if (lower.rfind("face-", 0) == 0 || lower.rfind("face_", 0) == 0) {
    const std::string digits = lower.substr(5);
    if (!digits.empty() && digits.size() <= 2 && std::all_of(digits.begin(), digits.end(), [](unsigned char c) { return std::isdigit(c) != 0; })) {
      const std::string candidate = "face_" + std::string(digits.size() == 1 ? "0" : "") + digits;
      if (IsKnownJointName(candidate)) return candidate;
    }
  }
  for (const std::string side : {"left", "right"}) {
    if (lower.rfind(side + "_", 0) != 0) continue;
    const std::string rest = lower.substr(side.size() + 1);
    if (rest == "hand_root") return "hand_root_" + side;
    for (const auto& [mmpose, ours] : std::vector<std::pair<std::string, std::string>>{{"thumb", "thumb"},
                                                                                       {"forefinger", "index"},
                                                                                       {"middle_finger", "middle"},
                                                                                       {"ring_finger", "ring"},
                                                                                       {"pinky_finger", "pinky"}}) {
      if (rest.size() == mmpose.size() + 1 && rest.rfind(mmpose, 0) == 0 &&
          std::isdigit(static_cast<unsigned char>(rest.back()))) {
        const std::string candidate = "hand_" + ours + "_" + rest.back() + "_" + side;
        if (IsKnownJointName(candidate)) return candidate;
      }
    }
  }
  if (name.size() > 2 && (name[0] == 'L' || name[0] == 'R') && std::isupper(static_cast<unsigned char>(name[1]))) {
    std::string base = snake(name.substr(1));
    if (base == "foot") base = "ankle";
    const std::string candidate = base + (name[0] == 'L' ? "_left" : "_right");
    if (IsKnownJointName(candidate)) return candidate;
    if (IsKnownJointName("foot_" + candidate)) return "foot_" + candidate;
  }
  return "";
}

std::vector<TemplatePart> ParseTemplate(const std::string& text, const std::string& what) {
  std::vector<TemplatePart> parts;
  std::string literal;
  auto fail = [&](const std::string& why) {
    throw ConfigError(what + ": template " + QuoteName(text) + ": " + why);
  };
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '}') {
      if (i + 1 < text.size() && text[i + 1] == '}') {
        literal += '}';
        ++i;
        continue;
      }
      fail("unmatched '}' (write '}}' for a brace)");
    }
    if (c != '{') {
      literal += c;
      continue;
    }
    if (i + 1 < text.size() && text[i + 1] == '{') {
      literal += '{';
      ++i;
      continue;
    }
    const size_t close = text.find('}', i);
    if (close == std::string::npos) fail("unmatched '{'");
    const std::string field = text.substr(i + 1, close - i - 1);
    TemplatePart part;
    const char* p = field.data();
    const char* end = field.data() + field.size();
    auto [q, ec] = std::from_chars(p, end, part.group);
    if (ec != std::errc() || part.group < 0) fail("'{" + field + "}': expected {N}, {N:W} or {N:W+K}");
    if (q != end) {
      if (*q != ':') fail("'{" + field + "}': expected {N}, {N:W} or {N:W+K}");
      ++q;
      auto [r, ec2] = std::from_chars(q, end, part.width);
      if (ec2 != std::errc() || part.width < 0 || part.width > 30) fail("'{" + field + "}': width must be 0..30");
      if (r != end) {
        const bool plus = *r == '+';
        if (*r != '+' && *r != '-') fail("'{" + field + "}': expected +K or -K after the width");
        ++r;
        auto [s, ec3] = std::from_chars(r, end, part.offset);
        if (ec3 != std::errc() || s != end) fail("'{" + field + "}': bad offset");
        if (!plus) part.offset = -part.offset;
      }
    }
    if (!literal.empty()) parts.push_back(TemplatePart{literal});
    literal.clear();
    parts.push_back(part);
    i = close;
  }
  if (!literal.empty()) parts.push_back(TemplatePart{literal});
  return parts;
}

std::string Expand(const std::vector<TemplatePart>& parts, const std::vector<std::string>& match,
                   const std::string& source, const std::string& text) {
  std::string out;
  for (const TemplatePart& part : parts) {
    if (part.group < 0) {
      out += part.literal;
      continue;
    }
    const std::string& value = match[static_cast<size_t>(part.group)];
    if (part.width < 0) {
      out += value;
      continue;
    }
    long long number = 0;
    if (!io::ParseInteger(value, &number) || number < 0) {
      throw InputError(source + ": " + QuoteName(text) + ": capture group " + std::to_string(part.group) + " is " + QuoteName(value) +
                       ", not a non-negative integer");
    }
    number += part.offset;
    if (number < 0) {
      throw InputError(source + ": " + QuoteName(text) + ": frame number " + value + " " + std::to_string(part.offset) +
                       " is negative");
    }
    std::string digits = std::to_string(number);
    if (static_cast<int>(digits.size()) < part.width) digits.insert(0, part.width - digits.size(), '0');
    out += digits;
  }
  return out;
}

}  // namespace

const JointNames& ExtraJointNames() {
  static const JointNames names = {"head_top", "head_bottom", "neck",      "neck_nose",  "pelvis",     "body_center",
                                   "spine",    "thorax",      "hand_left", "hand_right"};
  return names;
}

bool IsKnownJointName(std::string_view name) {
  if (name.size() > 6 && name.substr(0, 6) == "extra_") return true;
  return KnownNames().count(std::string(name)) > 0;
}

void CheckJointNames(const JointNames& names, const std::string& where) {
  if (names.empty()) throw InputError(where + ": the joint list is empty");
  std::set<std::string> seen;
  // Every unknown name at once (a MediaPipe file of 33 names took one run per name), the first ones
  // with what they may mean.
  constexpr size_t kNamedUnknown = 12;
  std::vector<std::string> unknown;
  long count = 0;
  for (size_t j = 0; j < names.size(); ++j) {
    const std::string& name = names[j];
    if (name.empty()) throw InputError(where + ": joint " + std::to_string(j) + " has an empty name");
    if (!seen.insert(name).second) throw InputError(where + ": joint name " + QuoteName(name) + " appears twice");
    if (IsKnownJointName(name)) continue;
    if (++count > static_cast<long>(kNamedUnknown)) continue;
    const std::string suggestion = Suggestion(name);
    unknown.push_back(QuoteName(name) + (suggestion.empty() ? std::string() : " (did you mean " + QuoteName(suggestion) + "?)"));
  }
  if (count == 0) return;
  if (count > static_cast<long>(kNamedUnknown)) unknown.emplace_back("...");
  throw InputError(where + ": unknown joint name" + (count == 1 ? " " : "s (" + std::to_string(count) + "): ") +
                   Join(unknown, ", ") +
                   "; rpt's names: nose, eye_left, ..., ankle_right, foot_big_toe_left, ..., face_00 .. face_67, "
                   "hand_root_left, hand_thumb_1_left .. hand_pinky_4_right (listed in "
                   "docs/datasets/generic_formats.md); custom joints need the prefix 'extra_'");
}

// RE2 matches in time linear in the text whatever the pattern (a pattern such as (a+)+b made
// std::regex backtrack for hours on a name of 40 characters, and a run.json from someone else
// records the pattern rpt report re-runs); it has no backreferences and no lookaround.
RE2::Options PatternOptions() {
  RE2::Options options;
  options.set_log_errors(false);
  options.set_encoding(RE2::Options::EncodingLatin1);  // bytes: file names need not be UTF-8
  options.set_max_mem(8 << 20);
  return options;
}

struct PathMapper::Impl {
  explicit Impl(const std::string& pattern) : pattern(pattern, PatternOptions()) {}
  RE2 pattern;
  std::vector<TemplatePart> frame_id;
  std::vector<TemplatePart> camera;
};

PathMapper::PathMapper(const PathMapping& mapping, const std::string& what) {
  auto impl = std::make_unique<Impl>(mapping.pattern);
  if (!impl->pattern.ok()) {
    throw ConfigError(what + ": pattern " + QuoteName(mapping.pattern) + " is not a valid regular expression (" +
                      impl->pattern.error() + "; RE2 syntax: no backreferences or lookaround)");
  }
  impl->frame_id = ParseTemplate(mapping.frame_id, what + " frame id");
  impl->camera = ParseTemplate(mapping.camera, what + " camera");
  if (mapping.frame_id.empty()) throw ConfigError(what + ": the frame id template is empty");
  if (mapping.camera.empty()) throw ConfigError(what + ": the camera template is empty");
  const int groups = impl->pattern.NumberOfCapturingGroups();
  for (const auto* parts : {&impl->frame_id, &impl->camera}) {
    for (const TemplatePart& part : *parts) {
      if (part.group > groups) {
        throw ConfigError(what + ": a template uses {" + std::to_string(part.group) + "} but pattern '" +
                          mapping.pattern + "' has " + std::to_string(groups) + " capture group(s)");
      }
    }
  }
  impl_ = std::move(impl);
}

PathMapper::~PathMapper() = default;

bool PathMapper::Apply(const std::string& text, const std::string& source, std::string* frame_id,
                       std::string* camera) const {
  // No path is longer than PATH_MAX (4096 bytes): a longer name is not a file's, refused.
  constexpr size_t kMaxMatchedBytes = 4096;
  if (text.size() > kMaxMatchedBytes) {
    throw InputError(source + ": a name of " + std::to_string(text.size()) + " bytes, longer than any file path (" +
                     std::to_string(kMaxMatchedBytes) + "): not matched against the pattern");
  }
  const int groups = impl_->pattern.NumberOfCapturingGroups();
  std::vector<re2::StringPiece> pieces(static_cast<size_t>(groups) + 1);
  if (!impl_->pattern.Match(text, 0, text.size(), RE2::ANCHOR_BOTH, pieces.data(), static_cast<int>(pieces.size()))) {
    return false;
  }
  std::vector<std::string> match(pieces.size());
  for (size_t g = 0; g < pieces.size(); ++g) {
    if (!pieces[g].empty()) match[g].assign(pieces[g].data(), pieces[g].size());  // an unmatched group is ""
  }
  *frame_id = Expand(impl_->frame_id, match, source, text);
  *camera = Expand(impl_->camera, match, source, text);
  return true;
}

}  // namespace rpt
