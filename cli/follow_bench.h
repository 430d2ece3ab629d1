// SPDX-License-Identifier: MIT
// `rpt bench --follow`: the latency of the live input (`rpt triangulate --follow`) on the benchmark
// scenes (bench/bench_scenes.h). The scene's detections are written as detection lines and fed
// through a pipe one at a time to the live input's run loop (engine/live_input.h, the same code as
// the command, in a second thread, its frame lines written to a second pipe); each line goes in
// only once the output line of the one before has been read, so every latency is that of an idle
// pipeline. Reported per frame, medians after a warm-up pass: the triangulation time, the latency
// measured in the process (line read -> line written) and as the producer sees it (line written ->
// output line read), and what --follow adds to the triangulation (the target: 100 us on
// shelf-like). Each scene twice: numbers at full precision (as Python producers write floats) and
// with 3 decimals (as OpenPose writes them), since reading the numbers is most of the added time;
// and each with the live input's default --spin-us and with 0 (the feeding thread polls for the
// output line as long as the live input polls for its input: a producer that waits the same way).
#pragma once

#include <string>
#include <vector>

#include "bench/bench_scenes.h"
#include "engine/config.h"

namespace rpt::cli {

// `repeat` timed passes over each scene's frames after one warm-up pass; prints a table, or JSON.
// `rate` > 0: the lines are also paced at that many per second (a camera's; the pipeline idles
// between frames), each still only after the output line of the one before.
void RunFollowBench(const std::vector<bench::BenchScene>& scenes, int repeat, double rate, const std::string& detector,
                    const engine::Config& config, bool json);

}  // namespace rpt::cli
