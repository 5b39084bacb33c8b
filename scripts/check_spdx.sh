#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
# Checks that every source file of the project (C++, Python, shell, CMake) names its licence in
# an SPDX line near its top, as LICENSE says: BSD-3-Clause. Lists those that do not and fails.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
missing=()
while IFS= read -r file; do
  [ -f "$file" ] || continue
  head -n 5 "$file" | grep -q 'SPDX-License-Identifier: BSD-3-Clause' || missing+=("$file")
done < <(git ls-files | grep -E '(\.(h|hpp|cpp|cc|py|sh|cmake|in|launch|xml|cfg|msg|test|rviz)|CMakeLists\.txt|^\.ci/run)$' |
         grep -vE '(^|/)(package\.xml)$')
if [ ${#missing[@]} -gt 0 ]; then
  echo "check_spdx: these files lack 'SPDX-License-Identifier: BSD-3-Clause' in their first 5 lines:" >&2
  printf '  %s\n' "${missing[@]}" >&2
  exit 1
fi
echo "check_spdx: every source file names its licence (BSD-3-Clause)"
