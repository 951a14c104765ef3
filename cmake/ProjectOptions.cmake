# Warning and sanitizer settings as INTERFACE targets (cmake_template style).
add_library(orni_warnings INTERFACE)
add_library(orni::warnings ALIAS orni_warnings)
target_compile_options(orni_warnings INTERFACE
  -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor -Wold-style-cast -Wcast-align
  -Wunused -Woverloaded-virtual -Wnull-dereference -Wdouble-promotion -Wimplicit-fallthrough)
if(ORNI_WARNINGS_AS_ERRORS)
  target_compile_options(orni_warnings INTERFACE -Werror)
endif()

add_library(orni_sanitizers INTERFACE)
add_library(orni::sanitizers ALIAS orni_sanitizers)
if(ORNI_SANITIZE)
  target_compile_options(orni_sanitizers INTERFACE
    -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all)
  target_link_options(orni_sanitizers INTERFACE -fsanitize=address,undefined)
endif()

# Helper: apply project options to a target of ours.
function(orni_target_defaults target)
  target_link_libraries(${target} PRIVATE orni::warnings orni::sanitizers)
endfunction()
