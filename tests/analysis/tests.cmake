lbmshape_test(analysis_tests
  ${CMAKE_CURRENT_LIST_DIR}/mesh_topology_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/surface_comparison_test.cpp
)
lbmshape_shared_asset_test(analysis_shared_mesh_tests
  ${CMAKE_CURRENT_LIST_DIR}/shared_mesh_comparison_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/shared_mesh_topology_test.cpp
)
