#!/usr/bin/env bash
# Builds matiec's iec2c (the classic open-source IEC 61131-3 compiler, beremiz/matiec) with -O2 into
# target/matiec, as the side-by-side anchor for ladderc's IL benchmark (scripts/matiec-anchor.sh).
#
# Input:  MATIEC_SRC, a clone of https://github.com/beremiz/matiec (never committed here; this script
#         downloads nothing). Tools from the system's packages: flex, bison, autoconf, automake, libtool,
#         g++, make.
# Output: target/matiec/iec2c (and the build tree target/matiec/build); the last line printed is the
#         iec2c path. iec2c needs matiec's lib/ at run time: `iec2c -I "$MATIEC_SRC/lib" file.il`.
# Exit:   0 built, 2 usage error (no MATIEC_SRC, missing tools), other = the build's failure.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
out="$root/target/matiec"

if [[ -z "${MATIEC_SRC:-}" || ! -f "${MATIEC_SRC:-/nonexistent}/configure.ac" ]]; then
    echo "error: set MATIEC_SRC to a clone of https://github.com/beremiz/matiec" >&2
    echo "  e.g. git clone https://github.com/beremiz/matiec /tmp/matiec-src && MATIEC_SRC=/tmp/matiec-src $0" >&2
    exit 2
fi
src="$(cd "$MATIEC_SRC" && pwd)"

missing=()
for tool in flex bison autoconf automake libtoolize g++ make; do
    command -v "$tool" >/dev/null 2>&1 || missing+=("$tool")
done
if ((${#missing[@]})); then
    echo "error: missing tools: ${missing[*]}" >&2
    echo "  on Debian/Ubuntu: apt-get install -y flex bison autoconf automake libtool g++ make" >&2
    exit 2
fi

# Build out of the source tree's way: copy the sources (without .git) into target/matiec/build, so the
# clone stays clean and the build is reproducible from scratch.
build="$out/build"
mkdir -p "$build"
tar -C "$src" --exclude=.git -cf - . | tar -C "$build" -xf -
cd "$build"
echo "building matiec from $src (commit $(git -C "$src" rev-parse --short HEAD 2>/dev/null || echo unknown)) in $build" >&2
autoreconf -i >"$out/autoreconf.log" 2>&1 || { tail -20 "$out/autoreconf.log" >&2; exit 1; }
CFLAGS=-O2 CXXFLAGS=-O2 ./configure >"$out/configure.log" 2>&1 || { tail -20 "$out/configure.log" >&2; exit 1; }
make -j2 >"$out/make.log" 2>&1 || { tail -30 "$out/make.log" >&2; exit 1; }
cp iec2c "$out/iec2c"
echo "matiec lib (pass as -I): $src/lib" >&2
echo "$out/iec2c"
