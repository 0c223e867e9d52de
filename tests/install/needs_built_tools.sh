# Sourced by install_test.sh and package_test.sh: reads their arguments (BUILD_DIR SOURCE_DIR
# WORK_DIR TOOL_FILE...) into build, source and work, and exits 77 (ctest SKIP_RETURN_CODE) when a
# tool is not built: the sanitizer build folder builds only the test targets and some tools.
build=$1
source=$2
work=$3
shift 3
for tool_file in "$@"; do
  if [ ! -x "$tool_file" ]; then
    echo "$tool_file is not built (this test needs the full build: cmake --build $build): skipped"
    exit 77
  fi
done
fail() { echo "FAIL: $*" >&2; exit 1; }
