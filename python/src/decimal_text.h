// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Numbers as the objects' repr() writes them.

#include <cstdio>
#include <string>

namespace floodplane::python {

/// `value` with `decimals` digits after the point ("0.125").
inline std::string fixed(double value, int decimals) {
  char text[64];
  std::snprintf(text, sizeof(text), "%.*f", decimals, value);
  return text;
}

}  // namespace floodplane::python
