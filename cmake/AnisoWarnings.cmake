# Warnings as errors for the project's own targets only (never for third-party headers).
# ANISO_WARNINGS_AS_ERRORS=OFF keeps them warnings (the clang fuzzing build: another compiler
# warns of other things, and a harness build should not stop on them).
option(ANISO_WARNINGS_AS_ERRORS "Project warnings are errors" ON)
function(aniso_target_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
    -Wno-sign-conversion)
  if(ANISO_WARNINGS_AS_ERRORS)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()
