#!/usr/bin/env bash
# Uses the workbench as a package, the way a lab's own software would (docs/library.md):
#   1. installs the build ($RDSF_BUILD_DIR, default build/) into a temporary prefix;
#   2. the installed programs find the installed default model and recipes from any working folder;
#   3. configures and builds examples/detect-people against the prefix (find_package(rdsf)), runs it on a
#      few frames rendered by the installed rdsf-synth and checks that it prints detections;
#   4. compiles a one-file program with pkg-config's flags for rdsf.pc and checks rdsf::version();
#   5. configures a parent project that includes the tree with add_subdirectory (nothing may leak into it).
# With --deb (as root, or through sudo): instead builds the .deb with cpack, installs it with dpkg, runs 2-4
# against /usr, removes it (dpkg -r), checks that nothing of it is left, and purges it from dpkg's list.
# Prints one line per step; exits non-zero at the first failure.
set -euo pipefail
cd "$(dirname "$0")/.."
source_dir=$PWD
build_dir=$(cd "${RDSF_BUILD_DIR:-build}" && pwd)
deb=0
case "${1:-}" in
  --deb) deb=1 ;;
  "") ;;
  *) echo "check-install: unknown argument '$1' (use --deb or nothing)" >&2; exit 2 ;;
esac
fail() { echo "check-install: $*" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
version=$(sed -n 's/^project(rdsf VERSION \([0-9.]*\).*/\1/p' CMakeLists.txt)
[ -n "$version" ] || fail "no project version in CMakeLists.txt"

if ((deb)); then
  sudo=""
  if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
  if dpkg-query -W -f='${Status}' rdsf 2>/dev/null | grep -q "ok installed"; then
    fail "a package rdsf is installed already: remove it first (dpkg -r rdsf)"
  fi
  (cd "$work" && cpack -G DEB --config "$build_dir/CPackConfig.cmake" >"$work/cpack.log" 2>&1) ||
    { tail -20 "$work/cpack.log" >&2; fail "cpack -G DEB failed"; }
  package=$(ls "$work"/rdsf_*.deb) || fail "cpack made no rdsf_*.deb"
  echo "check-install: built $(basename "$package") ($(du -k "$package" | cut -f1) kB)"
  $sudo dpkg -i "$package" >/dev/null || fail "dpkg -i $package failed"
  dpkg-query -L rdsf | sort >"$work/files.txt"
  prefix=/usr
else
  prefix=$work/prefix
  cmake --install "$build_dir" --prefix "$prefix" >/dev/null || fail "cmake --install failed"
  echo "check-install: installed into a temporary prefix ($(find "$prefix" -type f | wc -l) files)"
fi

# 2. Every program of a lab's workflow is installed and runs (rdsf-adapt runs the others from its own folder),
# then the shipped model and recipes, from a working folder without models/.
for program in rdsf-detect rdsf-background rdsf-synth rdsf-mine rdsf-samples rdsf-label rdsf-review rdsf-train rdsf-adapt; do
  [ -x "$prefix/bin/$program" ] || fail "$program is not installed in $prefix/bin"
  "$prefix/bin/$program" --version 2>&1 | grep -qF "$program $version" || fail "installed $program --version does not say $version"
done
echo "check-install: the workflow's programs are installed (rdsf-detect ... rdsf-adapt)"

models="$prefix/share/rdsf/models"
[ -f "$models/people/v4.yml" ] && [ -f "$models/recipes/tree.yml" ] || fail "no default model or recipes under $models"
inspect=$(cd "$work" && "$prefix/bin/rdsf-train" --inspect people --top 1) || fail "installed rdsf-train --inspect people failed"
grep -qF "($models/people/v4.yml)" <<<"$inspect" || fail "installed rdsf-train did not resolve 'people' to $models/people/v4.yml: $(head -1 <<<"$inspect")"
echo "check-install: installed programs resolve the default model to $models/people/v4.yml"

# 3. The example, built against the package.
cmake -S "$source_dir/examples/detect-people" -B "$work/example" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$prefix" ${CMAKE_CXX_COMPILER_LAUNCHER:+-DCMAKE_CXX_COMPILER_LAUNCHER=$CMAKE_CXX_COMPILER_LAUNCHER} \
  >"$work/example.log" 2>&1 || { cat "$work/example.log" >&2; fail "the example does not configure against $prefix"; }
cmake --build "$work/example" >>"$work/example.log" 2>&1 || { tail -30 "$work/example.log" >&2; fail "the example does not build"; }
"$prefix/bin/rdsf-synth" --out "$work/frames" --frames 4 --people 2..2 --seed 7 --rgb >/dev/null 2>&1 ||
  fail "installed rdsf-synth failed"
"$work/example/detect-people" "$work/frames" "$models/people/v4.yml" >"$work/detections.txt" ||
  fail "the example failed on 4 synthetic frames"
head -1 "$work/detections.txt" | grep -qF "# rdsf $version," || fail "the example reports another version: $(head -1 "$work/detections.txt")"
n='-?[0-9]+\.[0-9]{2}'
detections=$(grep -cE "^[0-9]+ [1-9][0-9]* -?[0-9]+ -?[0-9]+ [0-9]+ [0-9]+ [01]\.[0-9]{3} $n $n $n\$" "$work/detections.txt" || true)
[ "$detections" -ge 1 ] || { cat "$work/detections.txt" >&2; fail "the example printed no detection lines on frames with 2 people each"; }
echo "check-install: examples/detect-people built against the package: $detections detections in 4 frames"

# 4. pkg-config.
pc=$(find "$prefix" -path '*/pkgconfig/rdsf.pc' | head -1)
[ -n "$pc" ] || fail "no rdsf.pc under $prefix"
cat >"$work/version.cpp" <<'CPP'
#include <cstdio>
#include "rdsf/version.hpp"
int main() { std::printf("%s %s\n", rdsf::version().c_str(), RDSF_VERSION_STRING); }
CPP
libdir=$(PKG_CONFIG_PATH=$(dirname "$pc") pkg-config --variable=libdir rdsf)
# shellcheck disable=SC2046
g++ -std=c++17 "$work/version.cpp" -o "$work/version" $(PKG_CONFIG_PATH=$(dirname "$pc") pkg-config --cflags --libs rdsf) \
  -Wl,-rpath,"$libdir" || fail "a program does not compile and link with pkg-config's flags for rdsf"
[ "$("$work/version")" = "$version $version" ] || fail "rdsf::version() says '$("$work/version")', expected $version"
echo "check-install: pkg-config rdsf: compiled and linked, rdsf::version() = $version"

# 5. As a subproject: configure a parent project that add_subdirectory()s the tree (programs off; building
#    the library again would take minutes) and check that nothing leaks into the parent; the tree uses
#    PROJECT_*/CMAKE_CURRENT_* paths (the top build folder only where shipped_data.cpp needs it).
leaks=$(grep -rn --include=CMakeLists.txt --include='*.cmake' -E 'CMAKE_(SOURCE|BINARY)_DIR' \
  CMakeLists.txt cmake src cli gui detector synth miner labeler review trainer recorder openni_driver tests bench fuzz |
  grep -v 'RDSF_BUILD_TREE=' || true)
[ -z "$leaks" ] || fail "CMAKE_SOURCE_DIR/CMAKE_BINARY_DIR break add_subdirectory; use PROJECT_*: $leaks"
mkdir -p "$work/parent"
cat >"$work/parent/CMakeLists.txt" <<CMAKE
cmake_minimum_required(VERSION 3.25)
project(parent LANGUAGES CXX)
add_subdirectory("$source_dir" rdsf)
add_executable(parent main.cpp)
target_link_libraries(parent PRIVATE rdsf::rdsf)
get_directory_property(parent_options COMPILE_OPTIONS)
file(WRITE \${CMAKE_BINARY_DIR}/leaks.txt "options=\${parent_options};flags=\${CMAKE_CXX_FLAGS};type=\${CMAKE_BUILD_TYPE};tests=\${RDSF_BUILD_TESTS};bench=\${RDSF_BUILD_BENCH}")
CMAKE
echo 'int main() {}' >"$work/parent/main.cpp"
cmake -S "$work/parent" -B "$work/parent/build" -DRDSF_BUILD_PROGRAMS=OFF >"$work/parent.log" 2>&1 ||
  { tail -20 "$work/parent.log" >&2; fail "a parent project cannot add_subdirectory() the tree"; }
[ "$(cat "$work/parent/build/leaks.txt")" = "options=;flags=;type=;tests=OFF;bench=OFF" ] ||
  fail "add_subdirectory() changed the parent project: $(cat "$work/parent/build/leaks.txt")"
echo "check-install: as a subproject: configures, no flags or build type forced on the parent, no tests or benchmarks"

if ((deb)); then
  $sudo dpkg -r rdsf >/dev/null || fail "dpkg -r rdsf failed"
  left=$(while read -r f; do if [ -e "$f" ] && [ ! -d "$f" ]; then echo "$f"; fi; done <"$work/files.txt")
  [ -z "$left" ] || fail "files left after dpkg -r rdsf: $left"
  dirs=$(while read -r f; do if [ -d "$f" ] && [[ "$f" == */rdsf* ]]; then echo "$f"; fi; done <"$work/files.txt")
  [ -z "$dirs" ] || fail "folders left after dpkg -r rdsf: $dirs"
  echo "check-install: dpkg -r rdsf removed all $(wc -l <"$work/files.txt") paths of the package"
  # dpkg keeps a removed package that has a maintainer script (ldconfig in postrm) as "rc" until purged.
  $sudo dpkg -P rdsf >/dev/null || fail "dpkg -P rdsf failed"
  if dpkg-query -W rdsf >/dev/null 2>&1; then fail "dpkg still lists rdsf after dpkg -P"; fi
  echo "check-install: dpkg -P rdsf: dpkg no longer knows the package"
fi
