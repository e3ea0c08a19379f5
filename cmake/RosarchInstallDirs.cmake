# The install layout (GNUInstallDirs), needed before the targets are defined: the executables
# find their helpers and data relative to themselves, so the paths are compiled in relative
# to bin/ and an installed tree still runs after it is moved.
#
#   bin/rosarch                       the application and the command line
#   libexec/rosarch/rosarch-stages    helper programs that rosarch runs, not meant for a
#   libexec/rosarch/rosarch-layout    person's PATH
#   lib/rosarch/librosarch_*.so       rosarch's own libraries (private: no headers, no soname)
#   share/rosarch/example_ws          the bundled example workspace the GUI opens first
include(GNUInstallDirs)

set(ROSARCH_INSTALL_LIBDIR "${CMAKE_INSTALL_LIBDIR}/rosarch")
set(ROSARCH_INSTALL_HELPERDIR "${CMAKE_INSTALL_LIBEXECDIR}/rosarch")
set(ROSARCH_INSTALL_DATADIR "${CMAKE_INSTALL_DATADIR}/rosarch")

# rosarch_relative_dir(<var> <from> <to>): the path from install folder <from> to <to>.
function(rosarch_relative_dir var from to)
  if(IS_ABSOLUTE "${from}" OR IS_ABSOLUTE "${to}")
    message(FATAL_ERROR "rosarch installs relocatably: give CMAKE_INSTALL_*DIR relative to the prefix")
  endif()
  file(RELATIVE_PATH path "/prefix/${from}" "/prefix/${to}")
  set(${var} "${path}" PARENT_SCOPE)
endfunction()

rosarch_relative_dir(ROSARCH_HELPERS_FROM_BIN "${CMAKE_INSTALL_BINDIR}" "${ROSARCH_INSTALL_HELPERDIR}")
rosarch_relative_dir(ROSARCH_DATA_FROM_BIN "${CMAKE_INSTALL_BINDIR}" "${ROSARCH_INSTALL_DATADIR}")
