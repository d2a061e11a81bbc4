# The linker: GNU gold where the compiler driver accepts it (binutils ships it with ld on
# Debian 12). The build links about 150 executables and modules; BFD ld took 1.36 s to link
# test_render_sources here, gold 0.28 s (docs/RELIABILITY.md, "CI's time").
# -DANISO_LINKER=default keeps the compiler's own choice.
set(ANISO_LINKER gold CACHE STRING "Linker passed as -fuse-ld= (\"default\": the compiler's own)")
if(NOT ANISO_LINKER STREQUAL "default")
  include(CheckLinkerFlag)
  check_linker_flag(CXX "-fuse-ld=${ANISO_LINKER}" ANISO_LINKER_WORKS_${ANISO_LINKER})
  if(ANISO_LINKER_WORKS_${ANISO_LINKER})
    add_link_options("-fuse-ld=${ANISO_LINKER}")
  else()
    message(STATUS "aniso: -fuse-ld=${ANISO_LINKER} does not link here; the compiler's own linker is used")
  endif()
endif()
