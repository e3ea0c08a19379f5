# Writes rosarch(1) from the program's own --help, so the man page never disagrees with it.
#   cmake -DROSARCH=<rosarch> -DOUT=<rosarch.1> -P manpage.cmake
# The usage text is already laid out for a terminal, so it goes in verbatim (.nf); each
# command's own --help follows under COMMANDS.
foreach(var ROSARCH OUT)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "manpage.cmake needs -D${var}=...")
  endif()
endforeach()

# help(<var> <args...>): the program's stdout for <args>; a failure fails the build.
function(help var)
  execute_process(COMMAND "${ROSARCH}" ${ARGN} OUTPUT_VARIABLE text RESULT_VARIABLE code
    ERROR_VARIABLE errors)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "${ROSARCH} ${ARGN} failed (${code}): ${errors}")
  endif()
  # The usage lines name the program as it was started.
  string(REPLACE "${ROSARCH}" "rosarch" text "${text}")
  set(${var} "${text}" PARENT_SCOPE)
endfunction()

# roff(<var> <text>): <text> safe to put in a man page between .nf and .fi.
function(roff var text)
  string(REPLACE "\\" "\\e" text "${text}")
  string(REGEX REPLACE "(^|\n)([.'])" "\\1\\\\&\\2" text "${text}")
  string(REGEX REPLACE "\n+$" "" text "${text}")
  set(${var} "${text}" PARENT_SCOPE)
endfunction()

help(version --version)
string(REGEX MATCH "[0-9][0-9.]*" version "${version}")
help(usage --help)
roff(usage_roff "${usage}")

string(CONCAT page
  ".TH ROSARCH 1 \"\" \"rosarch ${version}\" \"User Commands\"\n"
  ".SH NAME\n"
  "rosarch \\- recover the architecture of a ROS 2 workspace\n"
  ".SH SYNOPSIS\n"
  ".B rosarch\n"
  "[\\fIworkspace\\fR]\n"
  ".br\n"
  ".B rosarch\n"
  "\\fIcommand\\fR [\\fIoptions\\fR]\n"
  ".SH DESCRIPTION\n"
  "rosarch reads a ROS 2 workspace's sources and launch files and recovers its nodes, their "
  "topics, services, actions and parameters, and how the launch files compose them. Without a "
  "command it opens the window on \\fIworkspace\\fR; with one it runs headless.\n"
  ".PP\n"
  ".nf\n${usage_roff}\n.fi\n"
  ".SH COMMANDS\n")

# The commands are the words of the usage lines "  rosarch <command> ...".
string(REGEX MATCHALL "\n  rosarch [a-z]+" lines "${usage}")
set(commands "")
foreach(line IN LISTS lines)
  string(REGEX REPLACE "\n  rosarch " "" command "${line}")
  list(APPEND commands "${command}")
endforeach()
list(REMOVE_DUPLICATES commands)
foreach(command IN LISTS commands)
  help(text ${command} --help)
  roff(text_roff "${text}")
  string(APPEND page ".SS ${command}\n.nf\n${text_roff}\n.fi\n")
endforeach()

file(WRITE "${OUT}" "${page}")
