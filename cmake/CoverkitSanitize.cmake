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
# COVERKIT_TSAN=ON      every coverkit target built with ThreadSanitizer (not with the two above: TSan
#                       and ASan exclude each other); `bash .ci/bootstrap tsan` runs the Concurrency.*
#                       tests under it (docs/fuzzing.md, "ThreadSanitizer"). CGAL is header-only, so
#                       it is instrumented with the project; GMP, MPFR and libstdc++'s compiled part
#                       are not. cmake/tsan-suppressions.txt: one harmless race inside CGAL's CORE.
#
# CGAL's interval arithmetic switches the rounding mode: the compiler must not fold or reorder
# floating-point code across it. CGAL adds -frounding-math for GCC only; with clang it is added here.
# GMP, yaml-cpp, libpng and the other Debian libraries are not instrumented (their memory is still
# watched by ASan's malloc and the leak checker).
option(COVERKIT_SANITIZE "Build with AddressSanitizer + UndefinedBehaviorSanitizer" OFF)
option(COVERKIT_FUZZ "Build the libFuzzer targets in fuzz/ (clang++; implies COVERKIT_SANITIZE)" OFF)
option(COVERKIT_TSAN "Build with ThreadSanitizer (not with COVERKIT_SANITIZE or COVERKIT_FUZZ)" OFF)

if(COVERKIT_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    message(FATAL_ERROR "COVERKIT_FUZZ needs clang++ (libFuzzer): configure with -DCMAKE_CXX_COMPILER=clang++")
  endif()
  set(COVERKIT_SANITIZE ON CACHE BOOL "Build with AddressSanitizer + UndefinedBehaviorSanitizer" FORCE)
endif()
if(COVERKIT_TSAN AND COVERKIT_SANITIZE)
  message(FATAL_ERROR "COVERKIT_TSAN excludes COVERKIT_SANITIZE and COVERKIT_FUZZ (ThreadSanitizer cannot run with AddressSanitizer): use another build folder")
endif()

if(COVERKIT_SANITIZE OR COVERKIT_TSAN)
  # Build type: RelWithDebInfo unless chosen, with -O2 and line tables only (stack traces with file
  # and line). Measured on geometry/src/cspace.cpp with both sanitizers (CPU seconds): GCC -O2 192,
  # -O2 -g1 199, -O1 -g 165 (4 GB, a 148 MB object); clang -O1 and -O2 with line tables 93-94, -O2
  # -g 110; a plain GCC -O3 build 49. -O1 would compile no faster and run slower.
  if(NOT CMAKE_BUILD_TYPE AND NOT CMAKE_CONFIGURATION_TYPES)
    set(CMAKE_BUILD_TYPE RelWithDebInfo CACHE STRING "Build type" FORCE)
  endif()
  if(COVERKIT_FUZZ)
    set(CMAKE_CXX_FLAGS_RELWITHDEBINFO "-O1 -gline-tables-only -DNDEBUG")  # as OSS-Fuzz builds
  elseif(CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    set(CMAKE_CXX_FLAGS_RELWITHDEBINFO "-O2 -gline-tables-only -DNDEBUG")
  else()
    set(CMAKE_CXX_FLAGS_RELWITHDEBINFO "-O2 -g1 -DNDEBUG")
  endif()
endif()

if(COVERKIT_TSAN)
  add_compile_options(-fsanitize=thread -fno-omit-frame-pointer)
  add_link_options(-fsanitize=thread)
  if(CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    add_compile_options(-frounding-math)
  endif()
  message(STATUS "coverkit: ThreadSanitizer on")
endif()

if(COVERKIT_SANITIZE)
  set(COVERKIT_SANITIZERS address,undefined,float-cast-overflow)
  add_compile_options(-fsanitize=${COVERKIT_SANITIZERS} -fno-sanitize-recover=all -fno-omit-frame-pointer)
  add_link_options(-fsanitize=${COVERKIT_SANITIZERS})
  if(CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    # -fsanitize-blacklist is the old name of -fsanitize-ignorelist: ccache 4.7 hashes the list's
    # content only under that name (with the new one, a changed list would not rebuild).
    add_compile_options(-frounding-math -fsanitize-blacklist=${CMAKE_CURRENT_LIST_DIR}/ubsan-ignorelist.txt)
  else()
    # GCC has no ignore list: the vptr check goes entirely (CGAL's arrangement iterators downcast
    # their DCEL records, cmake/ubsan-ignorelist.txt).
    add_compile_options(-fno-sanitize=vptr)
  endif()
  message(STATUS "coverkit: sanitizers on (${COVERKIT_SANITIZERS})")
endif()

if(COVERKIT_FUZZ)
  add_compile_options(-fsanitize=fuzzer-no-link)
endif()
