// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// floodplane::Params from Python keyword arguments whose names are the struct's field names,
// and back. One table of the fields, so that the names, the conversions and the messages
// cannot drift apart.

#include <pybind11/pybind11.h>

#include <string>
#include <vector>

#include "floodplane/params.h"

namespace floodplane::python {

/// A number (int or float, numpy's too; not bool, not a string), for a length or an angle.
/// Raises TypeError otherwise; `where` names the argument in the message.
double toDouble(pybind11::handle value, const std::string& where);

/// An integer (anything with __index__, not bool) in [low, high]. Raises TypeError for
/// another type, ValueError for a value outside the range.
long long toInteger(pybind11::handle value, const std::string& where, long long low, long long high);

/// The keyword names, in the order of floodplane::Params.
std::vector<std::string> parameterNames();

/// Params with each keyword of `keywords` set; `function` names the caller in messages.
/// Raises TypeError for an unknown keyword or a value of the wrong type (a string, a bool
/// where a number is meant, None for a field that is not optional), ValueError for a value
/// the method cannot use (Params::problem()).
Params paramsFromKeywords(const pybind11::dict& keywords, const std::string& function);

/// Every field as a dict, None for the optional ones that are unset.
pybind11::dict paramsToDict(const Params& params);

}  // namespace floodplane::python
