#!/usr/bin/env bash
# The library, the CLI and the unit tests built with clang++ under
# AddressSanitizer and UndefinedBehaviorSanitizer (-O1, LUTBAKE_SANITIZE=ON)
# in build-asan/, then the part of the suite that is neither compiler-,
# install- nor timing-bound run under them; any report fails the run. Then
# the same commit's two builds compared byte for byte: build/ (g++, Release)
# and build-asan/ (clang++) bake every table, format, shader language and
# several presets (scripts/compare_compilers.sh). scripts/test.sh calls this
# after the main suite; docs/reliability.md has the subset and its time.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build-asan -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" -DLUTBAKE_SANITIZE=ON -DLUTBAKE_REQUIRE_TEST_PACKAGES=ON >/dev/null
cmake --build build-asan -j"$(nproc)" --target lutbake_tests lutbake_image_tests lutbake
# The subset (the sanitizer build compiles only its test files, CMakeLists
# LUTBAKE_SANITIZED_TEST_SOURCES): the readers and writers with the hostile
# inputs and every fuzz corpus replayed (the scene, manifest, table,
# source-embedding, preset.json and option parsers), the plans, the models,
# the furnace and the reference integrator, the lookups and the atomic
# output. Left out: everything that runs the lutbake binary (the CLI, eval,
# bad-input, determinism, kill and signal tests: minutes of process starts,
# each over a second under ASan), the consumer builds and the layer check
# (compiler- and install-bound), the regeneration of luts/, and the table
# and quadrature suites (seconds each at -O1 with ASan). The binary itself
# runs under the sanitizers in the comparison below.
SUBSET='^(FuzzCorpus|HostileInput|TableReader|Lookup|BinaryWriter|ExrWriter|PngTable|Ktx2Table|DdsTable|ThreeDTable|AtomicOutput|OutputSet|SceneReader|Manifest|Plan|Storage|Sobol|PointBlocks|GaussLegendre|Fresnel|Ndf|SheenModel|DielectricModel|OrenNayar|Eon|Phong|BlinnPhong|Furnace|ReferenceIntegrator|VndfKernel|ChiSquare)\.'
export ASAN_OPTIONS=halt_on_error=1:detect_leaks=1
export UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1
ctest --test-dir build-asan -j"$(nproc)" --output-on-failure -R "$SUBSET" "$@"
GXX_TREE=build CLANG_TREE=build-asan bash scripts/compare_compilers.sh "$(nproc)"
