lbmshape_test(cli_tests
  ${CMAKE_CURRENT_LIST_DIR}/compress_cli_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/curvature_colours_cli_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/denoise_cli_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/hostile_input_cli_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/jobs_file_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/json_results_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/morph_align_and_convergence_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/morph_cli_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/progress_cli_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/render_cli_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/signals_cli_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/morph_empty_frames_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/usage_errors_test.cpp
)
add_dependencies(cli_tests lbmshape)  # they run the binary
target_link_libraries(cli_tests PRIVATE PkgConfig::STB)  # reads the pictures
