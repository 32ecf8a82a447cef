lbmshape_test(surface_tests
  ${CMAKE_CURRENT_LIST_DIR}/band_marching_cubes_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/cube_cases_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/marching_cubes_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/surface_pieces_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/triangle_relaxation_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/volume_keeping_test.cpp
)
