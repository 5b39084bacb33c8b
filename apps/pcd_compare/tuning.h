#pragma once
// The baselines' parameter search (pcd_compare --tune) and its result file, which --tuned
// reads: per baseline and sensor model, the values that gave the highest mean IoU on a
// tuning folder.

#include <iosfwd>
#include <map>
#include <string>
#include <vector>

#include "baselines.h"

namespace pcd_compare {

/// The values to try, per baseline and parameter: {"omps": {"angular_threshold": [...]}}.
using Grid = std::map<std::string, std::map<std::string, std::vector<double>>>;

/// The grid searched when no grid file is given (bench/README.md says why these values).
Grid defaultGrid();
/// Reads a grid from a JSON file of the same shape; every baseline and parameter must be
/// known and every value valid (std::runtime_error naming the file otherwise).
Grid readGrid(const std::string& path);

struct TuningOptions {
  std::string folder;                  ///< the tuning split: <scene>.<sensor>.pcd files with labels
  Grid grid;                           ///< only the baselines named here are tuned
  std::string output_file;             ///< written atomically
  std::size_t clouds_per_sensor = 12;  ///< the subset: evenly spaced in name order
  int passes = 2;                      ///< coordinate-descent passes at most
};

/// Tunes every baseline of `options.grid` per sensor model on a stratified subset of the
/// folder, by coordinate descent from the defaults, maximising the mean IoU; writes the grid,
/// the subset and the winners as JSON. Progress lines go to `progress`. Throws
/// std::runtime_error for a folder without usable clouds or an unwritable output.
void tuneBaselines(const TuningOptions& options, std::ostream& progress);

/// A baseline's tuned values per sensor model, from a file written by tuneBaselines.
struct TunedValues {
  std::map<std::string, std::map<std::string, ParameterValues>> by_method_and_sensor;
};

/// Reads a tuning result; std::runtime_error naming the file if it cannot be read or parsed.
TunedValues readTunedValues(const std::string& path);

}  // namespace pcd_compare
