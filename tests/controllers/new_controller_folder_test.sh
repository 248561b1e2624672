#!/usr/bin/env bash
# Adding a controller is its folder and one registration line, nothing else: no CMake file to
# edit, no cmake to re-run. A copy of the sources is configured first (a user's existing
# build), then controllers/cockroach/ is copied as controllers/antlike/ with its names changed
# and registered; a plain build of the controllers library must compile it. To stay cheap,
# only that library is built in the copy: the swarmagg binary is linked from this build's
# other libraries (its own link command) with the copy's controllers library, and runs a
# world of the new type.
# Usage: new_controller_folder_test.sh SOURCE_DIR BUILD_DIR [COMPILER_LAUNCHER]
set -euo pipefail
source_dir=$1
build_dir=$2
launcher=${3:-}
tmp=$(mktemp -d "${TMPDIR:-/tmp}/swarmagg-new-controller-XXXXXX")
trap 'rm -rf "$tmp"' EXIT

mkdir -p "$tmp/src"
for part in CMakeLists.txt cmake src controllers bench tests worlds; do
  cp -r "$source_dir/$part" "$tmp/src/"
done
launch=()
if [ -n "$launcher" ]; then launch=(-DCMAKE_CXX_COMPILER_LAUNCHER="$launcher"); fi
cmake -S "$tmp/src" -B "$tmp/build" -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=OFF "${launch[@]}" \
  >"$tmp/configure.log" 2>&1 || { cat "$tmp/configure.log"; exit 1; }

# The new controller: a renamed copy and its registration line.
cp -r "$tmp/src/controllers/cockroach" "$tmp/src/controllers/antlike"
for file in "$tmp/src/controllers/antlike"/*; do
  sed -i 's/cockroach/antlike/g; s/Cockroach/Antlike/g' "$file"
  mv "$file" "$(dirname "$file")/$(basename "$file" | sed 's/cockroach/antlike/')"
done
sed -i 's|  X(cockroach)                  \\|  X(cockroach)                  \\\n  X(antlike)                    \\|' \
  "$tmp/src/controllers/controller_registry.cpp"
grep -q 'X(antlike)' "$tmp/src/controllers/controller_registry.cpp" ||
  { echo "could not add the registration line"; exit 1; }

cmake --build "$tmp/build" --target swarmagg_controllers >"$tmp/build.log" 2>&1 ||
  { cat "$tmp/build.log"; exit 1; }
# By the symbol, not the object's name: a unity build compiles the folder as one batch. Not
# grep -q, which stops reading at the first match: nm then dies of SIGPIPE, and pipefail
# fails the test.
nm -C --defined-only "$tmp/build/src/libswarmagg_controllers.a" |
  grep 'antlike_registration()' >/dev/null ||
  { echo "the build did not compile controllers/antlike/"; cat "$tmp/build.log"; exit 1; }

# This build's link command for swarmagg, with the copy's controllers library.
link=$(sed "s|libswarmagg_controllers.a|$tmp/build/src/libswarmagg_controllers.a|g; s|-o ../swarmagg|-o $tmp/swarmagg|" \
  "$build_dir/src/CMakeFiles/swarmagg.dir/link.txt")
(cd "$build_dir/src" && eval "$link")

cd "$source_dir"
"$tmp/swarmagg" validate worlds/examples/cockroach.yaml --set controller.type=antlike |
  grep 'type: antlike' >/dev/null
"$tmp/swarmagg" run worlds/examples/cockroach.yaml --set controller.type=antlike \
  --set run.duration=20 --replicates 1 --no-plots --no-model --quiet --out "$tmp/run"
grep -q 'type: antlike' "$tmp/run/world.resolved.yaml"
echo "controllers/antlike/ was compiled by a plain build and runs"
