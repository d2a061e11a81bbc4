# cmake -DANISO=EXECUTABLE -DOUTPUT=FILE -P GenerateCompletion.cmake
# Writes the bash completion of aniso from the executable's help: its commands, the kinds of
# `aniso bake` and the options of each; file names where a value or a mesh is expected.
include(${CMAKE_CURRENT_LIST_DIR}/HelpText.cmake)

aniso_help(main_help)
aniso_help_section_words(commands "${main_help}" "(Sub)?[Cc]ommands:")
aniso_help_options(main_options "${main_help}")
if(NOT commands)
  message(FATAL_ERROR "no commands found in '${ANISO} --help'")
endif()
list(JOIN commands " " command_words)
list(JOIN main_options " " main_words)

set(cases "")
foreach(command IN LISTS commands)
  aniso_help(help ${command})
  aniso_help_options(options "${help}")
  list(JOIN options " " option_words)
  if(command STREQUAL "bake")
    aniso_help_section_words(kinds "${help}" "Kinds:")
    list(JOIN kinds " " kind_words)
    set(kind_cases "")
    foreach(kind IN LISTS kinds)
      aniso_help(kind_help bake ${kind})
      aniso_help_options(kind_options "${kind_help}")
      list(JOIN kind_options " " kind_option_words)
      string(APPEND kind_cases "        ${kind}) opts=\"${kind_option_words}\" ;;\n")
    endforeach()
    string(APPEND cases
      "    bake)\n"
      "      if [ \"$cword\" -eq 2 ]; then\n"
      "        COMPREPLY=($(compgen -W \"${kind_words} ${option_words}\" -- \"$cur\"))\n"
      "        return\n"
      "      fi\n"
      "      case \"\${COMP_WORDS[2]}\" in\n"
      "${kind_cases}"
      "        *) opts=\"${option_words}\" ;;\n"
      "      esac\n"
      "      ;;\n")
  else()
    string(APPEND cases "    ${command}) opts=\"${option_words}\" ;;\n")
  endif()
endforeach()

set(ANISO_COMPLETION_COMMANDS "${command_words}")
set(ANISO_COMPLETION_MAIN_OPTIONS "${main_words}")
set(ANISO_COMPLETION_CASES "${cases}")
configure_file(${CMAKE_CURRENT_LIST_DIR}/resources/aniso.bash-completion.in "${OUTPUT}" @ONLY)
# configure_file leaves an unchanged file as it is: its time would stay older than the
# executable's, and every build would generate it again.
file(TOUCH "${OUTPUT}")
