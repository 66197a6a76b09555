# The ORCA solver and the `orca` policy plugin (plugins/policies/orca).
if(CROWDSIM_BUILD_TESTS OR CROWDSIM_BUILD_BENCHMARKS)
  # The two-pass crowd simulator the solver tests and benchmarks drive.
  add_library(crowdsim_orca_test_sim STATIC ${CMAKE_CURRENT_SOURCE_DIR}/unit/orca/orca_test_sim.cc)
  target_include_directories(crowdsim_orca_test_sim PUBLIC ${CMAKE_CURRENT_SOURCE_DIR}/unit/orca)
  target_link_libraries(crowdsim_orca_test_sim PUBLIC crowdsim_orca_solver)
  target_compile_options(crowdsim_orca_test_sim PRIVATE ${CROWDSIM_WARNINGS})
endif()

if(CROWDSIM_BUILD_TESTS)
  foreach(test orca_solver_test orca_scenarios_test orca_guidance_test orca_plugin_test
               orca_rect_index_test orca_agent_lines_test)
    crowdsim_add_gtest(${test} unit
      SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/unit/orca/${test}.cc
      LIBS crowdsim_orca_solver crowdsim_orca_test_sim)
  endforeach()
endif()

if(CROWDSIM_BUILD_BENCHMARKS)
  crowdsim_add_benchmark(orca_bench
    SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/bench/orca/orca_bench.cc
    LIBS crowdsim_orca_solver crowdsim_orca_test_sim)
  crowdsim_add_benchmark(rvo2_scenarios_bench
    SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/bench/orca/rvo2_scenarios_bench.cc
    LIBS crowdsim_orca_solver crowdsim_orca_test_sim)
  # One seeded run of Circle or Blocks, for overlap_stats.sh's paired comparison with RVO2.
  add_executable(rvo2_overlap_stats ${CMAKE_CURRENT_SOURCE_DIR}/bench/orca/rvo2_overlap_stats.cc)
  target_link_libraries(rvo2_overlap_stats PRIVATE crowdsim_orca_solver crowdsim_orca_test_sim)
  target_compile_options(rvo2_overlap_stats PRIVATE ${CROWDSIM_WARNINGS})
  set_target_properties(rvo2_overlap_stats PROPERTIES RUNTIME_OUTPUT_DIRECTORY "${CMAKE_BINARY_DIR}/bench")
endif()
