# The `social_force` policy plugin (plugins/policies/social_force): its forces against their
# closed forms, the loaded plugin among rectangles, and a decision's cost.
if(CROWDSIM_BUILD_TESTS)
  crowdsim_add_gtest(social_force_test unit
    SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/unit/social_force/social_force_test.cc
            ${CMAKE_SOURCE_DIR}/plugins/policies/social_force/social_force.cc)
  target_include_directories(social_force_test PRIVATE
    ${CMAKE_SOURCE_DIR}/plugins/policies/social_force ${CMAKE_SOURCE_DIR}/plugins/lib/walking/include)
endif()

if(CROWDSIM_BUILD_BENCHMARKS)
  crowdsim_add_benchmark(social_force_bench
    SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/bench/social_force/social_force_bench.cc)
endif()
