#!/usr/bin/env bash
# Fuzzes the VEM recording reader (tests/fuzz/recording_reader_fuzz.cpp) for a bounded time:
# configures a separate clang build with VEM_BUILD_FUZZERS=ON, builds only the fuzzer, seeds a
# corpus with a few small valid recordings (the fuzzer's --write-seeds mode) and runs libFuzzer
# with ASan + UBSan. Fails on any crash, leak, undefined behaviour, timeout or memory blow-up;
# the reproducer is left in build-fuzz/fuzz-artifacts/.
#   VEM_FUZZ_SECONDS (default 60): how long to fuzz.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${VEM_FUZZ_SECONDS:-60}"
build=build-fuzz

cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
      -DVEM_BUILD_FUZZERS=ON -DVEM_BUILD_BENCHMARKS=OFF
cmake --build "$build" --target recording_reader_fuzz

fuzzer="$build/tests/fuzz/recording_reader_fuzz"
corpus="$build/fuzz-corpus/recording_reader"
mkdir -p "$corpus" "$build/fuzz-artifacts"
"$fuzzer" --write-seeds="$corpus"
"$fuzzer" -max_total_time="$seconds" -rss_limit_mb=2048 -malloc_limit_mb=512 -timeout=10 \
          -max_len=65536 -print_final_stats=1 -artifact_prefix="$build/fuzz-artifacts/" "$corpus"
