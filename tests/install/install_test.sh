#!/usr/bin/env bash
# install_test.sh BUILD_DIR WORK_DIR: installs the build into WORK_DIR/prefix with `cmake --install`,
# then configures, builds and runs the consumer application (tests/install/consumer/) against
# that tree only (find_package(rpt) from the prefix, no source tree on its include path).
set -euo pipefail
build=$1
work=$2
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work"
cmake --install "$build" --prefix "$work/prefix" >/dev/null
cmake -S "$here/consumer" -B "$work/consumer" -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$work/prefix" >/dev/null
cmake --build "$work/consumer" -j2 >/dev/null
"$work/consumer/rpt_consumer"
# An unknown component fails naming the known ones (it failed without a reason).
mkdir -p "$work/unknown"
cat > "$work/unknown/CMakeLists.txt" <<'EOF2'
cmake_minimum_required(VERSION 3.20)
project(rpt_unknown_component LANGUAGES CXX)
find_package(rpt 0.1 REQUIRED COMPONENTS core nosuch)
EOF2
if cmake -S "$work/unknown" -B "$work/unknown/build" -DCMAKE_PREFIX_PATH="$work/prefix" > "$work/unknown.log" 2>&1; then
  echo "find_package(rpt COMPONENTS nosuch) succeeded" >&2
  exit 1
fi
# (CMake wraps the message: its words are checked one line at a time.)
grep -q "rpt has no component 'nosuch' (its components: core, io, datasets," "$work/unknown.log" &&
  grep -q "simulation, metrics, engine)" "$work/unknown.log" || {
  cat "$work/unknown.log" >&2
  exit 1
}
