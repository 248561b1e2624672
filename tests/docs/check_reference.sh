#!/usr/bin/env bash
# The generated reference pages equal what the code prints today:
#   docs/reference/world-keys.md == `swarmagg keys --markdown` (the key table)
#   docs/reference/cli.md        == `swarmagg help --markdown` (every command's --help)
# Usage: check_reference.sh SWARMAGG SOURCE_DIR. On a difference it shows the diff and the
# one-line command that regenerates the page.
set -euo pipefail
swarmagg=$1
source_dir=$2
status=0
check() {
  local page=$1
  shift
  local generated
  generated=$(mktemp)
  "$swarmagg" "$@" >"$generated"
  if ! diff -u "$source_dir/$page" "$generated"; then
    echo "$page differs from 'swarmagg $*'; regenerate it with:" >&2
    echo "  build/swarmagg $* > $page" >&2
    status=1
  fi
  rm -f "$generated"
}
check docs/reference/world-keys.md keys --markdown
check docs/reference/cli.md help --markdown
exit $status
