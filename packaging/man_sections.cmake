# Writes the man page's extra sections (help2man --include): the help of each subcommand, so
# isoparm(1) covers every subcommand and option. Run with -DISOPARM=<binary> -DOUT=<file>.
set(text "[SUBCOMMANDS]\n")
foreach(sub geom render figure animate export import examples)
  execute_process(COMMAND ${ISOPARM} ${sub} --help OUTPUT_VARIABLE help RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "isoparm ${sub} --help failed (${rc})")
  endif()
  string(REPLACE "${ISOPARM}" "isoparm" help "${help}") # not the build tree's path
  # Lines starting with a dot or a quote would be read as roff requests.
  string(REPLACE "\n." "\n\\&." help "${help}")
  string(REPLACE "\n'" "\n\\&'" help "${help}")
  string(APPEND text ".SS \"isoparm ${sub}\"\n.nf\n${help}.fi\n")
endforeach()
string(APPEND text "[FILES]\n.TP\n.I PREFIX/share/isoparm/scenes\nThe example scenes (the paper's figures); File > Open Example lists them.\n"
  ".TP\n.I $XDG_CONFIG_HOME/isoparm/settings.json\nLayout, recent files and window sizes.\n"
  ".TP\n.I $XDG_STATE_HOME/isoparm/\nAutosaved recovery files.\n")
file(WRITE ${OUT} "${text}")
