#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
# Every include of the library points down its layers, which are the pipeline's steps:
#   the API's plain types (floodplane/point_grid.h, plane_fit.h, params.h, noise_model.h,
#   segmentation_stats.h, segmentation.h)
#   <- util/ (SIMD, small containers, label-image scans)
#   <- models/ (what the steps share: noise model, tolerances, flood criterion, plane sums,
#      planarity test, the plane candidates and their numbers, facet pairs)
#   <- frame/ (the frame's preparation) <- seeds/ (seed selection) <- flood/ (the flood pass)
#   <- coarse/ (the coarse planes, s > 1) and regions/ (the planes a user gets), neither
#      including the other
#   <- segmenter/ (Segmenter::segment calling them in order; floodplane/segmenter.h, which no
#      step includes: they take and return the plain types)
#   <- tracking/, semantics/, objects/, pcl_interface/ and the PCL class (floodplane/flood_fill_plane_segmentation.h).
# params/ sits beside util/ (it needs the API's params.h alone). A public header includes
# nothing of src/, io/ or toolkit/. Beside the library, on its API: io/ (floodplane_io, the
# file formats), whose headers (io/include/floodplane/io) include the API and each other alone
# and whose sources also the parameters' one list (params/); nothing of src/ includes io's.
# toolkit/ (what the programs, tests and benchmarks share) sits on top: it includes the API,
# io's headers, params/ and its own folders, never the pipeline's internals.
# Lists every include that runs back up and fails.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"

types='floodplane/(point_grid|plane_fit|params|noise_model|segmentation_stats|segmentation)\.h'
# Allowed targets of #include "..." per folder, as one extended regex each.
declare -A allowed=(
  [util]="^(util/|${types})"
  [params]="^(params/|${types})"
  [models]="^(util/|models/|${types})"
  [frame]="^(util/|models/|frame/|${types})"
  [seeds]="^(util/|models/|frame/|seeds/|${types})"
  [flood]="^(util/|models/|frame/|seeds/|flood/|${types})"
  [coarse]="^(util/|models/|frame/|seeds/|flood/|coarse/|${types})"
  [regions]="^(util/|models/|frame/|seeds/|flood/|regions/|${types})"
  [segmenter]="^(util/|models/|frame/|seeds/|flood/|coarse/|regions/|segmenter/|${types}|floodplane/segmenter\.h)"
  [tracking]="^(util/|models/|tracking/|floodplane/)"
  [semantics]="^(util/|models/|semantics/|floodplane/)"
  [objects]="^(util/|models/|objects/|floodplane/)"
  [pcl_interface]="^(floodplane/)"
)
toolkit='^(floodplane/|params/|cli/|view/|baselines/|synth/|eval/)'
# io/: its headers on the API and each other, its sources on those and the parameters' list.
declare -A io_allowed=([include]='^floodplane/' [src]='^(floodplane/|params/)')
# An include line's target, matched by bash itself: a process per line made this take half a
# minute on a loaded machine.
include='^[[:space:]]*#include "([^"]*)"'
problems=()
for folder in "${!allowed[@]}"; do
  [ -d "src/$folder" ] || continue
  while IFS= read -r line; do
    file=${line%%:*}
    rest=${line#*:}
    number=${rest%%:*}
    [[ "${rest#*:}" =~ $include ]] || continue
    target=${BASH_REMATCH[1]}
    # A file's own header, next to it, and generated headers (no folder) are its own.
    [[ "$target" == */* ]] || continue
    [[ "$target" =~ ${allowed[$folder]} ]] || problems+=("src/$folder/$file:$number includes \"$target\"")
  done < <(cd "src/$folder" && grep -n '#include "' -- *.h *.cpp 2> /dev/null || true)
done
while IFS= read -r line; do
  file=${line%%:*}
  rest=${line#*:}
  [[ "${rest#*:}" =~ $include ]] || continue
  target=${BASH_REMATCH[1]}
  [[ "$target" == */* ]] || continue
  [[ "$target" =~ $toolkit ]] || problems+=("toolkit/$file:${rest%%:*} includes \"$target\"")
done < <(cd toolkit && grep -rn '#include "' --include='*.h' --include='*.cpp' . | sed 's|^\./||' || true)
for part in include src; do
  while IFS= read -r line; do
    file=${line%%:*}
    rest=${line#*:}
    [[ "${rest#*:}" =~ $include ]] || continue
    target=${BASH_REMATCH[1]}
    [[ "$target" == */* ]] || continue
    [[ "$target" =~ ${io_allowed[$part]} ]] || problems+=("io/$part/$file:${rest%%:*} includes \"$target\"")
  done < <(cd "io/$part" && grep -rn '#include "' --include='*.h' --include='*.cpp' . | sed 's|^\./||' || true)
done
while IFS= read -r line; do
  problems+=("src/$line (the library includes the file formats' io/)")
done < <(cd src && grep -rn '#include "floodplane/io/' . | sed 's|^\./||' || true)
while IFS= read -r line; do
  problems+=("include/$line (a public header includes an internal one)")
done < <(cd include && grep -rnE '#include "(util|models|frame|seeds|flood|coarse|regions|segmenter|params|tracking|semantics|io|pcl_interface|cli|view|baselines|synth|eval|floodplane/io)/' . | sed 's|^\./||' || true)
if [ ${#problems[@]} -gt 0 ]; then
  echo "check_includes: these includes run back up the library's layers (see the top of $0):" >&2
  printf '  %s\n' "${problems[@]}" >&2
  exit 1
fi
echo "check_includes: every include of src/, include/, io/ and toolkit/ points down"
