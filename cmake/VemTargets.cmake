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
