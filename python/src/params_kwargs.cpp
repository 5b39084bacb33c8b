// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "params_kwargs.h"

#include <cstdint>
#include <functional>
#include <limits>
#include <optional>

#include "errors.h"

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

bool toBool(py::handle value, const std::string& where) {
  const py::module_ numpy = py::module_::import("numpy");
  if (!PyBool_Check(value.ptr()) && !py::isinstance(value, numpy.attr("bool_"))) {
    raiseTypeError(where + " must be True or False, got " + typeName(value));
  }
  return value.cast<bool>();
}

// One field: its name, how a Python value is stored into Params, and how it is read back.
struct Field {
  const char* name;
  std::function<void(Params&, py::handle, const std::string&)> set;
  std::function<py::object(const Params&)> get;
};

template <typename T>
py::object optionalObject(const std::optional<T>& value) {
  return value ? py::cast(*value) : py::none();
}

const std::vector<Field>& fields() {
  using Length = std::optional<double> Params::*;
  const auto optionalLength = [](const char* name, Length member) {
    return Field{name,
                 [member](Params& p, py::handle v, const std::string& where) {
                   p.*member = v.is_none() ? std::nullopt : std::optional<double>(toDouble(v, where));
                 },
                 [member](const Params& p) { return optionalObject(p.*member); }};
  };
  const auto number = [](const char* name, double Params::*member) {
    return Field{name, [member](Params& p, py::handle v, const std::string& where) { p.*member = toDouble(v, where); },
                 [member](const Params& p) { return py::cast(p.*member); }};
  };
  static const std::vector<Field> table = {
      optionalLength("distance_threshold", &Params::distance_threshold),
      optionalLength("seed_size", &Params::seed_size),
      number("angular_threshold", &Params::angular_threshold),
      optionalLength("merge_distance", &Params::merge_distance),
      Field{"min_inliers",
            [](Params& p, py::handle v, const std::string& where) {
              if (v.is_none()) {
                p.min_inliers.reset();
              } else {
                p.min_inliers =
                    static_cast<std::uint32_t>(toInteger(v, where, 0, std::numeric_limits<std::uint32_t>::max()));
              }
            },
            [](const Params& p) { return optionalObject(p.min_inliers); }},
      number("maximum_curvature", &Params::maximum_curvature),
      Field{"project_points",
            [](Params& p, py::handle v, const std::string& where) { p.project_points = toBool(v, where); },
            [](const Params& p) { return py::cast(p.project_points); }},
      Field{"subsampling",
            [](Params& p, py::handle v, const std::string& where) {
              p.subsampling = static_cast<int>(
                  toInteger(v, where, std::numeric_limits<int>::min(), std::numeric_limits<int>::max()));
            },
            [](const Params& p) { return py::cast(p.subsampling); }},
      optionalLength("depth_noise_coefficient", &Params::depth_noise_coefficient),
      optionalLength("depth_noise_constant", &Params::depth_noise_constant),
  };
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
