# Warnings for vistrack's own targets only; third-party headers are included as SYSTEM.
function(vistrack_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
                                           -Wno-sign-conversion)
  if(VISTRACK_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()
