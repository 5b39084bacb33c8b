#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
# Checks that every C++ file of the project is formatted as the project's .clang-format says
# (Debian 12's clang-format 14, from scripts/install_deps.sh). Lists the files that are not and
# fails; `scripts/check_format.sh --fix` formats them in place instead.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
mapfile -t files < <(git ls-files -- include src codegen toolkit apps python bench test examples ros | grep -E '\.(h|hpp|cpp|cc)$')
if [ "${1:-}" = "--fix" ]; then
  clang-format -i "${files[@]}"
  exit 0
fi
log=$(mktemp)
trap 'rm -f "$log"' EXIT
if ! clang-format --dry-run --Werror "${files[@]}" 2> "$log"; then
  echo "check_format: these files differ from .clang-format (scripts/check_format.sh --fix formats them):" >&2
  grep -oE '^[^:]+\.(h|hpp|cpp|cc):' "$log" | sort -u | sed 's/:$//; s/^/  /' >&2
  exit 1
fi
echo "check_format: ${#files[@]} files formatted as .clang-format says"
