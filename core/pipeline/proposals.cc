// SPDX-License-Identifier: MIT
#include "core/pipeline/pipeline_types.h"

#include <algorithm>

namespace rpt {

void Proposals::Move(int from, int to) {
  if (from == to) return;
  const size_t n = static_cast<size_t>(num_joints);
  pairs[to] = pairs[from];
  std::copy_n(xyz.begin() + from * n, n, xyz.begin() + to * n);
  std::copy_n(gap.begin() + from * n, n, gap.begin() + to * n);
  std::copy_n(score.begin() + from * n, n, score.begin() + to * n);
  std::copy_n(geometric.begin() + from * n, n, geometric.begin() + to * n);
  pair_score[to] = pair_score[from];
  group[to] = group[from];
}

void Proposals::Truncate(int n) {
  const size_t joints = static_cast<size_t>(num_joints);
  pairs.resize(n);
  xyz.resize(n * joints);
  gap.resize(n * joints);
  score.resize(n * joints);
  geometric.resize(n * joints);
  pair_score.resize(n);
  group.resize(n);
}

}  // namespace rpt
