# cmake -DANISO=EXECUTABLE -DOUTPUT=FILE -P GenerateManInclude.cmake
# Writes help2man's include file for aniso's man page: a section per command (and per kind of
# `aniso bake`) holding that command's own --help, as the executable prints it.
include(${CMAKE_CURRENT_LIST_DIR}/HelpText.cmake)

# TEXT as roff lines kept as they are (no filling): backslashes escaped, lines starting with a
# control character protected.
function(aniso_roff out text)
  string(REPLACE "\\" "\\e" text "${text}")
  string(REGEX REPLACE "(^|\n)([.'])" "\\1\\\\&\\2" text "${text}")
  set(${out} ".nf\n${text}\n.fi\n" PARENT_SCOPE)
endfunction()

aniso_help(main_help)
aniso_help_section_words(commands "${main_help}" "(Sub)?[Cc]ommands:")

# The synopsis: every usage line of the main help ("Usage: aniso ..." and the lines under it up
# to the first empty one), each its own line.
string(REPLACE ";" "," usage_text "${main_help}")
string(REPLACE "\n" ";" usage_lines "${usage_text}")
set(synopsis "")
foreach(line IN LISTS usage_lines)
  if(line STREQUAL "")
    break()
  endif()
  if(line MATCHES "^(Usage:)? *aniso(.*)$")
    string(REGEX REPLACE "  +\\(.*\\)$" "" rest "${CMAKE_MATCH_2}")
    string(STRIP "${rest}" rest)
    string(REPLACE "\\" "\\e" rest "${rest}")
    string(APPEND synopsis ".B aniso\n${rest}\n.br\n")
  endif()
endforeach()

set(include "[SYNOPSIS]\n${synopsis}\n[DESCRIPTION]\n.B aniso\nopens a window on a mesh, a session file (a .json file written by the window) or the\ndefault scene when started without a command, and runs the commands below without a window.\nEach command prints its own options with\n.BR \"aniso COMMAND --help\" .\n\n")
foreach(command IN LISTS commands)
  aniso_help(help ${command})
  aniso_roff(roff "${help}")
  string(TOUPPER "${command}" title)
  string(APPEND include "[COMMAND ${title}]\n${roff}\n")
  if(command STREQUAL "bake")
    aniso_help_section_words(kinds "${help}" "Kinds:")
    foreach(kind IN LISTS kinds)
      aniso_help(kind_help bake ${kind})
      aniso_roff(roff "${kind_help}")
      string(TOUPPER "${kind}" kind_title)
      string(APPEND include "[COMMAND BAKE ${kind_title}]\n${roff}\n")
    endforeach()
  endif()
endforeach()
string(APPEND include "[FILES]\n.TP\n.I /usr/share/doc/aniso/README.md\nthe user's guide: the window, the commands, the file formats.\n.TP\n.I ~/.cache/aniso\nlookup tables baked once and kept for the next runs.\n")
file(WRITE "${OUTPUT}" "${include}")
