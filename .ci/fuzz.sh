#!/usr/bin/env bash
# Fuzzes the input parsers for a bounded time each, with libFuzzer + ASan + UBSan (clang):
#   recording_reader_fuzz  the VEM recording reader (tests/fuzz/recording_reader_fuzz.cpp)
#   client_message_fuzz    vemd's handler of client WebSocket messages (client_message_fuzz.cpp)
#   server_message_fuzz    the stream client's decoder (server_message_fuzz.cpp)
# One separate clang build (VEM_BUILD_FUZZERS=ON) in build-fuzz/; each fuzzer seeds its corpus with
# a few valid inputs (its --write-seeds mode). Fails on any crash, leak, undefined behaviour, broken
# rule (abort), timeout or memory blow-up; the reproducer is left in build-fuzz/fuzz-artifacts/.
#   usage: .ci/fuzz.sh [FUZZER...]        (default: all three)
#   VEM_FUZZ_SECONDS (default 60): how long to fuzz each.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${VEM_FUZZ_SECONDS:-60}"
build=build-fuzz
# The longest input each fuzzer is given: a recording's header and a few frames; a client message
# just over the server's 64 KiB limit; a server message with a small cube map and its levels.
declare -A max_len=([recording_reader_fuzz]=65536 [client_message_fuzz]=70000
                    [server_message_fuzz]=262144)
fuzzers=("$@")
[ ${#fuzzers[@]} -gt 0 ] || fuzzers=(recording_reader_fuzz client_message_fuzz server_message_fuzz)
for fuzzer in "${fuzzers[@]}"; do
  [ -n "${max_len[$fuzzer]:-}" ] || { echo "fuzz.sh: unknown fuzzer '$fuzzer'" >&2; exit 2; }
done

cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
      -DVEM_BUILD_FUZZERS=ON -DVEM_BUILD_BENCHMARKS=OFF
cmake --build "$build" --target "${fuzzers[@]}"

mkdir -p "$build/fuzz-artifacts"
for fuzzer in "${fuzzers[@]}"; do
  binary="$build/tests/fuzz/$fuzzer"
  corpus="$build/fuzz-corpus/${fuzzer%_fuzz}"
  mkdir -p "$corpus"
  "$binary" --write-seeds="$corpus"
  "$binary" -max_total_time="$seconds" -rss_limit_mb=2048 -malloc_limit_mb=512 -timeout=10 \
            -max_len="${max_len[$fuzzer]}" -print_final_stats=1 \
            -artifact_prefix="$build/fuzz-artifacts/" "$corpus"
done
