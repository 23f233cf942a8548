# Sanitizer and fuzzing builds (docs/architecture.md, "Build"; docs/fuzzing.md).
#
# COVERKIT_SANITIZE=ON  every coverkit target (libraries, tests, CLI) built with AddressSanitizer
#                       (leaks included) and UndefinedBehaviorSanitizer; the first finding aborts.
#                       UBSan's `undefined` group leaves out float-cast-overflow under GCC (a
#                       double → int conversion out of range, how a far coordinate corrupts an
#                       index); it is added. float-divide-by-zero is not: IEEE division by zero
#                       (±inf) is used on purpose (CGAL's interval arithmetic, slopes of vertical edges).
# COVERKIT_FUZZ=ON      libFuzzer targets in fuzz/ (clang only); implies the sanitizers above and
#                       adds coverage instrumentation (-fsanitize=fuzzer-no-link) to every target.
#
# CGAL's interval arithmetic switches the rounding mode: the compiler must not fold or reorder
# floating-point code across it. CGAL adds -frounding-math for GCC only; with clang it is added here.
# GMP, yaml-cpp, libpng and the other Debian libraries are not instrumented (their memory is still
# watched by ASan's malloc and the leak checker).
option(COVERKIT_SANITIZE "Build with AddressSanitizer + UndefinedBehaviorSanitizer" OFF)
option(COVERKIT_FUZZ "Build the libFuzzer targets in fuzz/ (clang++; implies COVERKIT_SANITIZE)" OFF)

if(COVERKIT_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    message(FATAL_ERROR "COVERKIT_FUZZ needs clang++ (libFuzzer): configure with -DCMAKE_CXX_COMPILER=clang++")
  endif()
  set(COVERKIT_SANITIZE ON CACHE BOOL "Build with AddressSanitizer + UndefinedBehaviorSanitizer" FORCE)
endif()

if(COVERKIT_SANITIZE)
  set(COVERKIT_SANITIZERS address,undefined,float-cast-overflow)
  add_compile_options(-fsanitize=${COVERKIT_SANITIZERS} -fno-sanitize-recover=all -fno-omit-frame-pointer)
  add_link_options(-fsanitize=${COVERKIT_SANITIZERS})
  if(CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    add_compile_options(-frounding-math)
  endif()
  message(STATUS "coverkit: sanitizers on (${COVERKIT_SANITIZERS})")
endif()

if(COVERKIT_FUZZ)
  add_compile_options(-fsanitize=fuzzer-no-link)
endif()
