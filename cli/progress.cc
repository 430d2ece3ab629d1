// SPDX-License-Identifier: MIT
#include "cli/progress.h"

#include <unistd.h>

#include <cstdio>

#include "core/printable_text.h"

namespace rpt::cli {
namespace {
constexpr double kQuietSeconds = 2.0;
constexpr double kUnknownTotalSeconds = 10.0;
}

Progress::Progress(std::string label, long total, bool enabled)
    : label_(PrintableText(label, LineBreaks::kEscape)),  // a sequence's name, from the input
      total_(total),
      enabled_(enabled && total != 0),
      tty_(isatty(fileno(stderr)) != 0),
      start_(std::chrono::steady_clock::now()),
      last_draw_(start_) {}

Progress::~Progress() {
  if (shown_ && tty_) std::fprintf(stderr, "\n");
}

void Progress::Update(long done) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  if (total_ < 0) {  // unknown length: a line every kUnknownTotalSeconds
    if (elapsed < kQuietSeconds || std::chrono::duration<double>(now - last_draw_).count() < kUnknownTotalSeconds) return;
    last_draw_ = now;
    std::fprintf(stderr, "%s: %ld (%.0f s)\n", label_.c_str(), done, elapsed);
    std::fflush(stderr);
    return;
  }
  if (elapsed < kQuietSeconds && done < total_) return;
  if (!shown_ && done >= total_) return;  // finished quickly: stay silent
  const int decile = static_cast<int>(10 * done / total_);
  if (tty_) {
    if (std::chrono::duration<double>(now - last_draw_).count() < 0.2 && done < total_) return;
    last_draw_ = now;
    const int width = 30, filled = static_cast<int>(width * done / total_);
    std::fprintf(stderr, "\r%s [%.*s%*s] %ld/%ld (%.0f s)", label_.c_str(), filled,
                 "==============================", width - filled, "", done, total_, elapsed);
  } else if (decile != last_decile_) {
    std::fprintf(stderr, "%s: %ld/%ld (%.0f s)\n", label_.c_str(), done, total_, elapsed);
  }
  last_decile_ = decile;
  shown_ = true;
  std::fflush(stderr);
}

std::unique_ptr<Progress> ProgressOf(engine::Input& input, bool enabled) {
  long total = 0;
  for (int i = 0; i < input.size(); ++i) {
    const long n = input.source(i).num_frames();
    total = n < 0 || total < 0 ? -1 : total + n;
  }
  return std::make_unique<Progress>(input.size() == 1 ? input.header(0).name : "triangulating",
                                    input.size() == 0 ? 0 : total, enabled);
}

std::function<void(long)> ReportTo(Progress* progress) {
  return [progress](long done) { progress->Update(done); };
}

}  // namespace rpt::cli
