# Warnings and sanitizer switches, applied to every halfeti target through halfeti_options.
add_library(halfeti_options INTERFACE)
target_compile_options(halfeti_options INTERFACE -Wall -Wextra -Wno-unused-parameter)
if(HALFETI_ENABLE_SANITIZERS)
  target_compile_options(halfeti_options INTERFACE -fsanitize=address,undefined -fno-omit-frame-pointer)
  target_link_options(halfeti_options INTERFACE -fsanitize=address,undefined)
endif()
