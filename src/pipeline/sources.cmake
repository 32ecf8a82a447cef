target_sources(lbmshape_lib PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/animation_memory.cpp
  ${CMAKE_CURRENT_LIST_DIR}/compute_device.cpp
  ${CMAKE_CURRENT_LIST_DIR}/denoise.cpp
  ${CMAKE_CURRENT_LIST_DIR}/feature_probe.cpp
  ${CMAKE_CURRENT_LIST_DIR}/field_noise.cpp
  ${CMAKE_CURRENT_LIST_DIR}/frame_writer.cpp
  ${CMAKE_CURRENT_LIST_DIR}/interruptible_steps.cpp
  ${CMAKE_CURRENT_LIST_DIR}/morph.cpp
  ${CMAKE_CURRENT_LIST_DIR}/morph_frame_report.cpp
  ${CMAKE_CURRENT_LIST_DIR}/morph_front.cpp
  ${CMAKE_CURRENT_LIST_DIR}/morph_schedule.cpp
  ${CMAKE_CURRENT_LIST_DIR}/smoothing_radius.cpp
  ${CMAKE_CURRENT_LIST_DIR}/smoothing_stop.cpp
  ${CMAKE_CURRENT_LIST_DIR}/morph_lattice.cpp
  ${CMAKE_CURRENT_LIST_DIR}/render_job.cpp
  ${CMAKE_CURRENT_LIST_DIR}/stage_clock.cpp
)
