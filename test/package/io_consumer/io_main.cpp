// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// Writes a small organized cloud as a PCD file with the installed floodplane::io, reads it
// back as an input frame and checks the points and the labels' colours.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "floodplane/io/input_frame.h"
#include "floodplane/io/label_palette.h"
#include "floodplane/io/pcd_file.h"

int main() {
  pcl::PointCloud<pcl::PointXYZ> cloud(3, 2);
  for (std::size_t i = 0; i < cloud.size(); ++i) cloud[i] = pcl::PointXYZ(0.1f * i, 0.2f, 1.0f + i);
  cloud[4].x = cloud[4].y = cloud[4].z = NAN;
  const std::string path = (std::filesystem::temp_directory_path() / "floodplane_io_consumer.pcd").string();
  floodplane::io::savePcd(path, cloud);
  const floodplane::io::InputFrame frame = floodplane::io::loadInputFrame(path);
  std::filesystem::remove(path);
  if (frame.xyz.width != 3 || frame.xyz.height != 2) {
    std::fprintf(stderr, "io_consumer: read a %ux%u frame, wrote 3x2\n", frame.xyz.width, frame.xyz.height);
    return 1;
  }
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const bool same = i == 4 ? std::isnan(frame.xyz[i].z) : frame.xyz[i].z == cloud[i].z;
    if (!same) {
      std::fprintf(stderr, "io_consumer: point %zu read back as z = %g\n", i, frame.xyz[i].z);
      return 1;
    }
  }
  if (floodplane::io::labelColor(0) != floodplane::io::kNoPlaneColor) {
    std::fprintf(stderr, "io_consumer: label 0 is not coloured as no plane\n");
    return 1;
  }
  std::printf("io_consumer: a 3x2 PCD written and read back with floodplane::io\n");
  return 0;
}
