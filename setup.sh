#!/usr/bin/env bash
# rosarch set-up: installs what is missing (Debian 12), fetches the tree-sitter grammars,
# builds, and then either opens the GUI on the bundled example workspace or runs the tests.
#
#   ./setup.sh gui     build and open the GUI on resources/example_ws
#   ./setup.sh test    format check, a warnings-as-errors build with AddressSanitizer +
#                      UBSan in build-asan, the whole test suite under it, clang-tidy over
#                      what changed since .ci/tidy-base (ROSARCH_TIDY_ALL=1: every file),
#                      then every libFuzzer target for a fixed number of runs in build-fuzz
#                      (what CI runs)
#   ./setup.sh build   only build
#   ./setup.sh package build what is installed and the Debian package build/rosarch_*.deb
#                      (docs/install.md)
set -euo pipefail
cd "$(dirname "$0")"
mode=${1:-gui}
build_dir=${ROSARCH_BUILD_DIR:-build}

packages=(build-essential cmake ninja-build pkg-config ca-certificates curl
  qt6-base-dev qt6-base-dev-tools qt6-svg-dev qt6-tools-dev qt6-tools-dev-tools qt6-l10n-tools
  libqt6svg6 qt6-qpa-plugins libgl-dev libqscintilla2-qt6-dev libgraphviz-dev graphviz
  nlohmann-json3-dev libcurl4-openssl-dev libssl-dev libtree-sitter-dev libyaml-cpp-dev xvfb xauth
  fonts-dejavu-core
  ccache clang-format clang-tidy default-jre-headless nodejs git clang-16 libclang-rt-16-dev
  chromium # the architecture site's browser test (tests/support/site)
  python3-jsonschema python3-yaml) # the NoDL validator of the tests (tests/support/validate-nodl.py)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  sudo_cmd=""; [ "$(id -u)" -ne 0 ] && sudo_cmd="sudo"
  $sudo_cmd apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# npm comes with nodesource's nodejs; Debian packages it apart.
if ! command -v npm >/dev/null 2>&1; then
  sudo_cmd=""; [ "$(id -u)" -ne 0 ] && sudo_cmd="sudo"
  DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq --no-install-recommends npm
fi

scripts/fetch-grammars.sh "$build_dir/_grammars"
scripts/fetch-plantuml.sh "$build_dir/_plantuml" # the real consumer of our PlantUML, for the tests
scripts/fetch-sarif-schema.sh "$build_dir/_sarif" # SARIF 2.1.0 schema + validator, for the tests
scripts/fetch-mermaid.sh "$build_dir/_mermaid" # Mermaid's parser, for the tests
scripts/fetch-site-tools.sh "$build_dir/_sitetools" # puppeteer-core, vnu-jar, axe-core, for the tests

echo "setup: packages and test tools took ${SECONDS} s"

# step <name> <command...>: runs the command and says how long it took (CI's time per stage)
step() {
  local name=$1 start=$SECONDS
  shift
  "$@"
  echo "setup: $name took $((SECONDS - start)) s"
}

jobs=$(nproc 2>/dev/null || echo 2)
grammars="$PWD/$build_dir/_grammars"

# configure <dir> <cmake options...>
configure() {
  local dir=$1; shift
  cmake -S . -B "$dir" -G Ninja -DROSARCH_GRAMMAR_DIR="$grammars" \
    -DROSARCH_PLANTUML_JAR="$PWD/$build_dir/_plantuml/plantuml.jar" \
    -DROSARCH_SARIF_DIR="$PWD/$build_dir/_sarif" -DROSARCH_MERMAID_DIR="$PWD/$build_dir/_mermaid" \
    -DROSARCH_SITE_TOOLS_DIR="$PWD/$build_dir/_sitetools" "$@"
}

# configure_and_build <dir> <cmake options...>
configure_and_build() {
  configure "$@"
  cmake --build "$1" -j "$jobs"
}

case "$mode" in
  gui)
    configure_and_build "$build_dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo
    if [ -z "${DISPLAY:-}" ] && [ -z "${WAYLAND_DISPLAY:-}" ]; then
      echo "setup: no display found; starting the GUI under Xvfb (export DISPLAY to use your own)"
      exec xvfb-run -a -s "-screen 0 1600x1000x24" "$build_dir/bin/rosarch" resources/example_ws
    fi
    exec "$build_dir/bin/rosarch" resources/example_ws ;;
  test)
    # What CI runs: the format check, one warnings-as-errors build with AddressSanitizer and
    # UBSan, the whole suite under it and the clang-tidy checks. (A second, plain build of the
    # same suite took CI a third of its time and found nothing the sanitized one did not;
    # ROSARCH_SKIP_SANITIZERS=1 builds and tests the plain RelWithDebInfo tree instead.)
    export QT_QPA_PLATFORM=offscreen
    step "format check" scripts/check-format.sh
    if [ "${ROSARCH_SKIP_SANITIZERS:-0}" != 1 ]; then
      test_dir=${ROSARCH_ASAN_BUILD_DIR:-build-asan}
      step "sanitizer build" configure_and_build "$test_dir" -DCMAKE_BUILD_TYPE=Debug \
        -DCMAKE_CXX_FLAGS_DEBUG="-g -O1" -DROSARCH_WERROR=ON -DROSARCH_SANITIZE=address,undefined
    else
      test_dir=$build_dir
      step "build" configure_and_build "$test_dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
        -DROSARCH_WERROR=ON
    fi
    ASAN_OPTIONS=detect_leaks=0:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1 \
      step "test suite" ctest --test-dir "$test_dir" --output-on-failure -j "$jobs"
    # Only the files a change since the last full green run (.ci/tidy-base) can reach: the
    # full run took CI as long as the tests, and a file whose source, headers and build
    # settings did not change since a full run passed gives the same result. A change to the
    # build settings or to .clang-tidy checks everything; so does ROSARCH_TIDY_ALL=1.
    step "clang-tidy" scripts/check-tidy.sh "$test_dir"
    if [ "${ROSARCH_SKIP_FUZZ:-0}" != 1 ]; then
      # Every libFuzzer target (clang-16, ASan + UBSan) over its seed corpus, a fixed number
      # of runs each.
      # Only the fuzz targets (one per corpus folder) and what they link: the GUI and the
      # tests were built and run twice already, and building them a third time took CI a
      # quarter of its time.
      fuzz_dir=${ROSARCH_FUZZ_BUILD_DIR:-build-fuzz}
      mapfile -t fuzz_targets < <(ls tests/fuzz/corpus)
      fuzz_build() {
        configure "$fuzz_dir" -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-g -O1" \
          -DCMAKE_C_COMPILER=clang-16 -DCMAKE_CXX_COMPILER=clang++-16 -DROSARCH_FUZZ=ON \
          -DROSARCH_SANITIZE=address,undefined,fuzzer-no-link
        cmake --build "$fuzz_dir" -j "$jobs" --target "${fuzz_targets[@]}"
      }
      step "fuzz build" fuzz_build
      step "fuzz runs" scripts/run-fuzzers.sh "$fuzz_dir" runs=2000
    fi
    echo "setup: the whole test run took ${SECONDS} s" ;;
  build)
    configure_and_build "$build_dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo ;;
  package)
    configure "$build_dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo
    cmake --build "$build_dir" -j "$jobs" --target rosarch-installable
    (cd "$build_dir" && cpack -G DEB) ;;
  *) echo "usage: $0 [gui|test|build|package]" >&2; exit 2 ;;
esac
