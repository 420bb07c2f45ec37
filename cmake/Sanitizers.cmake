# AddressSanitizer + UndefinedBehaviorSanitizer for the second, checking build of scripts/test.sh.
# Any UB report aborts the test, so it fails CI instead of scrolling past.
if(DROPSCOPE_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer -g)
  add_link_options(-fsanitize=address,undefined)
endif()
