// Each competitor registers its benchmarks from its own file.
#pragma once

#include <string>

namespace floodplane::bench {

/// The configuration a method prints before the numbers.
std::string floodplaneConfiguration();
std::string ompsConfiguration();

void registerFloodplane();
void registerOmps();

}  // namespace floodplane::bench
