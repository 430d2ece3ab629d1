// SPDX-License-Identifier: MIT
#include "core/pipeline/verify.h"

#include <algorithm>

namespace rpt {

namespace {

// Mean distance between persons a and b over the core joints valid (score > 0) in both; a
// negative value with fewer than 2 such joints.
double MeanCoreDistance(const Poses3D& persons, std::span<const int> core_joints, int a, int b) {
  const auto pa = persons.Person(a), pb = persons.Person(b);
  double sum = 0;
  int common = 0;
  for (const int j : core_joints) {
    if (pa(3, j) <= 0 || pb(3, j) <= 0) continue;
    sum += (pa.col(j).head<3>() - pb.col(j).head<3>()).norm();
    ++common;
  }
  return common >= 2 ? sum / common : -1.0;
}

// Fills scratch->views_of (per person and view: made from one of that view's poses) and
// scratch->num_views; all zero without groups (person i merged from group i, whose pairs are the
// proposals groups.begin[i] .. begin[i + 1] of triangulate_full).
void MarkOwnViews(const steps::VerifyInput& in, bool by_group, int num_persons, VerifyScratch* scratch) {
  const int num_views = static_cast<int>(in.geometry.size());
  VerifyScratch& s = *scratch;
  s.views_of.assign(static_cast<size_t>(num_persons) * num_views, 0);
  s.num_views.assign(num_persons, 0);
  for (int p = 0; p < num_persons && by_group; ++p) {
    char* const views_of = s.views_of.data() + static_cast<size_t>(p) * num_views;
    for (int m = in.groups.begin[p]; m < in.groups.begin[p + 1]; ++m) {
      views_of[in.views.view_of[in.proposals.pairs[m].a]] = 1;
      views_of[in.views.view_of[in.proposals.pairs[m].b]] = 1;
    }
    for (int v = 0; v < num_views; ++v) s.num_views[p] += views_of[v];
  }
}

// Marks scratch->duplicate[p] for every person p within duplicate_distance_m of a stronger kept
// person made from none of p's views (scratch->views_of). Stronger: made from more views, then
// from more pairs, then the earlier person.
void MarkDuplicates(const VerifyOptions& options, const steps::VerifyInput& in, VerifyScratch* scratch,
                    const Poses3D& persons) {
  const int num_persons = persons.num_persons();
  const int num_views = static_cast<int>(in.geometry.size());
  VerifyScratch& s = *scratch;
  // Two persons share no view only if their view counts add up to at most the views: else (most
  // frames, where every person is seen by most cameras) there is nothing to compare.
  int fewest = num_views + 1, second_fewest = num_views + 1;
  for (int p = 0; p < num_persons; ++p) {
    if (s.num_views[p] < fewest) {
      second_fewest = fewest;
      fewest = s.num_views[p];
    } else if (s.num_views[p] < second_fewest) {
      second_fewest = s.num_views[p];
    }
  }
  if (fewest + second_fewest > num_views) return;
  s.by_strength.resize(num_persons);
  for (int p = 0; p < num_persons; ++p) s.by_strength[p] = p;
  const auto pairs = [&](int p) { return in.groups.begin[p + 1] - in.groups.begin[p]; };
  std::sort(s.by_strength.begin(), s.by_strength.end(), [&](int a, int b) {
    if (s.num_views[a] != s.num_views[b]) return s.num_views[a] > s.num_views[b];
    if (pairs(a) != pairs(b)) return pairs(a) > pairs(b);
    return a < b;
  });
  for (int i = 1; i < num_persons; ++i) {
    const int p = s.by_strength[i];
    const char* const views_p = s.views_of.data() + static_cast<size_t>(p) * num_views;
    for (int i_stronger = 0; i_stronger < i; ++i_stronger) {
      const int q = s.by_strength[i_stronger];
      if (s.duplicate[q]) continue;
      const char* const views_q = s.views_of.data() + static_cast<size_t>(q) * num_views;
      bool shared_view = false;
      for (int v = 0; v < num_views && !shared_view; ++v) shared_view = views_p[v] && views_q[v];
      if (shared_view) continue;
      const double distance = MeanCoreDistance(persons, in.core_joints, p, q);
      if (distance >= 0 && distance < options.duplicate_distance_m) {
        s.duplicate[p] = 1;
        break;
      }
    }
  }
}

// Marks scratch->duplicate[p] for every person p that is a part of a person with more joints
// (score > 0) not marked before it (in person order): at least 2 of p's joints each within
// part_distance_m of that person's same joint.
void MarkParts(const VerifyOptions& options, VerifyScratch* scratch, const Poses3D& persons) {
  const int num_persons = persons.num_persons();
  const int n = persons.num_joints;
  VerifyScratch& s = *scratch;
  s.num_joints.assign(num_persons, 0);
  for (int p = 0; p < num_persons; ++p) {
    const auto person = persons.Person(p);
    for (int j = 0; j < n; ++j) s.num_joints[p] += person(3, j) > 0 ? 1 : 0;
  }
  const double max_sq = options.part_distance_m * options.part_distance_m;
  for (int p = 0; p < num_persons; ++p) {
    if (s.duplicate[p]) continue;
    const auto part = persons.Person(p);
    for (int q = 0; q < num_persons && !s.duplicate[p]; ++q) {
      if (q == p || s.duplicate[q] || s.num_joints[q] <= s.num_joints[p]) continue;
      const auto whole = persons.Person(q);
      int same = 0;
      for (int j = 0; j < n && same < 2; ++j) {
        if (part(3, j) <= 0 || whole(3, j) <= 0) continue;
        same += (part.col(j).head<3>() - whole.col(j).head<3>()).squaredNorm() < max_sq ? 1 : 0;
      }
      if (same >= 2) s.duplicate[p] = 1;
    }
  }
}

}  // namespace

int steps::Verify(const VerifyOptions& options, const VerifyInput& in, VerifyScratch* scratch, Poses3D* persons,
                  FrameStats* stats) {
  const PreparedViews& views = in.views;
  const std::span<const ViewGeometry> geometry = in.geometry;
  if (!options.enabled || persons->num_persons() == 0) return persons->num_persons();
  const int num_views = static_cast<int>(geometry.size());
  const bool by_group = in.groups.size() == persons->num_persons();
  MarkOwnViews(in, by_group, persons->num_persons(), scratch);
  scratch->duplicate.assign(persons->num_persons(), 0);
  if (by_group && options.duplicate_distance_m > 0 && persons->num_persons() > 1) {
    MarkDuplicates(options, in, scratch, *persons);
  }
  if (options.part_distance_m > 0 && persons->num_persons() > 1) MarkParts(options, scratch, *persons);
  bool have_boxes = false;  // pose boxes are computed when first needed
  int kept = 0;
  for (int p = 0; p < persons->num_persons(); ++p) {
    if (scratch->duplicate[p]) {
      ++stats->duplicate_persons;
      continue;
    }
    const auto person = persons->Person(p);
    const char* const own_view = scratch->views_of.data() + static_cast<size_t>(p) * num_views;
    int support = scratch->num_views[p], empty = 0;
    // Empty views can only come from the other views: skip persons that cannot be dropped.
    const int others = num_views - support;
    const bool can_drop = others >= options.min_empty_views && others > support;
    for (int v = 0; can_drop && v < num_views; ++v) {
      if (own_view[v]) continue;
      if (!have_boxes) {
        PoseBoxes(views, &scratch->verdict.boxes);
        have_boxes = true;
      }
      const ViewVerdict verdict = JudgeView(views, geometry[v], v, in.core_joints, person, in.kernel.scale_m,
                                            options.min_inside_fraction, &scratch->verdict, nullptr);
      support += verdict == ViewVerdict::kSupport;
      empty += verdict == ViewVerdict::kEmpty;
    }
    if (empty >= options.min_empty_views && empty > support) {
      ++stats->unsupported_persons;
      continue;
    }
    if (kept != p) persons->MovePerson(p, kept);
    ++kept;
  }
  persons->Truncate(kept);
  return kept;
}

}  // namespace rpt
