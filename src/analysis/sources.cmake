target_sources(lbmshape_lib PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/joined_seams.cpp
  ${CMAKE_CURRENT_LIST_DIR}/mesh_topology.cpp
  ${CMAKE_CURRENT_LIST_DIR}/normal_noise.cpp
  ${CMAKE_CURRENT_LIST_DIR}/surface_comparison.cpp
  ${CMAKE_CURRENT_LIST_DIR}/surface_sampling.cpp
)
