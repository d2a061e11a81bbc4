# Checks that every project source includes only what its room may (docs/ARCHITECTURE.md,
# "Rooms"), by the repository-rooted path, and that no room reaches a layer above it or a
# library it must not know (core: no VTK, Qt or GL; the VTK layer: no Qt; meshes: no GL or
# shaders; scene and widgets: no VTK or shaders). Run as `cmake -DROOT=<repo> -P CheckLayers.cmake`
# (ctest's test_layers); prints each violation with its file and line and fails if any.

# "room  rooms it may include (comma-separated)  system headers it must not include (regex)"
# (the meshes' Qt pattern spares OpenCASCADE's Quantity_*.hxx, whose names start with Q too)
set(_rules
  "core/ core/ ^<(vtk|Q|GL/|QVTK)"
  "vtkpasses/mesh/ core/,vtkpasses/mesh/ ^<(Q[A-Za-z0-9]*>|Qt[A-Za-z]*/|GL/|vtkOpenGL|vtkShader)"
  "vtkpasses/render/ core/,vtkpasses/render/ ^<Q"
  "scene/ core/,scene/ ^<(vtk|QVTK|GL/)"
  "widgets/ core/,scene/,widgets/ ^<(vtk|QVTK|GL/)"
  "app/gui/ core/,vtkpasses/,scene/,widgets/,app/ ^<$"
  "app/main.cxx core/,app/,bench/bench_command.h ^<$"
  "app/ core/,vtkpasses/,app/ ^<Q"
  "bench/ core/,vtkpasses/,scene/,widgets/,app/,bench/ ^<$"
  "tests/ core/,vtkpasses/,scene/,widgets/,app/,bench/,tests/ ^<$"
  "fuzz/ core/,vtkpasses/,scene/,widgets/,app/,fuzz/ ^<$"
  "paraview/ core/,vtkpasses/,paraview/ ^<Q"
)

file(GLOB_RECURSE _files RELATIVE "${ROOT}"
  "${ROOT}/core/*.h" "${ROOT}/core/*.cxx" "${ROOT}/vtkpasses/*.h" "${ROOT}/vtkpasses/*.cxx"
  "${ROOT}/scene/*.h" "${ROOT}/scene/*.cxx" "${ROOT}/widgets/*.h" "${ROOT}/widgets/*.cxx"
  "${ROOT}/app/*.h" "${ROOT}/app/*.cxx" "${ROOT}/bench/*.h" "${ROOT}/bench/*.cxx"
  "${ROOT}/tests/*.h" "${ROOT}/tests/*.cxx" "${ROOT}/fuzz/*.h" "${ROOT}/fuzz/*.cxx"
  "${ROOT}/paraview/*.h" "${ROOT}/paraview/*.cxx")
list(LENGTH _files _count)
if(_count LESS 100)
  message(FATAL_ERROR "CheckLayers: found only ${_count} sources under ${ROOT}")
endif()

set(_violations 0)
foreach(_file IN LISTS _files)
  # The first rule whose room prefixes the file applies.
  set(_allowed)
  set(_forbidden)
  foreach(_rule IN LISTS _rules)
    string(REGEX REPLACE " +" ";" _parts "${_rule}")
    list(GET _parts 0 _room)
    string(FIND "${_file}" "${_room}" _at)
    if(_at EQUAL 0)
      list(GET _parts 1 _allowed)
      string(REPLACE "," ";" _allowed "${_allowed}")
      list(GET _parts 2 _forbidden)
      break()
    endif()
  endforeach()
  file(STRINGS "${ROOT}/${_file}" _lines REGEX "^[ \t]*#[ \t]*include")
  foreach(_line IN LISTS _lines)
    string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]*" "" _inc "${_line}")
    string(REGEX REPLACE "[ \t]*//.*$" "" _inc "${_inc}")
    string(STRIP "${_inc}" _inc)
    if(_inc MATCHES "^\"(.*)\"$")
      set(_path "${CMAKE_MATCH_1}")
      if(_path STREQUAL "aniso_shaders.h")
        if(NOT _file MATCHES "^vtkpasses/render/")
          message("${_file}: includes the embedded shaders outside vtkpasses/render: ${_inc}")
          math(EXPR _violations "${_violations} + 1")
        endif()
        continue()
      endif()
      if(_path MATCHES "\\.moc$")
        continue()
      endif()
      if(NOT EXISTS "${ROOT}/${_path}")
        message("${_file}: include not by its path from the repository root: ${_inc}")
        math(EXPR _violations "${_violations} + 1")
        continue()
      endif()
      set(_ok FALSE)
      foreach(_prefix IN LISTS _allowed)
        string(FIND "${_path}" "${_prefix}" _at)
        if(_at EQUAL 0)
          set(_ok TRUE)
          break()
        endif()
      endforeach()
      if(NOT _ok)
        message("${_file}: includes ${_inc}, outside what its room may include (${_allowed})")
        math(EXPR _violations "${_violations} + 1")
      endif()
    elseif(_inc MATCHES "${_forbidden}")
      message("${_file}: includes ${_inc}, a library its room must not know")
      math(EXPR _violations "${_violations} + 1")
    endif()
  endforeach()
endforeach()

if(_violations GREATER 0)
  message(FATAL_ERROR "CheckLayers: ${_violations} include(s) break the layering")
endif()
message("CheckLayers: ${_count} sources, every include within its room's layers")
