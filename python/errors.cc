// SPDX-License-Identifier: MIT
// rpt's errors as Python exceptions, with the CLI's messages:
//   rpt.ConfigError(ValueError)   bad options or parameters (the CLI's ConfigError, exit code 2)
//   rpt.InputError(ValueError)    input that cannot be used (the CLI's InputError, exit code 2)
//   rpt.InputFileNotFoundError(FileNotFoundError, rpt.InputError)   a file or folder named by
//                                 the input is missing ("<path>: file not found", ...)
//   rpt.OutputError(OSError, rpt.InputError)   an output that cannot be written (a full disk, no
//                                 permission, a read-only folder: "<path>: write failed (...)", ...)
// and the CLI's "warning:" lines as warnings of category rpt.InputWarning(UserWarning).
#include <Python.h>

#include <string>
#include <string_view>

#include "core/errors.h"
#include "python/bindings.h"

namespace rpt::python {
namespace {

PyObject* config_error = nullptr;
PyObject* input_error = nullptr;
PyObject* missing_file_error = nullptr;
PyObject* output_error = nullptr;
PyObject* input_warning = nullptr;

// The readers' words for a file or folder that is not there (datasets/io, datasets/calibration,
// datasets/readers): "<path>: file not found", "<path>: folder not found", "<path>: not found",
// "<path>: file not found or unreadable".
bool IsMissingFile(std::string_view message) {
  for (std::string_view words : {": file not found", ": folder not found", ": not found", "folder not found"}) {
    if (message.find(words) != std::string_view::npos) return true;
  }
  return false;
}

// The writers' words for an output that cannot be written (datasets/io/staged_output.cc, the
// exports): "<path>: write failed (<reason>)", "cannot open for writing", "cannot create output
// folder", "cannot create the folder", "cannot replace", "cannot create the HDF5 file".
bool IsWriteFailure(std::string_view message) {
  for (std::string_view words : {"write failed (", "cannot open for writing", "cannot create output folder",
                                 "cannot create the folder", ": cannot replace", "cannot create the HDF5 file"}) {
    if (message.find(words) != std::string_view::npos) return true;
  }
  return false;
}

PyObject* NewException(const char* name, const char* doc, PyObject* bases) {
  PyObject* type = PyErr_NewExceptionWithDoc(name, doc, bases, nullptr);
  if (type == nullptr) throw py::error_already_set();
  return type;
}

}  // namespace

void RegisterErrors(py::module_& m) {
  config_error =
      NewException("rpt.ConfigError", "Bad options or parameters (the CLI's exit code 2).", PyExc_ValueError);
  input_error = NewException("rpt.InputError", "Input that cannot be used (the CLI's exit code 2).", PyExc_ValueError);
  PyObject* bases = PyTuple_Pack(2, PyExc_FileNotFoundError, input_error);
  missing_file_error =
      NewException("rpt.InputFileNotFoundError", "A file or folder named by the input is missing.", bases);
  Py_DECREF(bases);
  bases = PyTuple_Pack(2, PyExc_OSError, input_error);
  output_error = NewException("rpt.OutputError",
                              "An output that cannot be written (a full disk, no permission, a read-only folder).", bases);
  Py_DECREF(bases);
  m.add_object("ConfigError", py::handle(config_error));
  m.add_object("OutputError", py::handle(output_error));
  m.add_object("InputError", py::handle(input_error));
  m.add_object("InputFileNotFoundError", py::handle(missing_file_error));
  input_warning = NewException("rpt.InputWarning",
                               "Input used with a correction or a doubt (the CLI's 'warning:' lines).",
                               PyExc_UserWarning);
  m.add_object("InputWarning", py::handle(input_warning));
  py::register_exception_translator([](std::exception_ptr error) {
    try {
      if (error) std::rethrow_exception(error);
    } catch (const MissingInputError& e) {
      PyErr_SetString(missing_file_error, e.what());
    } catch (const ConfigError& e) {
      PyErr_SetString(config_error, e.what());
    } catch (const InputError& e) {
      PyErr_SetString(IsWriteFailure(e.what()) ? output_error
                      : IsMissingFile(e.what()) ? missing_file_error
                                                : input_error,
                      e.what());
    } catch (const std::bad_alloc&) {
      PyErr_SetString(PyExc_MemoryError, "out of memory");
    }
  });
}

void WarnInput(const std::vector<std::string>& lines) {
  for (const std::string& line : lines) {
    // stacklevel 1: a C function has no frame of its own, so the warning points at the Python line
    // that called rpt (2 pointed one frame above it: "sys:1" from a script's top level). -1: the
    // warning filter made it an exception (python -W error), which propagates.
    if (PyErr_WarnEx(input_warning, line.c_str(), 1) < 0) throw py::error_already_set();
  }
}

}  // namespace rpt::python
