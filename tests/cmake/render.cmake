# Episode figures, animations and the HTML report (harness/render, target crowdsim_render).
if(CROWDSIM_BUILD_TESTS)
  find_package(GIF REQUIRED)  # the animation test decodes its GIF
  foreach(test render_figure_test render_output_test render_report_test learning_curve_test)
    crowdsim_add_gtest(${test} unit
      SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/unit/render/${test}.cc
      LIBS crowdsim_render GIF::GIF)
  endforeach()
  add_dependencies(learning_curve_test crowdsim-bench)  # `train` writes the curve
  # The render and report subcommands, run as a user would.
  crowdsim_add_gtest(render_cli_test integration
    SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/unit/render/render_cli_test.cc)
  add_dependencies(render_cli_test crowdsim-bench)
endif()
