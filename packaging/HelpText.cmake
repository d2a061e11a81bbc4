# Helpers of the packaging scripts that read the aniso executable's own help (cmake -P):
# the commands, the kinds of `aniso bake` and the options of each are taken from what the
# executable prints, so the man page and the completion follow the option declarations.

# OUT: what `ANISO ARGS... --help` prints (fails the build if it fails).
function(aniso_help out)
  execute_process(COMMAND ${ANISO} ${ARGN} --help
    OUTPUT_VARIABLE text RESULT_VARIABLE result ERROR_VARIABLE error)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "'${ANISO} ${ARGN} --help' failed (${result}): ${error}")
  endif()
  set(${out} "${text}" PARENT_SCOPE)
endfunction()

# OUT: the words listed under the heading matching the regular expression HEADING
# ("(Sub)?[Cc]ommands:", "Kinds:") of TEXT: the first
# word of each line indented by two spaces (then an optional upper-case argument name, "bake
# KIND", and two spaces), up to the next heading.
function(aniso_help_section_words out text heading)
  string(REPLACE ";" "," text "${text}")
  string(REPLACE "\n" ";" lines "${text}")
  set(words)
  set(inside FALSE)
  foreach(line IN LISTS lines)
    if(line MATCHES "^${heading}$")
      set(inside TRUE)
    elseif(inside AND line MATCHES "^[^ ]")
      set(inside FALSE)
    elseif(inside AND line MATCHES "^  ([a-z][a-z0-9-]*)( [A-Z]+)?  ")
      list(APPEND words "${CMAKE_MATCH_1}")
    endif()
  endforeach()
  set(${out} "${words}" PARENT_SCOPE)
endfunction()

# OUT: every option TEXT declares: "--name" and "-x" at the start of its option lines.
function(aniso_help_options out text)
  string(REPLACE ";" "," text "${text}")
  string(REPLACE "\n" ";" lines "${text}")
  set(options)
  foreach(line IN LISTS lines)
    if(line MATCHES "^  +(-[A-Za-z]), (--[A-Za-z0-9][A-Za-z0-9-]*)")
      list(APPEND options "${CMAKE_MATCH_1}" "${CMAKE_MATCH_2}")
    elseif(line MATCHES "^  +(--[A-Za-z0-9][A-Za-z0-9-]*)")
      list(APPEND options "${CMAKE_MATCH_1}")
    endif()
  endforeach()
  list(REMOVE_DUPLICATES options)
  set(${out} "${options}" PARENT_SCOPE)
endfunction()
