// SPDX-License-Identifier: MIT
#include "datasets/io/text_file.h"

#include <fstream>

#include "core/errors.h"
#include "datasets/io/staged_output.h"

namespace rpt::io {

void WriteTextFile(const std::filesystem::path& path, NamedBy named_by,
                   const std::function<void(std::ostream&)>& write) {
  StagedFile staged(path, named_by);
  std::ofstream out(staged.path(), std::ios::binary | std::ios::trunc);
  if (!out) throw InputError(path.string() + ": cannot open for writing");
  write(out);
  out.close();
  if (!out) throw InputError(path.string() + ": write failed (" + WriteFailureReason(staged.path(), errno) + ")");
  staged.Commit();
}

void WriteTextFile(const std::filesystem::path& path, NamedBy named_by, const std::string& text) {
  WriteTextFile(path, named_by,
                [&text](std::ostream& out) { out.write(text.data(), static_cast<std::streamsize>(text.size())); });
}

}  // namespace rpt::io
