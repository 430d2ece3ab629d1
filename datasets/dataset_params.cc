// SPDX-License-Identifier: MIT
#include "datasets/dataset_params.h"

#include <algorithm>

#include "core/closest_name.h"
#include "core/text.h"

namespace rpt::dataset_params {

std::string ParamKey(std::string_view dataset, std::string_view key) {
  return std::string(dataset) + "." + std::string(key);
}

std::string RepeatedNameProblem(const std::vector<std::string>& names) {
  for (size_t i = 1; i < names.size(); ++i) {
    for (size_t k = 0; k < i; ++k) {
      if (names[i] == names[k]) return QuoteName(names[i]) + " is listed twice";
    }
  }
  return "";
}

std::string UnknownParamProblem(std::string_view dataset, const std::string& key,
                                const std::vector<std::string>& known) {
  return UnknownNameProblem("parameter", key, known,
                            std::string(dataset) + " has: " + (known.empty() ? std::string("none") : Join(known)));
}

void CheckKnownKeys(const std::string& dataset, const std::map<std::string, std::string>& given,
                    const std::vector<std::string>& known) {
  for (const auto& [key, value] : given) {
    if (std::find(known.begin(), known.end(), key) != known.end()) continue;
    throw ConfigError("--param " + key + "=" + value + ": " + UnknownParamProblem(dataset, key, known));
  }
}

}  // namespace rpt::dataset_params
