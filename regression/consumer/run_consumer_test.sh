#!/usr/bin/env bash
# Installs this build into a scratch prefix, then configures, builds and runs
# docs/example_consumer against it with find_package(Cyclone).
set -euo pipefail
build_dir=$1; source_dir=$2
prefix="$build_dir/consumer-test/install"
rm -rf "$build_dir/consumer-test"
cmake --install "$build_dir" --prefix "$prefix" > /dev/null
cmake -S "$source_dir/docs/example_consumer" -B "$build_dir/consumer-test/build" \
  -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release > /dev/null
cmake --build "$build_dir/consumer-test/build" -j 2 > /dev/null
LD_LIBRARY_PATH="$prefix/lib:${LD_LIBRARY_PATH:-}" "$build_dir/consumer-test/build/consumer"
