# One place for warnings: every coverkit target calls this.
function(coverkit_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wno-unused-parameter)
endfunction()

# Adds a coverkit library: coverkit_<name>, alias coverkit::<name>, public include dir.
function(coverkit_library name)
  cmake_parse_arguments(ARG "" "" "SOURCES" ${ARGN})
  add_library(coverkit_${name} STATIC ${ARG_SOURCES})
  add_library(coverkit::${name} ALIAS coverkit_${name})
  target_include_directories(coverkit_${name} PUBLIC
    $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include> $<INSTALL_INTERFACE:include>)
  set_target_properties(coverkit_${name} PROPERTIES POSITION_INDEPENDENT_CODE ON EXPORT_NAME ${name})
  coverkit_warnings(coverkit_${name})
endfunction()
