#!/usr/bin/env bash
# Installs this build into a scratch prefix, then configures and builds examples/
# against it with find_package(Cyclone), as an engineering code would. The examples
# are run by their own ctest entries (each asserts what its results must satisfy).
set -euo pipefail
build_dir=$1; source_dir=$2
work="$build_dir/examples-test"
rm -rf "$work/install"
cmake --install "$build_dir" --prefix "$work/install" > /dev/null
cmake -S "$source_dir/examples" -B "$work/build" -DCMAKE_PREFIX_PATH="$work/install" -DCMAKE_BUILD_TYPE=Release \
  > /dev/null
cmake --build "$work/build" -j 2 > /dev/null
# Each example runs in an empty directory (no reduced model cached by an earlier run).
for d in "$work"/run_*; do rm -rf "$d" && mkdir -p "$d"; done
echo "examples built against $work/install"
