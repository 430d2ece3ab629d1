// SPDX-License-Identifier: MIT
// Safe reader for Python pickles (protocols 2-5) as written by VoxelPose, mmpose,
// EgoHumans and np.save of object arrays.
//
// It is a small stack machine for the binary opcodes, never an evaluator: GLOBAL /
// STACK_GLOBAL may only name an allow-listed callable, and each of those is re-implemented
// here with fixed semantics:
//   numpy.core.multiarray._reconstruct, numpy.ndarray, numpy.dtype,
//   numpy.core.multiarray.scalar, numpy.core.numeric._frombuffer (numpy._core.* alike),
//   collections.defaultdict, collections.OrderedDict,
//   builtins/__builtin__ list, dict, tuple, set, frozenset, bytes, bytearray,
//   _codecs.encode (how protocol 2 stores bytes).
// Anything else (os.system, builtins.eval, copyreg._reconstructor of arbitrary classes,
// ...) is refused with an InputError naming the module.name, the byte offset and the file.
// Refused opcodes: text-protocol opcodes (INT, LONG, FLOAT, STRING, UNICODE, GET, PUT,
// INST, OBJ), persistent ids, extension codes, out-of-band buffers (NEXT_BUFFER).
//
// Resource limits: every length is checked against the remaining bytes; the work done by
// copies (list(...), array data, dict keys) is limited to a multiple of the input size;
// the finished value tree may nest at most kPickleMaxDepth levels and may not contain
// cycles. Memory use is linear in the input size.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>

#include "datasets/io/py_value.h"

namespace rpt::io {

inline constexpr std::size_t kPickleMaxDepth = 200;

// Parses pickle bytes. `source` names the data in messages; `base_offset` is added to
// reported byte offsets (for a pickle embedded in a larger file, e.g. an .npy payload).
PyView ParsePickle(std::span<const std::uint8_t> bytes, const std::string& source,
                   std::size_t base_offset = 0);

// Reads and parses a .pkl file; messages name the path.
PyView ReadPickle(const std::filesystem::path& path);

}  // namespace rpt::io
