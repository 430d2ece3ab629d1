// SPDX-License-Identifier: MIT
// File names made from names read from input (cameras, sequences, frame ids): the escaping of the
// file-system sink, one-to-one, so that names from someone else never leave the output folder and
// two distinct names never share a file. Used by rpt render and the TRC export.
#pragma once

#include <string>
#include <vector>

namespace rpt::engine {

// A file name for `text` (a frame id, a camera or sequence name), one-to-one: letters, digits, '-',
// '_' and '.' stay, every other byte becomes %XX ('cam a' -> 'cam%20a', 'cam/a' -> 'cam%2Fa',
// 'cam_a' stays), and so does a leading '.' (no hidden files, no '.' or '..'); "" becomes "%". A
// name over 200 bytes is cut at 180 and ends in '~' and 16 hex digits of a hash of the whole text.
std::string FileNameOf(const std::string& text);

// FileNameOf of each text, made distinct where FileNameOf alone is not: on file systems that do not
// tell case apart ("Cam" and "cam") and for cut long names. A repeated name gets "~2", "~3", ... in
// the order given; distinct texts never share a file.
std::vector<std::string> UniqueFileNames(const std::vector<std::string>& texts);

}  // namespace rpt::engine
