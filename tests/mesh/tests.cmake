lbmshape_reader_test(mesh_tests
  ${CMAKE_CURRENT_LIST_DIR}/atomic_file_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/bad_input_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/gltf_reading_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/gltf_validation_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/hand_made_gltf.cpp
  ${CMAKE_CURRENT_LIST_DIR}/mesh_fixtures.cpp
  ${CMAKE_CURRENT_LIST_DIR}/noise_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/reader_cases_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/reader_file_system_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/round_trip_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/soup_reading_test.cpp
)
if(NOT LBMSHAPE_READERS_ONLY)  # the sanitized readers build runs the core reader tests only
  lbmshape_shared_asset_test(mesh_shared_asset_tests
    ${CMAKE_CURRENT_LIST_DIR}/shared_meshes_test.cpp
  )
endif()
