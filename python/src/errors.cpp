// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "errors.h"

#include <filesystem>
#include <system_error>

namespace floodplane::python {
namespace {

[[noreturn]] void raise(PyObject* type, const std::string& message) {
  PyErr_SetString(type, message.c_str());
  throw pybind11::error_already_set();
}

}  // namespace

void raiseTypeError(const std::string& message) { raise(PyExc_TypeError, message); }

void raiseValueError(const std::string& message) { raise(PyExc_ValueError, message); }

void raiseFileError(FileAccess access, const std::string& function, const std::string& argument,
                    const std::string& path, const std::string& reason) {
  std::filesystem::path needed(path);
  if (access == FileAccess::write) {
    needed = needed.parent_path();
    if (needed.empty()) needed = ".";
  }
  std::error_code error;
  const bool missing = !std::filesystem::exists(needed, error) && !error;
  raise(missing ? PyExc_FileNotFoundError : PyExc_OSError, function + ": " + argument + " '" + path + "': " + reason);
}

std::string typeName(pybind11::handle value) {
  const pybind11::handle type = reinterpret_cast<PyObject*>(Py_TYPE(value.ptr()));
  const std::string module = pybind11::str(type.attr("__module__"));
  const std::string name = pybind11::str(type.attr("__qualname__"));
  return module == "builtins" ? name : module + "." + name;
}

}  // namespace floodplane::python
