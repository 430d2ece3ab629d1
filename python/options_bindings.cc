// SPDX-License-Identifier: MIT
// rpt.Options: every option of the configuration (engine/config.h: the triangulator's sections and
// "metrics"), typed, read and written through the one option codec, so values are refused with the
// CLI's words and key ("Options: filter.min_match_score: '1.5' is not a number in [0, 1]").
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <string>

#include "core/errors.h"
#include "engine/config.h"
#include "python/bindings.h"
#include "python/option_values.h"

namespace rpt::python {

std::string OptionText(py::handle value, std::string_view where, std::string_view key) {
  if (value.is_none()) throw ConfigError(OptionMessage(where, key, "None is not a value"));
  if (py::isinstance<py::str>(value)) return value.cast<std::string>();
  if (py::isinstance<py::bool_>(value)) return value.cast<bool>() ? "true" : "false";
  if (py::isinstance<py::float_>(value)) return FormatNumber(value.cast<double>());
  // ints, numpy scalars, lists and tuples as JSON writes them (a list of names, a 3-vector)
  py::object json = py::module_::import("json");
  py::object numpy_tolist = py::getattr(value, "tolist", py::none());
  py::object plain = numpy_tolist.is_none() ? py::reinterpret_borrow<py::object>(value) : numpy_tolist();
  if (py::isinstance<py::float_>(plain)) return FormatNumber(plain.cast<double>());
  if (py::isinstance<py::bool_>(plain)) return plain.cast<bool>() ? "true" : "false";
  try {
    return json.attr("dumps")(plain).cast<std::string>();
  } catch (const py::error_already_set&) {
    throw ConfigError(OptionMessage(
        where, key,
        "a " + py::str(py::type::of(value)).cast<std::string>() + " is not a value (str, bool, number or list)"));
  }
}

namespace {

// Calls f(section, name, field) for every option of `config`, in dump order.
template <class Self, class F>
void ForEachOption(Self& config, F&& f) {
  auto section_visitor = [&f](std::string_view section, auto& options) {
    auto field_visitor = [&f, section](std::string_view name, auto& field, const OptionSpec&) {
      f(section, name, field);
    };
    VisitFields(field_visitor, options);
  };
  VisitSections(section_visitor, config);
}

py::object Get(const engine::Config& config, const std::string& key) {
  py::object result;
  ForEachOption(config, [&](std::string_view section, std::string_view name, const auto& field) {
    if (!result && key == std::string(section) + "." + std::string(name)) result = OptionObject(field);
  });
  if (!result) engine::GetConfigOption(config, key);  // throws the CLI's "unknown option" with its suggestion
  return result;
}

void Set(engine::Config* config, const std::string& key, py::handle value, const std::string& where) {
  engine::SetConfigOption(key, OptionText(value, where, key), where, config);
}

// {"section": {"key": value}} or {"section.key": value}, applied in order.
void Apply(engine::Config* config, const py::dict& values, const std::string& where) {
  for (const auto& [key_object, value] : values) {
    const std::string key = py::str(key_object).cast<std::string>();
    if (py::isinstance<py::dict>(value)) {
      for (const auto& [name, item] : py::reinterpret_borrow<py::dict>(value)) {
        Set(config, key + "." + py::str(name).cast<std::string>(), item, where);
      }
    } else {
      Set(config, key, value, where);
    }
  }
}

py::dict ToDict(const engine::Config& config) {
  py::dict out;
  ForEachOption(config, [&](std::string_view section, std::string_view name, const auto& field) {
    const py::str section_key{std::string(section)};
    if (!out.contains(section_key)) out[section_key] = py::dict();
    out[section_key][py::str(std::string(name))] = OptionObject(field);
  });
  return out;
}

}  // namespace

engine::Config ConfigOf(py::handle options) {
  engine::Config config;
  if (options.is_none()) return config;
  if (py::isinstance<engine::Config>(options)) {
    config = options.cast<engine::Config>();
  } else if (py::isinstance<py::dict>(options)) {
    Apply(&config, py::reinterpret_borrow<py::dict>(options), "options");
  } else {
    throw py::type_error("options: expected None, a dict or an rpt.Options, got " +
                         py::str(py::type::of(options)).cast<std::string>());
  }
  engine::CheckConfig(config);
  return config;
}

void RegisterOptions(py::module_& m) {
  py::class_<engine::Config>(m, "Options",
                             "Every option of the triangulator and the metrics (`rpt config --dump`), typed. Keys are "
                             "'section.name' (docs/options.md); values are refused like the CLI's --set.")
      .def(py::init([](py::handle values) {
             engine::Config config;
             if (py::isinstance<engine::Config>(values)) return values.cast<engine::Config>();  // a copy
             if (!values.is_none()) {
               if (!py::isinstance<py::dict>(values)) {
                 throw py::type_error("Options: expected a dict of values or an rpt.Options, got " +
                                      py::str(py::type::of(values).attr("__name__")).cast<std::string>());
               }
               Apply(&config, py::reinterpret_borrow<py::dict>(values), "Options");
             }
             return config;
           }),
           py::arg("values") = py::none(),
           "Defaults, then `values`: {'section': {'name': value}} or {'section.name': value}; or a copy of an "
           "rpt.Options")
      .def_static(
          "from_json",
          [](const std::filesystem::path& path) {
            engine::Config config;
            engine::LoadConfigFile(path, &config);
            return config;
          },
          py::arg("path"), "A config file as `--config FILE` reads it (any subset of sections and keys), checked")
      .def_static(
          "from_dict",
          [](const py::dict& values) {
            engine::Config config;
            Apply(&config, values, "Options.from_dict");
            engine::CheckConfig(config);
            return config;
          },
          py::arg("values"))
      .def("to_dict", &ToDict, "{'section': {'name': value}} with every option, typed")
      .def(
          "to_json", [](const engine::Config& c) { return engine::DumpConfig(c, false); },
          "The JSON text of `rpt config --dump` (from_json reads it back)")
      .def("__getitem__", &Get, py::arg("key"))
      .def("__setitem__",
           [](engine::Config& c, const std::string& key, py::handle value) { Set(&c, key, value, "Options"); })
      .def("__contains__",
           [](const engine::Config&, const std::string& key) {
             for (const engine::ConfigOptionInfo& info : engine::ConfigOptions()) {
               if (info.key == key) return true;
             }
             return false;
           })
      .def_static(
          "keys",
          [] {
            std::vector<std::string> keys;
            for (const engine::ConfigOptionInfo& info : engine::ConfigOptions()) keys.push_back(info.key);
            return keys;
          },
          "Every key, in dump order")
      .def_static(
          "describe",
          [](const std::string& key) {
            for (const engine::ConfigOptionInfo& info : engine::ConfigOptions()) {
              if (info.key != key) continue;
              py::dict d;
              d["key"] = info.key;
              d["type"] = info.type;
              d["default"] = info.default_value;
              d["unit"] = std::string(info.spec.unit);
              d["help"] = std::string(info.spec.help);
              return d;
            }
            engine::GetConfigOption(engine::Config{}, key);  // unknown: the CLI's message
            return py::dict();
          },
          py::arg("key"), "type, default, unit and help of one option")
      .def("check", &engine::CheckConfig, "Raises ConfigError naming the key of the first invalid setting")
      .def("warnings", &engine::ConfigWarnings, "Valid settings without effect, one line each")
      .def("copy", [](const engine::Config& c) { return c; })
      .def("__copy__", [](const engine::Config& c) { return c; })
      .def("__deepcopy__", [](const engine::Config& c, py::dict) { return c; }, py::arg("memo"))
      // Pickled as its values (to_dict), read back as Options(values) reads them: a sweep's workers
      // (multiprocessing, joblib) take Options.
      .def(py::pickle([](const engine::Config& c) { return ToDict(c); },
                      [](const py::dict& values) {
                        engine::Config config;
                        Apply(&config, values, "Options (unpickled)");
                        return config;
                      }))
      .def("__eq__",
           [](const engine::Config& a, const engine::Config& b) {
             return engine::DumpConfig(a, false) == engine::DumpConfig(b, false);
           })
      .def("__repr__", [](const engine::Config& c) {
        const engine::Config defaults;
        std::string changed;
        for (const engine::ConfigOptionInfo& info : engine::ConfigOptions()) {
          const std::string value = engine::GetConfigOption(c, info.key);
          if (value != info.default_value) changed += (changed.empty() ? "" : ", ") + info.key + "=" + value;
        }
        return "Options(" + changed + ")";
      });
}

}  // namespace rpt::python
