# Helpers that give every vemcast target the same compile options.
# Our own targets build warning-free under -Wall -Wextra -Werror; third-party headers are SYSTEM.

function(vem_target_options target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Werror -Wshadow
                                           -Wnon-virtual-dtor -Wold-style-cast -Wcast-align
                                           -Wdouble-promotion -Wformat=2)
endfunction()

# vem_sanitize(target): ASan+UBSan for the targets a sanitizer build instruments (VEM_SANITIZE=ON).
option(VEM_SANITIZE "Build tests and the core with AddressSanitizer and UndefinedBehaviorSanitizer" OFF)
if(VEM_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all)
  add_link_options(-fsanitize=address,undefined)
endif()
