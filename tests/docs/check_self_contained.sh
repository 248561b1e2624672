#!/usr/bin/env bash
# A clone holds everything its files point at: no file refers to the project's private
# notes (a folder beside the clone) or to the specification that lived there; code comments, help
# texts and pages cite docs/ and the papers instead.
# Usage: check_self_contained.sh SOURCE_DIR
set -euo pipefail
cd "$1"
# Outputs and build folders a developer may have inside the clone are not the repository.
# The pattern is put together from pieces so that this file does not match itself.
notes=share; notes+=d spec=SP; spec+=EC
pattern="\\.\\./$notes|$notes/(paper|$spec)|\\b$spec\\b"
found=$(find . \( -path ./.git -o -path './build*' -o -path ./runs -o -path ./renders \
  -o -path ./reproduce -o -path ./results \) -prune \
  -o -type f -print0 | xargs -0 grep -nIE "$pattern" || true)
if [[ -n $found ]]; then
  echo "$found"
  echo "these lines refer to files a clone does not have; cite docs/ or the papers instead" >&2
  exit 1
fi
