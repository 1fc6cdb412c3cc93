# Warnings, code generation and sanitizer switches, applied to every halfeti target through halfeti_options.
add_library(halfeti_options INTERFACE)
target_compile_options(halfeti_options INTERFACE -Wall -Wextra -Wno-unused-parameter)
# The math functions need not set errno (halfeti never reads it): sqrt becomes one instruction that loops can
# vectorise. The values are unchanged (IEEE sqrt is correctly rounded either way).
target_compile_options(halfeti_options INTERFACE -fno-math-errno)
# The instruction set: by default the build machine's own (-march=native: AVX2 or AVX-512 and FMA where the CPU has
# them, so that the pair search's kernel loop runs four or eight pairs at a time). Build with -DHALFETI_ARCH= for the compiler's
# portable default (a build for other machines than the one compiling), or name a level, e.g. x86-64-v3. Results
# differ between instruction sets in the last bits (fused multiply-adds), never between rank counts of one build.
set(HALFETI_ARCH "native" CACHE STRING "-march for every halfeti target (empty: the compiler's default)")
if(HALFETI_ARCH)
  target_compile_options(halfeti_options INTERFACE -march=${HALFETI_ARCH})
  # GCC 12 warns falsely inside its own AVX-512 intrinsics (the `__m512d __Y = __Y;` of avx512fintrin.h, reached
  # through Eigen's matrix-product kernels; GCC bug 105593, fixed in GCC 13): several hundred warnings that would
  # hide real ones. AVX-512 is worth keeping (the coupled step runs 15-20 % faster with it, docs/sph.md "Speed"), so
  # with an instruction set chosen these two warnings are off for GCC before 13.
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
    target_compile_options(halfeti_options INTERFACE -Wno-uninitialized -Wno-maybe-uninitialized)
  endif()
endif()
if(HALFETI_ENABLE_SANITIZERS)
  target_compile_options(halfeti_options INTERFACE -fsanitize=address,undefined -fno-omit-frame-pointer)
  target_link_options(halfeti_options INTERFACE -fsanitize=address,undefined)
endif()
