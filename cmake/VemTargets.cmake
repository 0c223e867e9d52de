# Helpers that give every vemcast target the same compile options.
# Our own targets build warning-free under -Wall -Wextra -Werror; third-party headers are SYSTEM.

function(vem_target_options target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Werror -Wshadow
                                           -Wnon-virtual-dtor -Wold-style-cast -Wcast-align
                                           -Wdouble-promotion -Wformat=2)
  # GCC's -Wmaybe-uninitialized misfires inside the standard library (<regex>'s std::function)
  # when the sanitizers instrument the code at -O1; GCC's manual warns it depends on the
  # optimisation. A warning there, not an error: the Release build keeps it an error.
  if(VEM_SANITIZE OR VEM_TSAN)
    target_compile_options(${target} PRIVATE -Wno-error=maybe-uninitialized)
  endif()
endfunction()

# vem_sanitize(target): ASan+UBSan for the targets a sanitizer build instruments (VEM_SANITIZE=ON).
option(VEM_SANITIZE "Build tests and the core with AddressSanitizer and UndefinedBehaviorSanitizer" OFF)
if(VEM_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all)
  add_link_options(-fsanitize=address,undefined)
endif()

# VEM_TSAN: ThreadSanitizer for every target configured after this point (vemd's capture and
# processing threads; CI builds only vemd_tests and vemd with it). Cannot be combined with
# VEM_SANITIZE (ASan and TSan exclude each other).
option(VEM_TSAN "Build with ThreadSanitizer (for vemd_tests)" OFF)
if(VEM_TSAN)
  if(VEM_SANITIZE)
    message(FATAL_ERROR "VEM_TSAN and VEM_SANITIZE cannot be combined: use two build folders")
  endif()
  add_compile_options(-fsanitize=thread -fno-omit-frame-pointer)
  add_link_options(-fsanitize=thread)
endif()

# vem_per_frame_code(target): the per-pixel work vemd does every frame (the lighting core, the
# calibration's remap, the synthetic camera, the pipeline, the sinks and the recorder, the stream's
# cube maps and texel packing) stays at -O1 in the sanitizer
# builds, which .ci/run compiles at -O0 for speed: the end-to-end tests there check that clients
# do not slow vemd below its rate, and at -O0 this code alone would. Still instrumented.
function(vem_per_frame_code target)
  if(VEM_SANITIZE OR VEM_TSAN)
    target_compile_options(${target} PRIVATE -O1)
  endif()
endfunction()

# vem_beast_units(file...): the units whose code is mostly Boost.Beast's and Asio's templates (the
# stream server, the stream client and the tests' WebSocket peers). In the ASan+UBSan build they
# leave out UBSan's null, alignment and vptr checks, which instrument every member access inside
# those templates and made up about a third of their compile time (stream_server.cpp at -O0:
# 165 s, 117 s without them). AddressSanitizer still checks every access there, a null one
# included, and UBSan's arithmetic checks stay; the units that parse what clients send (the wire
# decoder, the message handler, the handshake rules) keep every check.
function(vem_beast_units)
  if(VEM_SANITIZE)
    set_source_files_properties(${ARGN} PROPERTIES COMPILE_OPTIONS "-fno-sanitize=null,alignment,vptr")
  endif()
endfunction()

# Build time (issue 18: a cold CI under 45 minutes on 2 cores). Two measured levers, no effect on
# what the code does:
# - vem_unity_build(target batch): the target's sources compiled `batch` at a time in one
#   translation unit each. For the tools, whose every subcommand file includes CLI11 2.1: that
#   header alone costs about 15 s of compiling per file (it defines its validators as objects in
#   every file that includes it), so ten subcommands in two units instead of ten save most of it.
# - vem_test_precompiled_headers(folder): every test executable defined in `folder` and below
#   (those linking GoogleTest) compiles GoogleTest, GoogleMock and the common standard headers once
#   per executable instead of once per test file. ccache keeps working on such units when the
#   sloppiness .ci/run sets (pch_defines,time_macros,include_file_mtime,include_file_ctime).
function(vem_unity_build target batch)
  set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE ${batch})
endfunction()

function(vem_test_precompiled_headers folder)
  get_property(targets DIRECTORY ${folder} PROPERTY BUILDSYSTEM_TARGETS)
  foreach(target IN LISTS targets)
    get_target_property(type ${target} TYPE)
    get_target_property(links ${target} LINK_LIBRARIES)
    if(NOT type STREQUAL "EXECUTABLE" OR NOT links)
      continue()
    endif()
    if(NOT "GTest::gtest" IN_LIST links)
      continue()
    endif()
    set(headers <gtest/gtest.h>)
    if("GTest::gmock" IN_LIST links)
      list(APPEND headers <gmock/gmock.h>)
    endif()
    target_precompile_headers(${target} PRIVATE ${headers} <algorithm> <chrono> <cmath> <cstdint>
                              <filesystem> <fstream> <functional> <map> <memory> <optional>
                              <random> <sstream> <string> <string_view> <thread> <vector>)
  endforeach()
  get_property(subfolders DIRECTORY ${folder} PROPERTY SUBDIRECTORIES)
  foreach(subfolder IN LISTS subfolders)
    vem_test_precompiled_headers(${subfolder})
  endforeach()
endfunction()
