# Warnings for our own targets only; third-party headers are included as SYSTEM by their
# imported targets, so they do not trip these.
function(dropscope_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
                                           -Wno-sign-conversion -Werror=return-type -Werror=switch)
endfunction()
