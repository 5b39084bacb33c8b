// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "params_kwargs.h"

#include <cstdint>
#include <functional>
#include <limits>
#include <optional>

#include "errors.h"
#include "params/params_table.h"

namespace floodplane::python {

namespace py = pybind11;

// A number for a length or an angle: int or float (numpy's too), not bool, not a string.
double toDouble(py::handle value, const std::string& where) {
  if (PyBool_Check(value.ptr()) || PyComplex_Check(value.ptr()) || !PyNumber_Check(value.ptr())) {
    raiseTypeError(where + " must be a number, got " + typeName(value));
  }
  const double number = PyFloat_AsDouble(value.ptr());
  if (number == -1.0 && PyErr_Occurred()) throw py::error_already_set();
  return number;
}

// An integer (numpy's too, anything with __index__), not bool, within [low, high].
long long toInteger(py::handle value, const std::string& where, long long low, long long high) {
  if (PyBool_Check(value.ptr()) || !PyIndex_Check(value.ptr())) {
    raiseTypeError(where + " must be an integer, got " + typeName(value));
  }
  const py::int_ integer = py::reinterpret_steal<py::int_>(PyNumber_Index(value.ptr()));
  int overflow = 0;
  const long long number = PyLong_AsLongLongAndOverflow(integer.ptr(), &overflow);
  if (overflow != 0 || number < low || number > high) {
    raiseValueError(where + " must be an integer in [" + std::to_string(low) + ", " + std::to_string(high) + "], got " +
                    py::str(integer.ptr()).cast<std::string>());
  }
  return number;
}

namespace {

// One field: its name, how a Python value is stored into Params, and how it is read back.
struct Field {
  const char* name;
  std::function<void(Params&, py::handle, const std::string&)> set;
  std::function<py::object(const Params&)> get;
};

// How a Python value is stored into a field of each type (None unsets an optional field).
void assign(std::optional<double>& member, py::handle value, const std::string& where) {
  member = value.is_none() ? std::nullopt : std::optional<double>(toDouble(value, where));
}
void assign(double& member, py::handle value, const std::string& where) { member = toDouble(value, where); }
void assign(std::optional<std::uint32_t>& member, py::handle value, const std::string& where) {
  if (value.is_none()) {
    member.reset();
  } else {
    member = static_cast<std::uint32_t>(toInteger(value, where, 0, std::numeric_limits<std::uint32_t>::max()));
  }
}
void assign(int& member, py::handle value, const std::string& where) {
  member = static_cast<int>(toInteger(value, where, std::numeric_limits<int>::min(), std::numeric_limits<int>::max()));
}

template <typename T>
py::object toPython(const T& value) {
  return py::cast(value);
}
template <typename T>
py::object toPython(const std::optional<T>& value) {
  return value ? py::cast(*value) : py::none();
}

// Every field of params_table.h, in its order.
const std::vector<Field>& fields() {
#define FLOODPLANE_FIELD(field, kind, flag, setter, help)                                             \
  Field{#field, [](Params& p, py::handle v, const std::string& where) { assign(p.field, v, where); }, \
        [](const Params& p) { return toPython(p.field); }},
  static const std::vector<Field> table = {FLOODPLANE_PARAMETERS(FLOODPLANE_FIELD)};
#undef FLOODPLANE_FIELD
  return table;
}

std::string nameList() {
  std::string list;
  for (const Field& field : fields()) list += (list.empty() ? "" : ", ") + std::string(field.name);
  return list;
}

}  // namespace

std::vector<std::string> parameterNames() {
  std::vector<std::string> names;
  for (const Field& field : fields()) names.emplace_back(field.name);
  return names;
}

Params paramsFromKeywords(const py::dict& keywords, const std::string& function) {
  Params params;
  for (const auto& [key, value] : keywords) {
    const std::string name = py::str(key);
    const Field* field = nullptr;
    for (const Field& candidate : fields()) {
      if (name == candidate.name) field = &candidate;
    }
    if (!field) {
      raiseTypeError(function + "() got an unexpected keyword argument '" + name + "' (the parameters are " +
                     nameList() + ")");
    }
    field->set(params, value, function + ": " + name);
  }
  const std::string problem = params.problem();
  if (!problem.empty()) raiseValueError(function + ": " + problem);
  return params;
}

py::dict paramsToDict(const Params& params) {
  py::dict dict;
  for (const Field& field : fields()) dict[field.name] = field.get(params);
  return dict;
}

}  // namespace floodplane::python
