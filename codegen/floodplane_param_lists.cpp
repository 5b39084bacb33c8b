// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// floodplane_param_lists <template> <output>: writes the template with its markers replaced by
// the parameter lists of src/params/params_table.h (param_lists.h). Run by the build for the
// Python stubs and the ROS node's dynamic_reconfigure script; installed with the component
// ros, so that the ROS package builds against an installed floodplane too. The output is
// written to a temporary beside it and renamed: never half written.

#include <cstdio>
#include <exception>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

#include "param_lists.h"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: floodplane_param_lists <template> <output>\n"
                 "  writes <template> with each line holding a marker alone replaced by its list:\n"
                 "  "
              << floodplane::param_lists::kStubKeywordsMarker << " (the Python stubs' keywords), "
              << floodplane::param_lists::kReconfigureEntriesMarker << " (dynamic_reconfigure's entries)\n";
    return 2;
  }
  const std::string input = argv[1];
  const std::string output = argv[2];
  try {
    std::ifstream file(input, std::ios::binary);
    if (!file) throw std::runtime_error("cannot read the template");
    std::stringstream text;
    text << file.rdbuf();
    const std::string result = floodplane::param_lists::filled(text.str());
    const std::string temporary = output + ".tmp";
    {
      std::ofstream written(temporary, std::ios::binary | std::ios::trunc);
      written << result;
      written.close();
      if (!written) {
        std::remove(temporary.c_str());
        throw std::runtime_error("cannot write " + temporary);
      }
    }
    if (std::rename(temporary.c_str(), output.c_str()) != 0) {
      std::remove(temporary.c_str());
      throw std::runtime_error("cannot rename " + temporary + " to " + output);
    }
  } catch (const std::exception& error) {
    std::cerr << "floodplane_param_lists: " << input << ": " << error.what() << "\n";
    return 1;
  }
  return 0;
}
