// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// How the extension reports bad input: the Python exception that fits, with a message that
// names the function and the argument. Every function throws (pybind11::error_already_set),
// so a caller cannot forget to return.

#include <pybind11/pybind11.h>

#include <string>

namespace floodplane::python {

/// TypeError: an argument of the wrong type or dtype.
[[noreturn]] void raiseTypeError(const std::string& message);
/// ValueError: an argument of the right type with a value that cannot be used (shape, range).
[[noreturn]] void raiseValueError(const std::string& message);
enum class FileAccess { read, write };

/// OSError: a file that cannot be read or written; FileNotFoundError when the file to read,
/// or the folder of the file to write, does not exist. The message is
/// "<function>: <argument> '<path>': <reason>".
[[noreturn]] void raiseFileError(FileAccess access, const std::string& function, const std::string& argument,
                                 const std::string& path, const std::string& reason);

/// The Python type name of `value` ("str", "numpy.ndarray"), for messages.
std::string typeName(pybind11::handle value);

}  // namespace floodplane::python
