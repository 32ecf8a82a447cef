target_sources(lbmshape_lib PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/compute_program.cpp
  ${CMAKE_CURRENT_LIST_DIR}/device_description.cpp
  ${CMAKE_CURRENT_LIST_DIR}/driver_modules.cpp
  ${CMAKE_CURRENT_LIST_DIR}/driver_shader_cache.cpp
  ${CMAKE_CURRENT_LIST_DIR}/gpu_buffer.cpp
  ${CMAKE_CURRENT_LIST_DIR}/gpu_context.cpp
  ${CMAKE_CURRENT_LIST_DIR}/gpu_image.cpp
  ${CMAKE_CURRENT_LIST_DIR}/pipeline_cache_file.cpp
  ${CMAKE_CURRENT_LIST_DIR}/recorded_commands.cpp
  ${CMAKE_CURRENT_LIST_DIR}/staged_copies.cpp
  ${CMAKE_CURRENT_LIST_DIR}/vulkan_instance.cpp
)
