# Embeds GLSL files into a C++ header of raw string literals, at build time.
#
# Included: defines aniso_embed_shaders(TARGET target HEADER name.h NAMESPACE ns FILES a.glsl ...),
# which generates ${CMAKE_CURRENT_BINARY_DIR}/generated/<HEADER> whenever a listed file changes and
# adds that directory to TARGET's include path. File "foo_bar.glsl" becomes
# `inline constexpr const char* kFooBar` in namespace ns.
# Run as a script (cmake -P): writes the header from OUTPUT, NAMESPACE and FILES (|-separated).

function(_aniso_shader_identifier path out)
  get_filename_component(_stem "${path}" NAME_WE)
  string(REPLACE "_" ";" _parts "${_stem}")
  set(_id "k")
  foreach(_part IN LISTS _parts)
    string(SUBSTRING "${_part}" 0 1 _first)
    string(SUBSTRING "${_part}" 1 -1 _rest)
    string(TOUPPER "${_first}" _first)
    string(APPEND _id "${_first}${_rest}")
  endforeach()
  set(${out} "${_id}" PARENT_SCOPE)
endfunction()

function(_aniso_write_shader_header output namespace files)
  set(_text "// Generated from vtkpasses/render/shaders by cmake/EmbedShaders.cmake; edit the .glsl files.\n")
  string(APPEND _text "#pragma once\n\nnamespace ${namespace}\n{\n")
  foreach(_file IN LISTS files)
    file(READ "${_file}" _source)
    if(_source MATCHES "\\)glsl\"")
      message(FATAL_ERROR "${_file}: contains the raw-string terminator )glsl\"")
    endif()
    _aniso_shader_identifier("${_file}" _id)
    string(APPEND _text "inline constexpr const char* ${_id} = R\"glsl(${_source})glsl\";\n")
  endforeach()
  string(APPEND _text "} // namespace ${namespace}\n")
  # Rewrite only on change so dependants are not rebuilt needlessly.
  if(EXISTS "${output}")
    file(READ "${output}" _old)
    if(_old STREQUAL _text)
      return()
    endif()
  endif()
  file(WRITE "${output}" "${_text}")
endfunction()

if(CMAKE_SCRIPT_MODE_FILE)
  string(REPLACE "|" ";" _files "${FILES}")
  _aniso_write_shader_header("${OUTPUT}" "${NAMESPACE}" "${_files}")
  return()
endif()

set(_ANISO_EMBED_SHADERS_SCRIPT "${CMAKE_CURRENT_LIST_FILE}")

function(aniso_embed_shaders)
  cmake_parse_arguments(ARG "" "TARGET;HEADER;NAMESPACE" "FILES" ${ARGN})
  set(_dir "${CMAKE_CURRENT_BINARY_DIR}/generated")
  set(_output "${_dir}/${ARG_HEADER}")
  set(_files)
  foreach(_f IN LISTS ARG_FILES)
    get_filename_component(_abs "${_f}" ABSOLUTE)
    list(APPEND _files "${_abs}")
  endforeach()
  # "|" separates the files on the command line, where ";" would split the argument.
  string(REPLACE ";" "|" _joined "${_files}")
  add_custom_command(OUTPUT "${_output}"
    COMMAND ${CMAKE_COMMAND} -E make_directory "${_dir}"
    COMMAND ${CMAKE_COMMAND} "-DOUTPUT=${_output}" "-DNAMESPACE=${ARG_NAMESPACE}"
      "-DFILES=${_joined}" -P "${_ANISO_EMBED_SHADERS_SCRIPT}"
    DEPENDS ${_files} "${_ANISO_EMBED_SHADERS_SCRIPT}"
    COMMENT "Embedding shaders into ${ARG_HEADER}"
    VERBATIM)
  target_sources(${ARG_TARGET} PRIVATE "${_output}")
  target_include_directories(${ARG_TARGET} PRIVATE "${_dir}")
endfunction()
