// SPDX-License-Identifier: MIT
// NumPy .npy and .npz readers.
//
// NPY versions 1.0, 2.0 and 3.0; the header is a Python dict literal with 'descr' (a type
// string such as '<f8', '<f4', '<i8', '|u1', '|b1', '<U12', '|S4', or a structured list
// of (name, type[, shape]) tuples), 'fortran_order' and 'shape'. Arrays with dtype '|O'
// carry a pickle (read with the safe VM of pickle.h): np.save of a dict or list gives a
// 0-d object array, for which the unpickled value itself is returned.
//
// NPZ is a ZIP archive of .npy members, stored or deflated. The ZIP reader handles the
// central directory, local headers (including numpy's zip64 extra field in local headers
// of small members) and CRC-32; real zip64 archives (> 4 GiB or > 65535 members),
// encryption, multi-disk archives and other compression methods are refused clearly.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "datasets/io/py_value.h"

namespace rpt::io {

// Returns an ndarray value, or for a 0-d object array the unpickled object.
PyView ParseNpy(std::span<const std::uint8_t> bytes, const std::string& source);
PyView ReadNpy(const std::filesystem::path& path);

// Member name (".npy" suffix removed, as numpy's NpzFile does) -> value. Members that are
// not .npy files are returned as bytes under their full name. Before anything is inflated, the
// `required` members (names without ".npy") must be in the archive and the sizes the directory
// declares must fit the file's decompression budget (inflate_budget.h); else InputError.
std::map<std::string, PyView> ParseNpz(std::span<const std::uint8_t> bytes, const std::string& source,
                                       const std::vector<std::string>& required = {});
std::map<std::string, PyView> ReadNpz(const std::filesystem::path& path, const std::vector<std::string>& required = {});

// The pieces, exposed for readers and tests.
// Parses a Python literal (dict, list, tuple, str, int, float, True/False/None) such as an
// NPY header; `where` prefixes error messages.
PyValuePtr ParsePythonLiteral(std::string_view text, const std::string& where);
// A dtype from an NPY 'descr' value (type string or structured list).
DType DTypeFromDescr(const PyValue& descr, const std::string& where);

}  // namespace rpt::io
