// SPDX-License-Identifier: MIT
#include "datasets/dataset_params.h"

#include <algorithm>

#include "core/closest_name.h"
#include "core/text.h"

namespace rpt::dataset_params {

std::string ParamKey(std::string_view dataset, std::string_view key) {
  return std::string(dataset) + "." + std::string(key);
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
