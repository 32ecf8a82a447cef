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
# their path under src/ (or shaders/ for the constants shared with the
# shaders): only include/ goes on a program's include path. Only the headers
# lbmshape.hpp reaches are installed, which need nothing but the standard
# library, GLM and nlohmann-json (the package's declared dependencies); the
# other internal headers (Vulkan-Hpp's, tinygltf's, OpenMesh's, OpenMP's
# users) stay in the source tree. tests/install/check_install.cmake checks
# that this list is exactly what lbmshape.hpp includes, and what they in
# turn include.
set(api_headers
    band/band_field.hpp band/brick_set.hpp
    core/atomic_file.hpp core/error.hpp core/extent.hpp core/interrupt.hpp core/log.hpp core/parameter_names.hpp
    core/progress.hpp core/stopwatch.hpp core/volume.hpp
    lbm/adaptive_gamma.hpp lbm/band_solver.hpp lbm/lattice_solver.hpp lbm/stepping_solver.hpp
    library_version.hpp
    mesh/gltf_compression.hpp mesh/icosphere.hpp mesh/mesh_format.hpp mesh/mesh_noise.hpp mesh/mesh_reader.hpp
    mesh/mesh_source.hpp mesh/mesh_writer.hpp mesh/triangle_mesh.hpp mesh/writable_mesh.hpp
    pipeline/compute_device.hpp pipeline/denoise.hpp pipeline/field_noise.hpp pipeline/frame_writer.hpp
    pipeline/morph.hpp
    sdf/band_signed_distance.hpp sdf/grid_frame.hpp sdf/signed_distance.hpp sdf/triangle_bvh.hpp
    surface/surface_pieces.hpp surface/triangle_relaxation.hpp)
foreach(header IN LISTS api_headers)
  get_filename_component(folder ${header} DIRECTORY)
  install(FILES ${PROJECT_SOURCE_DIR}/src/${header} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/lbmshape/${folder})
endforeach()
install(FILES ${PROJECT_SOURCE_DIR}/shaders/adaptive_gamma_bounds.h
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/lbmshape/shaders)
# The licence travels with the copies (MIT).
install(FILES ${PROJECT_SOURCE_DIR}/LICENSE DESTINATION ${CMAKE_INSTALL_DATADIR}/doc/lbmshape)

set(package_dir ${CMAKE_INSTALL_LIBDIR}/cmake/lbmshape)
install(EXPORT lbmshapeTargets NAMESPACE lbmshape:: DESTINATION ${package_dir})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/lbmshapeConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/lbmshapeConfig.cmake INSTALL_DESTINATION ${package_dir})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/lbmshapeConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/lbmshapeConfig.cmake ${PROJECT_BINARY_DIR}/lbmshapeConfigVersion.cmake
        DESTINATION ${package_dir})

# pkg-config lbmshape. The prefix is found from the .pc file's own place
# (pkg-config's ${pcfiledir}), so an install with --prefix, a DESTDIR
# staging or a copied prefix all point at themselves.
if(IS_ABSOLUTE "${CMAKE_INSTALL_LIBDIR}")
  message(FATAL_ERROR "CMAKE_INSTALL_LIBDIR must be relative to the prefix, not ${CMAKE_INSTALL_LIBDIR}")
endif()
file(RELATIVE_PATH LBMSHAPE_PC_TO_PREFIX /prefix/${CMAKE_INSTALL_LIBDIR}/pkgconfig /prefix)
string(REGEX REPLACE "/$" "" LBMSHAPE_PC_TO_PREFIX "${LBMSHAPE_PC_TO_PREFIX}")
configure_file(${PROJECT_SOURCE_DIR}/cmake/lbmshape.pc.in ${PROJECT_BINARY_DIR}/lbmshape.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/lbmshape.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
