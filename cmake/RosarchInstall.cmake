# `cmake --install` and `cpack -G DEB`: the layout is described in RosarchInstallDirs.cmake and
# docs/install.md. Included at the end of the top CMakeLists.txt, once every target exists.

# rosarch_shared_libraries(<var> <folders...>): rosarch's own shared libraries defined in
# <folders> and below.
function(rosarch_shared_libraries var)
  set(found "")
  set(folders ${ARGN})
  while(folders)
    list(POP_FRONT folders folder)
    get_property(targets DIRECTORY ${folder} PROPERTY BUILDSYSTEM_TARGETS)
    foreach(target IN LISTS targets)
      get_target_property(type ${target} TYPE)
      if(type STREQUAL "SHARED_LIBRARY")
        list(APPEND found ${target})
      endif()
    endforeach()
    get_property(subfolders DIRECTORY ${folder} PROPERTY SUBDIRECTORIES)
    list(APPEND folders ${subfolders})
  endwhile()
  set(${var} ${found} PARENT_SCOPE)
endfunction()

# Everything the application and its helpers link (the tests and the benchmark tools are not
# installed). Empty when ROSARCH_SHARED_LIBS is off: the executables then hold the libraries.
rosarch_shared_libraries(rosarch_libraries
  ${PROJECT_SOURCE_DIR}/model ${PROJECT_SOURCE_DIR}/document ${PROJECT_SOURCE_DIR}/widgets
  ${PROJECT_SOURCE_DIR}/app)

# Relative RPATHs: the installed tree runs from any prefix, and after it is moved.
rosarch_relative_dir(bin_to_lib "${CMAKE_INSTALL_BINDIR}" "${ROSARCH_INSTALL_LIBDIR}")
rosarch_relative_dir(helper_to_lib "${ROSARCH_INSTALL_HELPERDIR}" "${ROSARCH_INSTALL_LIBDIR}")
set_target_properties(rosarch PROPERTIES INSTALL_RPATH "$ORIGIN/${bin_to_lib}")
set_target_properties(rosarch-stages PROPERTIES INSTALL_RPATH "$ORIGIN/${helper_to_lib}")
if(rosarch_libraries)
  set_target_properties(${rosarch_libraries} PROPERTIES INSTALL_RPATH "$ORIGIN")
endif()
# Linked libraries outside the system's folders (the Graphviz layout plugin's) stay found.
set_target_properties(rosarch rosarch-stages rosarch-layout ${rosarch_libraries}
  PROPERTIES INSTALL_RPATH_USE_LINK_PATH ON)

install(TARGETS rosarch RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(TARGETS rosarch-stages rosarch-layout RUNTIME DESTINATION ${ROSARCH_INSTALL_HELPERDIR})
if(rosarch_libraries)
  install(TARGETS ${rosarch_libraries} LIBRARY DESTINATION ${ROSARCH_INSTALL_LIBDIR})
endif()

# The example the GUI opens when it has no workspace yet. Everything else the program reads
# (prompts, schemas, interface models, site assets, icons, translations) is compiled in as
# Qt resources.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/resources/example_ws DESTINATION ${ROSARCH_INSTALL_DATADIR}
  PATTERN .clang-format EXCLUDE)

install(FILES ${PROJECT_SOURCE_DIR}/packaging/rosarch.desktop
  DESTINATION ${CMAKE_INSTALL_DATADIR}/applications)
install(FILES ${PROJECT_SOURCE_DIR}/resources/icons/rosarch.svg
  DESTINATION ${CMAKE_INSTALL_DATADIR}/icons/hicolor/scalable/apps)

install(FILES ${PROJECT_SOURCE_DIR}/LICENSE DESTINATION ${CMAKE_INSTALL_DOCDIR} RENAME copyright)

# rosarch(1), written from `rosarch --help` and each command's --help at build time.
# Compressed as Debian wants it (gzip -9n: no name or time stamp, so the same bytes each time).
set(manpage ${CMAKE_CURRENT_BINARY_DIR}/packaging/rosarch.1)
add_custom_command(OUTPUT ${manpage} ${manpage}.gz
  COMMAND ${CMAKE_COMMAND} -E env QT_QPA_PLATFORM=offscreen ASAN_OPTIONS=detect_leaks=0
    ${CMAKE_COMMAND} -DROSARCH=$<TARGET_FILE:rosarch> -DOUT=${manpage}
    -P ${PROJECT_SOURCE_DIR}/packaging/manpage.cmake
  COMMAND gzip -9nkf ${manpage}
  DEPENDS rosarch ${PROJECT_SOURCE_DIR}/packaging/manpage.cmake
  COMMENT "Writing rosarch(1) from rosarch --help"
  VERBATIM)
add_custom_target(rosarch-manpage ALL DEPENDS ${manpage}.gz)
install(FILES ${manpage}.gz DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)

# What `cmake --install` and cpack take from the build tree, without the tests and tools.
add_custom_target(rosarch-installable DEPENDS rosarch rosarch-stages rosarch-layout rosarch-manpage)

# cpack -G DEB (from the build folder). The package installs under /usr.
set(CPACK_PACKAGE_NAME rosarch)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "Recover the architecture of a ROS 2 workspace")
# One line of the control file's extended description each (Debian wants them under 80).
string(JOIN "\n" CPACK_PACKAGE_DESCRIPTION
  "rosarch reads a ROS 2 workspace's sources and launch files and recovers its"
  "nodes, their topics, services, actions and parameters, and how the launch files"
  "compose them. It shows the architecture in a window, traces every element back"
  "to its source, and writes JSON, PlantUML, Mermaid and an HTML site from the"
  "command line.")
set(CPACK_RESOURCE_FILE_LICENSE ${PROJECT_SOURCE_DIR}/LICENSE)
set(CPACK_PACKAGE_CONTACT "rosarch maintainers <rosarch@invalid>" CACHE STRING
  "Maintainer field of the .deb")
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION devel)
# dpkg-shlibdeps turns the linked libraries (Qt 6, QScintilla, Graphviz, libcurl, tree-sitter,
# yaml-cpp, OpenSSL) into Depends; it finds our own libraries through the $ORIGIN RPATHs.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# Loaded at run time, so no linked library names them: Qt's platform plugins (xcb, offscreen).
set(CPACK_DEBIAN_PACKAGE_DEPENDS "qt6-qpa-plugins")
# --render runs PlantUML with Java; `rosarch diff --rev` and the site's source links run git.
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "default-jre-headless | java-runtime-headless, plantuml, git")
include(CPack)
