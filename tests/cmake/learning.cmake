# The learned policies (plugins/lib/value_rl, cadrl, sarl) and the trainer (harness/host/train).
if(CROWDSIM_WITH_TORCH)
  if(CROWDSIM_BUILD_TESTS OR CROWDSIM_BUILD_BENCHMARKS)
    # Training helpers shared by the tests and the benchmarks.
    add_library(crowdsim_learning_test_util STATIC
      ${CMAKE_CURRENT_SOURCE_DIR}/unit/learning/learning_test_util.cc)
    target_include_directories(crowdsim_learning_test_util PUBLIC
      ${CMAKE_CURRENT_SOURCE_DIR}/unit/learning)
    target_link_libraries(crowdsim_learning_test_util PUBLIC crowdsim_host crowdsim_test_support
      crowdsim_value_rl)
    target_compile_options(crowdsim_learning_test_util PRIVATE ${CROWDSIM_WARNINGS})
  endif()

  if(CROWDSIM_BUILD_TESTS)
    foreach(test value_rl_state_test value_rl_weights_test training_spec_test training_test)
      crowdsim_add_gtest(${test} unit
        SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/unit/learning/${test}.cc
        LIBS crowdsim_learning_test_util)
    endforeach()
    # These tests also check the networks' tensor code directly.
    crowdsim_add_gtest(attention_weights_test unit
      SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/unit/learning/attention_weights_test.cc
      LIBS crowdsim_learning_test_util)
    foreach(test value_rl_weights_test attention_weights_test)
      target_link_libraries(${test} PRIVATE ${TORCH_LIBRARIES})
      target_include_directories(${test} SYSTEM PRIVATE ${TORCH_INCLUDE_DIRS})
    endforeach()
    # The trainer's internal pieces (value targets, replay memory, episode log, learning curve).
    crowdsim_add_gtest(value_targets_test unit
      SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/unit/learning/value_targets_test.cc)
    target_include_directories(value_targets_test PRIVATE ${CMAKE_SOURCE_DIR}/harness/host)
  endif()

  if(CROWDSIM_BUILD_BENCHMARKS)
    crowdsim_add_benchmark(learning_bench
      SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/bench/learning/learning_bench.cc
      LIBS crowdsim_learning_test_util crowdsim_value_rl)
  endif()
endif()
