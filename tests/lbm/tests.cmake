lbmshape_test(lbm_tests
  ${CMAKE_CURRENT_LIST_DIR}/adaptive_gamma_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/band_memory_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/band_solver_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/band_surface_pass_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/conservation_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/curvature_motion_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/diffusion_coefficient_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/gpu_matches_reference_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/lattice_memory_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/source_term_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/step_timing_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/surface_change_test.cpp
  DEVICE_SUITES BandSolverTest BandCopiesAcrossABus BandSurfacePass SurfacesOnTheDevice BandVulkanMatchesReference BandVulkanPools BandVulkanSource BandVulkanStaging Conservation CurvatureMotion
                DiffusionCoefficient GpuMatchesReference PaperRuleOnTheDevice SourceTerm StartUpTransient
)
