target_sources(lbmshape_lib PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/band_bench.cpp
  ${CMAKE_CURRENT_LIST_DIR}/denoise_stages.cpp
  ${CMAKE_CURRENT_LIST_DIR}/lattice_bench.cpp
  ${CMAKE_CURRENT_LIST_DIR}/memory_bandwidth.cpp
)
