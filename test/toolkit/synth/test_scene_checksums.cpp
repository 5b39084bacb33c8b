// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// The generated scenes of fixed seeds against checksums recorded in this file. Every accuracy
// figure of the project was measured on scenes of these generators, so a change to a generator
// (a draw added, moved or reordered) must show here; and the checksums hold under every
// compiler: .ci/run builds and runs this test with Clang as well as GCC, which evaluate the
// arguments of one call in different orders (hence one draw a statement, synth/random_source.h).
//
// The checksum is over the scene file text (synth::sceneJson) with every number rounded to
// 1e-6, so that the last bits of a sine that two maths libraries round differently do not count
// and a different draw does.

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "synth/scene_file.h"
#include "synth/scene_generator.h"

namespace {

using namespace floodplane::synth;

// The scene file's text with each number outside a string printed with 6 decimals.
std::string roundedNumbers(const std::string& json) {
  std::string out;
  out.reserve(json.size());
  bool in_string = false;
  for (std::size_t i = 0; i < json.size();) {
    const char c = json[i];
    if (in_string) {
      out += c;
      if (c == '\\' && i + 1 < json.size())
        out += json[++i];
      else if (c == '"')
        in_string = false;
      ++i;
      continue;
    }
    const bool starts_number =
        (c >= '0' && c <= '9') || (c == '-' && i + 1 < json.size() && json[i + 1] >= '0' && json[i + 1] <= '9');
    if (!starts_number) {
      in_string = c == '"';
      out += c;
      ++i;
      continue;
    }
    char* end = nullptr;
    const double value = std::strtod(json.c_str() + i, &end);
    char text[64];
    std::snprintf(text, sizeof text, "%.6f", value);
    out += std::string(text) == "-0.000000" ? "0.000000" : text;
    i = static_cast<std::size_t>(end - json.c_str());
  }
  return out;
}

// FNV-1a, 64 bits.
std::uint64_t checksum(const std::string& text, std::uint64_t hash = 14695981039346656037ull) {
  for (const char c : text) {
    hash ^= static_cast<unsigned char>(c);
    hash *= 1099511628211ull;
  }
  return hash;
}

template <typename Generate>
std::uint64_t checksumOfSeeds(Generate generate, std::uint64_t first, std::uint64_t last) {
  std::uint64_t hash = 14695981039346656037ull;
  for (std::uint64_t seed = first; seed <= last; ++seed)
    hash = checksum(roundedNumbers(sceneJson(generate(seed))), hash);
  return hash;
}

constexpr const char* kWhenChangedOnPurpose =
    "the generator gives other scenes for the same seeds. If that is the intent, render the "
    "splits again, re-measure every recorded accuracy figure on them (bench/README.md, "
    "bench/HISTORY.md) and record the new checksum here; if not, look for two draws in one "
    "expression (synth/random_source.h)";

TEST(SceneChecksums, RoundingKeepsTextAndRoundsEveryNumber) {
  EXPECT_EQ(roundedNumbers(R"({"a-1":[1,-2.5e-1,0.1234567,-0.0000001],"b":"x\"3"})"),
            R"({"a-1":[1.000000,-0.250000,0.123457,0.000000],"b":"x\"3"})");
}

TEST(SceneChecksums, RoomsOfSeeds1To20AreTheRecordedOnes) {
  EXPECT_EQ(checksumOfSeeds(generateRoomScene, 1, 20), 0xe339c7333a6ebb38ull) << kWhenChangedOnPurpose;
}

TEST(SceneChecksums, BlocksOfSeeds1To20AreTheRecordedOnes) {
  EXPECT_EQ(checksumOfSeeds(generateBlocksScene, 1, 20), 0xc70751dbde2ce69aull) << kWhenChangedOnPurpose;
}

TEST(SceneChecksums, BoardsOfSeeds1To20AreTheRecordedOnes) {
  EXPECT_EQ(checksumOfSeeds(generateBoardsScene, 1, 20), 0xdc3184a9d8dc533aull) << kWhenChangedOnPurpose;
}

}  // namespace
