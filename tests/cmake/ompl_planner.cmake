# The OMPL global-planner baseline (plugins/policies/ompl_planner). Skipped with the module.
if(TARGET crowdsim_ompl_planner)
  if(CROWDSIM_BUILD_TESTS)
    foreach(test ompl_planner_config_test global_planner_test action_set_test)
      crowdsim_add_gtest(${test} unit
        SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/unit/ompl_planner/${test}.cc
        LIBS crowdsim_ompl_planner)
    endforeach()
    crowdsim_add_gtest(ompl_planner_episodes_test integration
      SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/integration/ompl_planner/ompl_planner_episodes_test.cc)
  endif()

  if(CROWDSIM_BUILD_BENCHMARKS)
    crowdsim_add_benchmark(ompl_planner_bench
      SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/bench/ompl_planner/ompl_planner_bench.cc
      LIBS crowdsim_ompl_planner)
  endif()
endif()
