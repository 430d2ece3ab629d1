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
