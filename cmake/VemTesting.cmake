# How ctest runs the test executables (included by tests/CMakeLists.txt).
include(GoogleTest)

# Test executables left out of this build's `all`: .ci/run builds and runs those only in its
# sanitizer build, so that no test target compiles twice. ctest lists a test executable that is
# not built as <name>_NOT_BUILT; a test that runs one through a script is disabled here by
# vem_test_needs(test target).
set(VEM_TESTS_NOT_IN_ALL "" CACHE STRING
    "Test executables left out of `all` (.ci/run builds them in its sanitizer build instead)")
function(vem_test_needs test target)
  if(target IN_LIST VEM_TESTS_NOT_IN_ALL)
    set_tests_properties(${test} PROPERTIES DISABLED TRUE)
  endif()
endfunction()

# VEM_TEST_SHARDS: 0 (the default) makes each GoogleTest test its own ctest test, run in its own
# process (gtest_discover_tests), which names the failing test and isolates each one. N > 0 runs
# each test executable as N ctest tests instead, <name>_shard_<i>_of_<N>, each one GoogleTest
# shard (GTEST_TOTAL_SHARDS, GTEST_SHARD_INDEX) of the executable's tests in one process. .ci/run's
# sanitizer build uses it: an instrumented executable takes about 0.3 s to start (the dynamic
# loader and ASan's start-up, with OpenCV's image codecs' libraries), which over 931 tests was
# half of that stage's time. A GTEST_SKIP inside a shard shows in its output, not in ctest's
# summary.
set(VEM_TEST_SHARDS 0 CACHE STRING
    "0: one ctest test per GoogleTest test; N: each test executable as N GoogleTest shards")

# vem_gtest(target LABELS l... [TIMEOUT seconds]): the target's GoogleTest tests for ctest, with
# the labels, and the timeout of one test (of one shard: 900 s).
function(vem_gtest target)
  cmake_parse_arguments(ARG "" "TIMEOUT" "LABELS" ${ARGN})
  if(VEM_TEST_SHARDS GREATER 0)
    set(script "${CMAKE_CURRENT_BINARY_DIR}/${target}_shards.cmake")
    set(content "if(EXISTS [==[$<TARGET_FILE:${target}>]==])\n")
    math(EXPR last "${VEM_TEST_SHARDS} - 1")
    foreach(index RANGE ${last})
      set(name "${target}_shard_${index}_of_${VEM_TEST_SHARDS}")
      string(APPEND content
             "  add_test([==[${name}]==] [==[$<TARGET_FILE:${target}>]==])\n"
             "  set_tests_properties([==[${name}]==] PROPERTIES LABELS [==[${ARG_LABELS}]==]"
             " TIMEOUT 900 WORKING_DIRECTORY [==[${CMAKE_CURRENT_BINARY_DIR}]==]"
             " ENVIRONMENT [==[GTEST_TOTAL_SHARDS=${VEM_TEST_SHARDS};"
             "GTEST_SHARD_INDEX=${index}]==])\n")
    endforeach()
    string(APPEND content "else()\n  add_test([==[${target}_NOT_BUILT]==] [==[${target}_NOT_BUILT]==])\nendif()\n")
    file(GENERATE OUTPUT "${script}" CONTENT "${content}")
    set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES "${script}")
  else()
    if(ARG_TIMEOUT)
      gtest_discover_tests(${target} DISCOVERY_TIMEOUT 60
                           PROPERTIES LABELS "${ARG_LABELS}" TIMEOUT ${ARG_TIMEOUT})
    else()
      gtest_discover_tests(${target} DISCOVERY_TIMEOUT 60 PROPERTIES LABELS "${ARG_LABELS}")
    endif()
  endif()
endfunction()
