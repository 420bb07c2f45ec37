# AddressSanitizer + UndefinedBehaviorSanitizer for the second, checking build of scripts/test.sh.
# Any UB report aborts the test, so it fails CI instead of scrolling past. -g1 (line tables and function
# names: all a sanitizer's stack trace prints) instead of -g: full debug information made this build's
# compiles 1.7 times slower and its objects twice the size (one test file: 32.5 s against 19.2 s).
if(DROPSCOPE_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer -g1)
  add_link_options(-fsanitize=address,undefined)
endif()

# libFuzzer (docs/fuzzing.md): the fuzz targets of tests/fuzz live in the sanitizer build, so they cost only their
# own few files and not a third build of the project. The readers they drive (the scene layer, the spectra it
# builds, the CLI's rays CSV) are compiled with libFuzzer's coverage instrumentation (-fsanitize=fuzzer-no-link),
# whose callbacks the sanitizers' runtime takes in every other program. Nothing else is: on the geometry's meshing
# and the tracer's loops it costs time to guide nothing a reader decides (loading assets/scenes/shapes_gallery.json,
# mostly meshing: 7.3 s of CPU with the whole engine instrumented, 5.1 s with the readers alone).
if(DROPSCOPE_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "DROPSCOPE_FUZZ needs clang (libFuzzer), e.g. -DCMAKE_CXX_COMPILER=clang++-14")
  endif()
  if(NOT DROPSCOPE_SANITIZE)
    message(FATAL_ERROR "DROPSCOPE_FUZZ needs DROPSCOPE_SANITIZE: a fuzzer finds memory errors through ASan and UBSan")
  endif()
endif()
function(dropscope_fuzz_instrument target)
  if(DROPSCOPE_FUZZ)
    target_compile_options(${target} PRIVATE -fsanitize=fuzzer-no-link)
  endif()
endfunction()
