// SPDX-License-Identifier: MIT
// One sequence's frames through four stages (engine/run.h): read (pull the next frame from its
// source, the in-order part of reading: parsing, the synthetic walk, repeated-id checks), complete
// (the per-frame part of reading: the simulated detector, validation; datasets/frame_source.h),
// process (the triangulator, whose state carries from frame to frame) and emit (metrics, input
// checks, the sinks that write the outputs). Read, process and emit handle the frames one at a
// time and in order, as one thread would; complete handles each frame once, in any order and on
// several frames at once. The stages run at the same time on different frames, on up to `threads`
// workers (the calling thread and threads - 1 others). Any worker runs any stage; read, process
// and emit have one worker at a time, so their state needs no lock of its own (the pipeline's
// mutex orders every hand-over), and complete may have several, so it must be thread-safe and
// touch only its frame's slot and constant state. A frame reaches process once it and every
// frame before it are complete. The stages' work is the same whatever the thread count: the
// results are those of one thread.
//
// The frames live in a ring of reused slots, owned by the caller and indexed by the frame's
// number modulo the ring's size: a slot is read into, completed, processed, emitted, then read
// into again, so memory is `capacity` frames however long the sequence. With one thread the
// stages take turns frame by frame (read 0, complete 0, process 0, emit 0, read 1, ...): a ring
// of one slot is enough. With several threads a free worker takes emit, process or read when one
// has work (they are the ones only one worker can run, and the ring drains through them), else
// completes the next frame.
//
// A process stage may hold frames back (offline smoothing hands a frame out once the frames after
// it arrived): it returns how many frames became ready to emit. When every stage waits on the
// others (the frames held back fill the ring) the ring grows: `grow` is called with no stage
// running, so the caller can re-seat its slots.
//
// Errors: a stage that throws stops the pipeline; the error rethrown (once every worker stopped)
// is the one a single thread would have met first (the earliest frame, and within a frame read
// before complete before process before emit): the stages finish the frames before it, and
// nothing after it.
#pragma once

#include <functional>

namespace rpt::engine {

struct FrameStages {
  // Reads frame `frame` into slot frame % capacity; false after the last frame.
  std::function<bool(long frame)> read;
  // Completes frame `frame` (read, in its slot). May run on several workers at once for different
  // frames, and beside the other stages. Empty: the frames need no completing.
  std::function<void(long frame)> complete;
  // Processes frame `frame` (complete, in its slot); returns how many frames became ready to emit
  // (the next ones in order; 1 unless frames are held back).
  std::function<long(long frame)> process;
  // After the last frame was processed: returns how many held-back frames became ready (may be empty).
  std::function<long()> flush;
  // Hands on frame `frame` (processed and ready, in its slot); its slot is then free.
  std::function<void(long frame)> emit;
  // The ring grows from `old_capacity` to `new_capacity` slots: the frames [first, end) must move
  // from slot f % old_capacity to f % new_capacity. Called with no stage running.
  std::function<void(long old_capacity, long new_capacity, long first, long end)> grow;
};

// Runs `stages` over a whole sequence on `threads` workers (at least 1; the calling thread is one
// of them) with a ring of `capacity` slots (at least 1). Returns once every frame was emitted, or
// rethrows the first error (see above) once every worker has stopped.
void RunFramePipeline(const FrameStages& stages, int threads, long capacity);

}  // namespace rpt::engine
