# The real dropscope binary, run as a user would. Each test runs run_and_check_exit.cmake: the exit
# status must be exactly EXPECTED_EXIT, and stderr empty on success, else one line matching REGEX.
function(dropscope_add_cli_exit_test name expected_exit regex)
  list(JOIN ARGN "|" arguments)
  add_test(NAME ${name}
           COMMAND ${CMAKE_COMMAND} -DPROGRAM=$<TARGET_FILE:dropscope> "-DARGUMENTS=${arguments}"
                   -DEXPECTED_EXIT=${expected_exit} "-DSTDERR_REGEX=${regex}"
                   -P ${CMAKE_CURRENT_SOURCE_DIR}/app/run_and_check_exit.cmake)
endfunction()

set(_default_scene ${PROJECT_SOURCE_DIR}/assets/scenes/default.json)
set(_scenes ${CMAKE_CURRENT_SOURCE_DIR}/data/scenes)
dropscope_add_cli_exit_test(cli_inspect_default_scene 0 "" inspect ${_default_scene})
dropscope_add_cli_exit_test(cli_inspect_default_scene_json 0 "" inspect --json ${_default_scene})
dropscope_add_cli_exit_test(cli_help 0 "" --help)
dropscope_add_cli_exit_test(cli_version 0 "" --version)
dropscope_add_cli_exit_test(cli_inspect_missing_file 2 "does_not_exist\\.json: no such file$"
                            inspect ${_scenes}/does_not_exist.json)
dropscope_add_cli_exit_test(cli_inspect_bad_scene 2 "overlapping\\.json: shapes\\[1\\]: .* overlaps shapes\\[0\\]"
                            inspect ${_scenes}/overlapping.json)
dropscope_add_cli_exit_test(cli_inspect_malformed_json 2 "malformed\\.json: line 4, column 10: syntax error"
                            inspect ${_scenes}/malformed.json)
dropscope_add_cli_exit_test(cli_inspect_without_scene 2 "^dropscope: .*scene" inspect)
dropscope_add_cli_exit_test(cli_unknown_command 2 "^dropscope: unknown command \"render\"" render)
# No command opens the app; without a display that is one line pointing to `dropscope snapshot`, exit 3.
# A scene that does not load is bad input before any window opens.
dropscope_add_cli_exit_test(cli_no_command_without_display 3
                            "^dropscope: no display \\(DISPLAY is not set\\); .*dropscope snapshot SCENE --out")
set_tests_properties(cli_no_command_without_display PROPERTIES ENVIRONMENT_MODIFICATION "DISPLAY=unset:;WAYLAND_DISPLAY=unset:")
dropscope_add_cli_exit_test(cli_app_bad_scene 2 "overlapping\\.json: shapes\\[1\\]: .* overlaps shapes\\[0\\]"
                            ${_scenes}/overlapping.json)
dropscope_add_cli_exit_test(cli_app_missing_scene 2 "does_not_exist\\.json: no such file$" ${_scenes}/does_not_exist.json)

# dropscope trace: a small run (it must print nothing on stderr when stderr is no terminal), bad input,
# and Ctrl-C on a long run (trace_interrupt.sh: exit 130 and partial results).
set(_trace_out ${CMAKE_CURRENT_BINARY_DIR}/trace-output)
dropscope_add_cli_exit_test(cli_trace_default_scene 0 "" trace ${_default_scene} --photons 1e4 --paths 5
                            --out ${_trace_out}/default)
dropscope_add_cli_exit_test(cli_trace_without_photons 2 "^dropscope: --photons is required"
                            trace ${_default_scene} --out ${_trace_out}/bad)
dropscope_add_cli_exit_test(cli_trace_no_sources 2
                            "no_sources\\.json: sources: the scene has no light sources to trace$"
                            trace ${_scenes}/no_sources.json --photons 10 --out ${_trace_out}/bad)
add_test(NAME cli_trace_interrupt
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/app/trace_interrupt.sh $<TARGET_FILE:dropscope>
                 ${PROJECT_SOURCE_DIR}/assets/scenes/cloud.json ${_trace_out}/interrupted)
set_tests_properties(cli_trace_interrupt PROPERTIES TIMEOUT 30)
# A disk that fills while writing (a file-size limit): whole files or none (file_size_limit.sh).
add_test(NAME cli_outputs_under_file_size_limit
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/app/file_size_limit.sh $<TARGET_FILE:dropscope> ${_default_scene}
                 ${_trace_out}/size-limited)
set_tests_properties(cli_outputs_under_file_size_limit PROPERTIES TIMEOUT 60)
# Runs beyond the memory a process may use are refused with their estimate (memory_limit.sh). AddressSanitizer
# reserves terabytes of address space, so an address-space limit cannot be set on its build.
if(NOT DROPSCOPE_SANITIZE)
  # Found by fuzz_scene: a patches file naming /dev/zero was read until memory ran out. Reading stops at 1 GiB
  # (4 s here; left out of the sanitizer build, where that gigabyte costs far more). The file is not under
  # tests/data, whose scenes seed the fuzzers and the app test.
  dropscope_add_cli_exit_test(cli_patches_file_too_large 2
                              "shapes\\[0\\]\\.patches: in the patches file: /dev/zero: larger than 1024 MiB"
                              inspect ${CMAKE_CURRENT_SOURCE_DIR}/app/patches_from_dev_zero.json)
  add_test(NAME cli_memory_refused_up_front
           COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/app/memory_limit.sh $<TARGET_FILE:dropscope> ${_default_scene}
                   ${_trace_out}/memory-limited)
  set_tests_properties(cli_memory_refused_up_front PROPERTIES TIMEOUT 60)
endif()
unset(_trace_out)
unset(_scenes)
unset(_default_scene)
