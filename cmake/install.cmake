# `cmake --install build [--prefix DIR]`: the lbmshape binary with its man
# page and bash completion, liblbmshape.so with its headers under
# include/lbmshape, a CMake package (find_package(lbmshape), target
# lbmshape::lbmshape) and a pkg-config file.
# examples/denoise_in_memory builds against the result (tests/install/).
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

configure_file(${PROJECT_SOURCE_DIR}/cmake/version.hpp.in ${PROJECT_BINARY_DIR}/include/lbmshape/version.hpp @ONLY)
target_include_directories(lbmshape_shared INTERFACE "$<BUILD_INTERFACE:${PROJECT_BINARY_DIR}/include>")

if(LBMSHAPE_COMMAND_LINE)
  install(TARGETS lbmshape RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  # Bash completion (zsh through bashcompinit), reading the binary's --help.
  install(FILES ${PROJECT_SOURCE_DIR}/completion/lbmshape.bash
          DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions RENAME lbmshape)
  # The man page, from the binary's --help (help2man; Debian: help2man).
  find_program(HELP2MAN help2man)
  if(HELP2MAN)
    add_custom_command(OUTPUT ${PROJECT_BINARY_DIR}/lbmshape.1
                       COMMAND ${PROJECT_SOURCE_DIR}/scripts/make-man-page.sh $<TARGET_FILE:lbmshape> ${PROJECT_BINARY_DIR}/lbmshape.1
                       DEPENDS lbmshape ${PROJECT_SOURCE_DIR}/scripts/make-man-page.sh
                       COMMENT "Writing the man page lbmshape(1)" VERBATIM)
    add_custom_target(man_page ALL DEPENDS ${PROJECT_BINARY_DIR}/lbmshape.1)
    install(FILES ${PROJECT_BINARY_DIR}/lbmshape.1 DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
  else()
    message(STATUS "help2man not found: no man page (on Debian: apt-get install help2man)")
  endif()
endif()
install(TARGETS lbmshape_shared EXPORT lbmshapeTargets
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(FILES ${PROJECT_SOURCE_DIR}/include/lbmshape/lbmshape.hpp ${PROJECT_BINARY_DIR}/include/lbmshape/version.hpp
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/lbmshape)
# The API's headers include the library's own as "lbmshape/<folder>/...", by
# their path under src/, and the lattice's few constants shared with the
# shaders as "lbmshape/shaders/..." (shaders/*.h): only include/ goes on a
# program's include path.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/src/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/lbmshape
        FILES_MATCHING PATTERN "*.hpp")
file(GLOB shader_headers ${PROJECT_SOURCE_DIR}/shaders/*.h)
install(FILES ${shader_headers} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/lbmshape/shaders)
# The licence travels with the copies (MIT).
install(FILES ${PROJECT_SOURCE_DIR}/LICENSE DESTINATION ${CMAKE_INSTALL_DATADIR}/doc/lbmshape)

set(package_dir ${CMAKE_INSTALL_LIBDIR}/cmake/lbmshape)
install(EXPORT lbmshapeTargets NAMESPACE lbmshape:: DESTINATION ${package_dir})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/lbmshapeConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/lbmshapeConfig.cmake INSTALL_DESTINATION ${package_dir})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/lbmshapeConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/lbmshapeConfig.cmake ${PROJECT_BINARY_DIR}/lbmshapeConfigVersion.cmake
        DESTINATION ${package_dir})

# pkg-config lbmshape. The prefix is the one configured (CMAKE_INSTALL_PREFIX);
# an install elsewhere with --prefix gets its own, written straight to the
# prefix (nothing in the build tree changes, so two installs from one build
# cannot trade prefixes).
configure_file(${PROJECT_SOURCE_DIR}/cmake/lbmshape.pc.in ${PROJECT_BINARY_DIR}/lbmshape.pc.in.configured @ONLY)
install(CODE "
  file(READ \"${PROJECT_BINARY_DIR}/lbmshape.pc.in.configured\" pc)
  string(REPLACE \"prefix=${CMAKE_INSTALL_PREFIX}\" \"prefix=\${CMAKE_INSTALL_PREFIX}\" pc \"\${pc}\")
  set(pc_file \"\$ENV{DESTDIR}\${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_LIBDIR}/pkgconfig/lbmshape.pc\")
  message(STATUS \"Installing: \${pc_file}\")
  file(WRITE \"\${pc_file}\" \"\${pc}\")
  list(APPEND CMAKE_INSTALL_MANIFEST_FILES \"\${pc_file}\")")
