// SPDX-License-Identifier: MIT
// The fields of an options struct (one with VisitFields, core/option_spec.h) as command-line
// options `--<prefix><key>` (underscores written as dashes), their values parsed by the option
// codec (core/option_codec.h) once the command line is read: the same words, ranges and messages
// as --set and --param. Used where a command exposes a library's options struct directly (the
// calibration reader's and writer's options of `rpt cameras`).
#pragma once

#include <CLI/CLI.hpp>
#include <algorithm>
#include <map>
#include <memory>
#include <string>
#include <utility>

#include "core/errors.h"
#include "core/option_codec.h"
#include "core/options_check.h"

namespace rpt::cli {

template <class Options>
class FieldOptions {
 public:
  FieldOptions(CLI::App* command, std::string prefix, const std::string& what) : prefix_(std::move(prefix)) {
    Adder adder{command, prefix_, what, texts_};
    VisitFields(adder, std::as_const(defaults_));
  }

  // The options given on the command line over the defaults, then their Check() if they have one;
  // a bad value throws ConfigError naming the option.
  Options Parse() const {
    Options options = defaults_;
    Reader reader{prefix_, *texts_};
    VisitFields(reader, options);
    if constexpr (requires { options.Check(); }) ThrowIfInvalid(options);
    return options;
  }

 private:
  using Texts = std::map<std::string, std::string>;  // key -> text given

  static std::string Flag(const std::string& prefix, std::string_view key) {
    std::string flag = "--" + prefix + std::string(key);
    std::replace(flag.begin(), flag.end(), '_', '-');
    return flag;
  }

  struct Adder {
    CLI::App* command;
    const std::string& prefix;
    const std::string& what;
    std::shared_ptr<Texts> texts;
    template <class T>
    void operator()(std::string_view key, const T& value, const OptionSpec& spec) {
      std::string* text = &(*texts)[std::string(key)];
      command->add_option(Flag(prefix, key), *text,
                          what + std::string(spec.help) + " [" + OptionTypeText<T>(spec) + ", default " +
                              FormatOption(value) + "]");
    }
  };

  struct Reader {
    const std::string& prefix;
    const Texts& texts;
    template <class T>
    void operator()(std::string_view key, T& value, const OptionSpec& spec) {
      const auto it = texts.find(std::string(key));
      if (it == texts.end() || it->second.empty()) return;
      if (const std::string problem = ParseOption(it->second, spec, &value); !problem.empty()) {
        throw ConfigError(OptionMessage("command line", Flag(prefix, key), problem));
      }
    }
  };

  std::string prefix_;
  Options defaults_{};
  std::shared_ptr<Texts> texts_ = std::make_shared<Texts>();
};

}  // namespace rpt::cli
