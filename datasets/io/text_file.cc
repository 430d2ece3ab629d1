// SPDX-License-Identifier: MIT
#include "datasets/io/text_file.h"

#include <fstream>

#include "core/errors.h"

namespace rpt::io {

void WriteTextFile(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) throw InputError(path.string() + ": cannot open for writing");
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
  out.close();
  if (!out) throw InputError(path.string() + ": write failed");
}

}  // namespace rpt::io
