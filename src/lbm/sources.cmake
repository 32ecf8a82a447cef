target_sources(lbmshape_lib PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/band_reference_solver.cpp
  ${CMAKE_CURRENT_LIST_DIR}/band_state.cpp
  ${CMAKE_CURRENT_LIST_DIR}/band_surface_pass.cpp
  ${CMAKE_CURRENT_LIST_DIR}/band_vulkan_solver.cpp
  ${CMAKE_CURRENT_LIST_DIR}/adaptive_gamma.cpp
  ${CMAKE_CURRENT_LIST_DIR}/frozen_bricks.cpp
  ${CMAKE_CURRENT_LIST_DIR}/lattice_memory.cpp
  ${CMAKE_CURRENT_LIST_DIR}/reference_solver.cpp
  ${CMAKE_CURRENT_LIST_DIR}/relaxation.cpp
  ${CMAKE_CURRENT_LIST_DIR}/solver_state.cpp
  ${CMAKE_CURRENT_LIST_DIR}/surface_change.cpp
  ${CMAKE_CURRENT_LIST_DIR}/vulkan_solver.cpp
)
