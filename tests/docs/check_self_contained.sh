#!/usr/bin/env bash
# A clone holds everything its files point at: no file refers to the project's private
# notes (a ../shared folder) or to the specification that lived there; code comments, help
# texts and pages cite docs/ and the papers instead.
# Usage: check_self_contained.sh SOURCE_DIR
set -euo pipefail
cd "$1"
# Outputs and build folders a developer may have inside the clone are not the repository.
found=$(find . \( -path ./.git -o -path './build*' -o -path ./runs -o -path ./renders \
  -o -path ./reproduce -o -path ./results -o -path ./tests/docs/check_self_contained.sh \) -prune \
  -o -type f -print0 | xargs -0 grep -nIE '\.\./shared|shared/(paper|SPEC)|\bSPEC\b' || true)
if [[ -n $found ]]; then
  echo "$found"
  echo "these lines refer to files a clone does not have; cite docs/ or the papers instead" >&2
  exit 1
fi
