# The `hsfm` policy plugin (plugins/policies/hsfm): its forces and torque against their closed
# forms, the loaded plugin turning, walking among rectangles, and a decision's cost.
if(CROWDSIM_BUILD_TESTS)
  crowdsim_add_gtest(hsfm_test unit
    SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/unit/hsfm/hsfm_test.cc
            ${CMAKE_SOURCE_DIR}/plugins/policies/hsfm/hsfm.cc)
  target_include_directories(hsfm_test PRIVATE
    ${CMAKE_SOURCE_DIR}/plugins/policies/hsfm ${CMAKE_SOURCE_DIR}/plugins/lib/walking/include)
endif()

if(CROWDSIM_BUILD_BENCHMARKS)
  crowdsim_add_benchmark(hsfm_bench
    SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/bench/hsfm/hsfm_bench.cc)
endif()
